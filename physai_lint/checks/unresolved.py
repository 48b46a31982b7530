"""U101 unknown-package, U102 unknown-executable: references that ROS 2 cannot resolve."""
from __future__ import annotations

from typing import Any, Iterator

from physai_lint.checks._util import all_nodes, did_you_mean, relpath
from physai_lint.checks.base import CheckContext, rule
from physai_lint.closematch import close_matches
from physai_lint.model.findings import Diagnostic

# Executables that people mistake for packages: the package that really provides them.
KNOWN_EXECUTABLE_HOMES = {
    "move_group": "moveit_ros_move_group",
    "ros2_control_node": "controller_manager",
    "spawner": "controller_manager",
    "component_container": "rclcpp_components",
    "component_container_mt": "rclcpp_components",
    "component_container_isolated": "rclcpp_components",
    "static_transform_publisher": "tf2_ros",
    "ekf_node": "robot_localization",
    "async_slam_toolbox_node": "slam_toolbox",
    "sync_slam_toolbox_node": "slam_toolbox",
    "teleop_twist_keyboard": "teleop_twist_keyboard",
    "joy_node": "joy",
    "map_server": "nav2_map_server",
    "amcl": "nav2_amcl",
    "controller_server": "nav2_controller",
    "planner_server": "nav2_planner",
    "bt_navigator": "nav2_bt_navigator",
    "behavior_server": "nav2_behaviors",
    "lifecycle_manager": "nav2_lifecycle_manager",
}


# Packages renamed upstream: the Ignition -> Gazebo rename of ros_ign (humble ships both, later
# distros only ros_gz), and Gazebo Classic's ROS packages, which end with humble.
RENAMED = {
    "ros_ign": "ros_gz", "ros_ign_bridge": "ros_gz_bridge", "ros_ign_gazebo": "ros_gz_sim",
    "ros_ign_gazebo_demos": "ros_gz_sim_demos", "ros_ign_image": "ros_gz_image",
    "ros_ign_interfaces": "ros_gz_interfaces", "gazebo_ros": "ros_gz_sim",
    "gazebo_ros_pkgs": "ros_gz", "gazebo_plugins": "gz_ros2_control or ros_gz_bridge",
}


def _package_help(ctx: CheckContext, name: str, executable: str | None) -> tuple[str, str]:
    from physai_lint.workspace.distro import released_in

    hints = []
    elsewhere = released_in(name)
    if elsewhere:
        hints.append(f"it is released for {', '.join(elsewhere)}, not for {ctx.distro}")
        if name in RENAMED:
            hints.append(f"its successor is {RENAMED[name]}")
            return "; " + "; ".join(hints), f"use {RENAMED[name]}, or run with --distro {elsewhere[-1]}"
    home = KNOWN_EXECUTABLE_HOMES.get(executable or "") or KNOWN_EXECUTABLE_HOMES.get(name)
    if home and ctx.packages.has_package(home):
        hints.append(f'the "{executable or name}" executable is provided by package "{home}"')
    # package_names() is sorted and unique already (one tuple per run): no preparing it per finding
    close = [c for c in close_matches(name, ctx.packages.package_names(), 3, 0.6) if c != home]
    if close:
        hints.append("did you mean " + " or ".join(f'"{c}"' for c in close) + "?")
    extra = ("; " + "; ".join(hints)) if hints else ""
    return extra, (f'use package="{home}"' if home else
                   "check the package name, add the package to the workspace, or install it")


def _skipped(ctx: CheckContext, name: str, span: Any) -> Diagnostic | None:
    """U101 for a package of the workspace that colcon skips (an ignore marker in its directory)
    and no underlay provides: whatever the package.xml declares, nothing installs it."""
    found = getattr(ctx.packages, "ignored", {}).get(name)
    if found is None or ctx.packages.origin(name) is not None:
        return None
    pkg_dir, marker = found
    return Diagnostic(
        "U101", span,
        f'package "{name}" is in {relpath(pkg_dir)}, which holds {marker}: colcon skips it, so it is '
        f"never built or installed, and it is not in the {ctx.distro} distro",
        help=f"remove {relpath(pkg_dir)}/{marker} to build the package, or stop launching it", key=name)


def _unresolved(ctx: CheckContext, name: str, span: Any, file: str | None,
                reported: set[tuple[object, str]]) -> Diagnostic | bool:
    """Whether package ``name``, referenced at ``span`` in ``file``, is a U101 to write: False when
    it resolves, is reported there already, or the package holding ``file`` declares it
    (``_declared``); the finding itself for a package colcon skips (``_skipped``); True for an
    unknown package (then marked reported)."""
    if ctx.packages.has_package(name) or (span, name) in reported:
        return False
    skipped = _skipped(ctx, name, span)
    if skipped is not None:
        reported.add((span, name))
        return skipped
    if _declared(ctx, name, file):
        return False
    reported.add((span, name))
    return True


def _declared(ctx: CheckContext, name: str, file: str | None) -> bool:
    """Whether the package holding ``file`` declares a run dependency on ``name``: rosdep installs
    it from wherever its rules point (a vendor's apt source, a private rosdep key), which the
    workspace and the distro's package list cannot show, so its absence here is no mistake."""
    from physai_lint.workspace.distro import released_in

    owner = ctx.packages.package_of_source(file) if file else None
    return owner is not None and owner.valid and name in ctx.packages.exec_depends(owner.name) \
        and not released_in(name)  # one released elsewhere has no rosdep key for this distro


@rule("U101", "unknown-package")
def unknown_package(ctx: CheckContext) -> Iterator[Diagnostic]:
    reported: set[tuple[object, str]] = set()
    for _, node in all_nodes(ctx):
        if node.package is None:
            continue
        span = node.spans.get("package", node.span)
        verdict = _unresolved(ctx, node.package, span, span.file or node.file, reported)
        if verdict is not True:
            yield from (verdict,) if verdict else ()
            continue
        if not node.package:
            yield Diagnostic(
                "U101", span, "the package name is empty (its value here is \"\"); ament_index refuses "
                "an empty name and the launch aborts",
                help="name the package, or pass the launch argument that gives it", key="empty")
            continue
        extra, fix = _package_help(ctx, node.package, node.executable)
        yield Diagnostic(
            "U101", span,
            f'package "{node.package}" is not in the workspace or the {ctx.distro} distro{extra}',
            help=fix, key=node.package)
    for launch in ctx.launches:
        for name, span, _file, from_config in launch.package_refs:
            verdict = _unresolved(ctx, name, span, span.file or _file, reported) if span is not None else False
            if verdict is not True:
                yield from (verdict,) if verdict else ()
                continue
            if not name and from_config:  # a required argument's placeholder default, not set
                arg = f'launch argument "{from_config}"' if isinstance(from_config, str) else "a launch argument"
                yield Diagnostic(
                    "U101", span,
                    f"the package name is empty: it comes from {arg}, whose value is \"\" here; "
                    "ament_index refuses an empty name (an AssertionError on humble, a ValueError later) and "
                    "the launch aborts",
                    help="pass the argument (name:=package) or give it a default naming a package",
                    key=f"empty:{from_config}")
                continue
            extra, fix = _package_help(ctx, name, None)
            yield Diagnostic(
                "U101", span,
                f'package "{name}" is not in the workspace or the {ctx.distro} distro{extra}',
                help=fix, key=name)
    yield from _url_packages(ctx, reported)


def _url_packages(ctx: CheckContext, reported: set[tuple[object, str]]) -> Iterator[Diagnostic]:
    """The package of a ``package://<package>/<path>`` parameter value (camera_info_manager's
    ``camera_info_url``, a resource_retriever mesh), in a launch or a parameter file: the node looks
    it up in the ament index when it resolves the URL (camera_info_manager on humble: an uncaught
    PackageNotFoundError ends the process)."""
    from physai_lint.checks._urls import package_url, parameter_strings

    for ps in parameter_strings(ctx):
        found = package_url(ps.value)
        verdict = _unresolved(ctx, found[0], ps.span, ps.span.file, reported) if found else False
        if verdict is not True:
            yield from (verdict,) if verdict else ()
            continue
        name = found[0]  # type: ignore[index]
        extra, fix = _package_help(ctx, name, None)
        yield Diagnostic(
            "U101", ps.span,
            f'package "{name}" of URL "{ps.value}" (parameter "{ps.name}" {ps.whose}) is not in the '
            f"workspace or the {ctx.distro} distro, so the node cannot resolve the URL{extra}",
            help=fix, key=name)


@rule("U102", "unknown-executable")
def unknown_executable(ctx: CheckContext) -> Iterator[Diagnostic]:
    seen: set[object] = set()
    for _, node in all_nodes(ctx):
        if node.kind == "process" or node.package is None or node.executable is None:
            continue
        if node.kind == "composable_node":
            known = ctx.packages.plugins(node.package)
            what, where = "component plugin", "registered by rclcpp_components_register_node(s)"
        else:
            known = ctx.packages.executables(node.package)
            what, where = "executable", "installed to lib/" + node.package
        if known is None or node.executable in known:
            continue
        span = node.spans.get("executable" if node.kind != "composable_node" else "plugin", node.span)
        if (span, node.executable) in seen:
            continue
        seen.add((span, node.executable))
        in_bin, elsewhere = ctx.packages.scripts_outside_lib(node.package) \
            if node.kind != "composable_node" and hasattr(ctx.packages, "scripts_outside_lib") else (frozenset(), None)
        close = did_you_mean(node.executable, known | in_bin)
        if node.executable in in_bin or set(close) & in_bin:
            script = node.executable if node.executable in in_bin else min(set(close) & in_bin)
            lib = f"$base/lib/{node.package}"
            where_to = f"to {elsewhere} (setup.cfg's script_dir)" if elsewhere else \
                "to bin/ (no setup.cfg sends its scripts elsewhere)"
            fix = (f'set script_dir and install_scripts in setup.cfg to {lib}' if elsewhere else
                   f'add a setup.cfg next to setup.py with "[develop] script_dir={lib}" and '
                   f'"[install] install_scripts={lib}"')
            yield Diagnostic(
                "U102", span,
                f'package "{node.package}" installs its console script "{script}" {where_to}, not to '
                f'lib/{node.package}, where launch looks for "{node.executable}": the node fails to start '
                "with a SubstitutionFailure",
                help=fix + (f', and use "{script}"' if script != node.executable else ""),
                key=f"{node.package}/{node.executable}")
            continue
        hint = (" (did you mean " + " or ".join(f'"{c}"' for c in close) + "?)") if close else ""
        listing = ", ".join(f'"{k}"' for k in sorted(known)[:8]) or "none"
        if len(known) > 8:
            listing += f" and {len(known) - 8} more"
        yield Diagnostic(
            "U102", span,
            f'package "{node.package}" has no {what} "{node.executable}"{hint}; it provides: {listing}',
            help=f"use one of the package's {what}s, or make sure it is {where}",
            key=f"{node.package}/{node.executable}")
