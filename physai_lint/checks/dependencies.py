"""Package dependencies of launch files: U103 missing-exec-depend (ECOSYSTEM §5)."""
from __future__ import annotations

import functools
import posixpath
import re
from collections.abc import Iterator
from typing import Any

from physai_lint.checks._urls import ParamString, file_url_path, package_url, parameter_strings
from physai_lint.checks._util import ir_objects, python_facts, suggestion
from physai_lint.checks.base import CheckContext, rule
from physai_lint.model.findings import Diagnostic
from physai_lint.model.span import Span
from physai_lint.model.values import Command, FindPackage, PathJoin, literal_of


def _references(ctx: CheckContext) -> Iterator[tuple[str, Span, str]]:
    """(referenced package, where, launch file) of every package named literally.

    A name built from a launch configuration (``$(var vehicle_model)_description``) is chosen by
    whoever starts the launch; its default is one choice among many, which the package.xml of the
    launch file cannot list."""
    for launch in ctx.launches:
        for node in launch.nodes:
            if node.package and not node.package_from_config:
                yield node.package, node.spans.get("package", node.span), node.file
        for name, span, file, from_config in launch.package_refs:
            if span is not None and not from_config:
                yield name, span, file


@rule("U103", "missing-exec-depend")
def missing_exec_depend(ctx: CheckContext) -> Iterator[Diagnostic]:
    refs = sorted(set(_references(ctx)), key=lambda r: (r[2], r[1].line, r[1].col, r[0]))
    reported: set[tuple[str, str, bool]] = set()
    tests = {path for path, facts in python_facts(ctx) if facts.is_launch_test}
    for name, span, file in refs:
        owner = ctx.packages.package_of_source(span.file or file)
        if owner is None or not owner.valid or name == owner.name:
            continue
        is_test = (span.file or file) in tests  # a launch test: its <test_depend>s count too
        if (owner.name, name, is_test) in reported or not ctx.packages.has_package(name):
            continue
        declared = ctx.packages.exec_depends(owner.name)
        if name in declared or _through(ctx, declared, name):
            continue
        if is_test and name in getattr(ctx.packages, "test_depends", lambda _: ())(owner.name):
            continue
        reported.add((owner.name, name, is_test))
        excluded = getattr(ctx.packages, "excluded_depends", lambda _: {})(owner.name).get(name)
        if excluded is not None:
            why = (f'declares it only under the condition "{excluded}", which is false for '
                   f'{ctx.distro}')
            fix = (f'make the condition of the dependency on "{name}" hold for {ctx.distro}, or give '
                   f"the launch file a branch for {ctx.distro} that does not use it")
        else:
            why = "does not declare it (no <exec_depend> or <depend>)"
            fix = f'add <exec_depend>{name}</exec_depend> to the package.xml of "{owner.name}"'
            back = _dependency_path(ctx, name, owner.name)
            if back:
                fix += (f'; but "{name}" already depends on "{owner.name}" ({" -> ".join(back)}), and '
                        f"colcon cannot order packages that depend on each other: move this launch "
                        f'file into "{name}" or a package depending on both')
        yield Diagnostic(
            "U103", span,
            f'package "{owner.name}" uses package "{name}" in its launch files but its package.xml {why}',
            help=fix, key=f"{owner.name}->{name}")


# Released metapackages and members they have exec_depended on in every release since humble
# (their package.xml): a package declaring the metapackage gets these installed by rosdep. A
# subset where releases differ (ros2_control added joint_limits and transmission_interface later).
METAPACKAGES: dict[str, frozenset[str]] = {
    "ros2_control": frozenset({"controller_interface", "controller_manager", "hardware_interface",
                               "ros2controlcli", "ros2_control_test_assets"}),
    "gazebo_ros_pkgs": frozenset({"gazebo_dev", "gazebo_msgs", "gazebo_plugins", "gazebo_ros"}),
    "vision_opencv": frozenset({"cv_bridge", "image_geometry"}),
    "image_common": frozenset({"camera_calibration_parsers", "camera_info_manager", "image_transport"}),
    "perception_pcl": frozenset({"pcl_conversions", "pcl_ros"}),
    "ros_gz": frozenset({"ros_gz_bridge", "ros_gz_image", "ros_gz_sim", "ros_gz_sim_demos"}),
    "ros_ign": frozenset({"ros_gz", "ros_ign_bridge", "ros_ign_gazebo", "ros_ign_gazebo_demos",
                          "ros_ign_image"}),  # humble only: its members forward to ros_gz
    "navigation2": frozenset({
        "nav2_amcl", "nav2_behavior_tree", "nav2_behaviors", "nav2_bt_navigator", "nav2_collision_monitor",
        "nav2_constrained_smoother", "nav2_controller", "nav2_core", "nav2_costmap_2d", "nav2_dwb_controller",
        "nav2_lifecycle_manager", "nav2_map_server", "nav2_mppi_controller", "nav2_msgs",
        "nav2_navfn_planner", "nav2_planner", "nav2_regulated_pure_pursuit_controller",
        "nav2_rotation_shim_controller", "nav2_route", "nav2_rviz_plugins", "nav2_simple_commander",
        "nav2_smac_planner", "nav2_smoother", "nav2_theta_star_planner", "nav2_util",
        "nav2_velocity_smoother", "nav2_voxel_grid", "nav2_waypoint_follower"}),
    "nav2_dwb_controller": frozenset({"costmap_queue", "dwb_core", "dwb_critics", "dwb_msgs", "dwb_plugins",
                                     "nav_2d_msgs", "nav_2d_utils"}),
    # moveit2's metapackages (package.xml at humble and rolling; members of either)
    "moveit": frozenset({"moveit_commander", "moveit_core", "moveit_planners", "moveit_plugins", "moveit_ros",
                         "moveit_setup_assistant"}),
    "moveit_ros": frozenset({
        "moveit_ros_benchmarks", "moveit_ros_move_group", "moveit_ros_perception", "moveit_ros_planning",
        "moveit_ros_planning_interface", "moveit_ros_robot_interaction", "moveit_ros_visualization",
        "moveit_ros_warehouse"}),
    "moveit_planners": frozenset({"moveit_planners_chomp", "moveit_planners_ompl", "moveit_planners_stomp",
                                  "pilz_industrial_motion_planner"}),
    "moveit_plugins": frozenset({"moveit_ros_control_interface", "moveit_simple_controller_manager"}),
    # ros-controls/ros2_controllers' metapackage (rolling; older distros have a subset)
    "ros2_controllers": frozenset({
        "ackermann_steering_controller", "admittance_controller", "battery_state_broadcaster",
        "bicycle_steering_controller", "chained_filter_controller", "diff_drive_controller",
        "force_torque_sensor_broadcaster", "forward_command_controller", "gpio_controllers",
        "gps_sensor_broadcaster", "imu_sensor_broadcaster", "joint_state_broadcaster",
        "joint_trajectory_controller", "magnetometer_broadcaster", "mecanum_drive_controller",
        "motion_primitives_controllers", "omni_wheel_drive_controller", "parallel_gripper_controller",
        "pid_controller", "pose_broadcaster", "range_sensor_broadcaster", "state_interfaces_broadcaster",
        "steering_controllers_library", "tricycle_controller", "tricycle_steering_controller"}),
}


@functools.cache
def _metapackage_members(name: str) -> frozenset[str]:
    """What metapackage ``name`` brings, through the metapackages among its members."""
    out: set[str] = set()
    todo = [name]
    while todo:
        for member in METAPACKAGES.get(todo.pop(), ()):
            if member not in out:
                out.add(member)
                todo.append(member)
    return frozenset(out)


def _through(ctx: CheckContext, declared: dict[str, int], name: str) -> bool:
    """Whether a declared dependency brings ``name`` at run time: a metapackage holding it
    (``METAPACKAGES``), or a workspace package whose run dependencies reach it."""
    if any(name in _metapackage_members(dep) for dep in declared):
        return True
    return any(name in _run_closure(ctx, dep) for dep in declared)


def _run_closure(ctx: CheckContext, start: str, limit: int = 5000) -> dict[str, str]:
    """The run dependencies of workspace package ``start``, through the workspace packages among
    them, each with the package that first declares it (breadth first: shortest chains); empty
    for a package outside the workspace. Memoised per run."""
    memo: dict[str, dict[str, str]] = ctx.options.setdefault("_run_closure", {})
    if start in memo:
        return memo[start]
    came: dict[str, str] = {}
    queue = [start] if ctx.packages.workspace_package(start) is not None else []
    while queue and len(came) < limit:
        here = queue.pop(0)
        for dep in sorted(ctx.packages.exec_depends(here)):
            if dep == start or dep in came:
                continue
            came[dep] = here
            if ctx.packages.workspace_package(dep) is not None:
                queue.append(dep)
    memo[start] = came
    return came


def _dependency_path(ctx: CheckContext, start: str, target: str) -> list[str]:
    """The run dependencies leading from workspace package ``start`` to ``target`` (both
    included; the shortest), or [] when there are none among the workspace packages."""
    came = _run_closure(ctx, start)
    if target not in came:
        return []
    path = [target]
    while path[-1] != start:
        path.append(came[path[-1]])
    return path[::-1]


def _in_install(ctx: CheckContext, path: str) -> tuple[str, str] | None:
    """(workspace package, the rest of the path) when ``path`` is in that package's (virtual)
    install prefix: "<install>/<package>/<rest>"."""
    root = getattr(ctx.packages, "install_root", None)
    if not root or not path.startswith(root + "/"):
        return None
    name, _, rest = path[len(root) + 1 :].partition("/")
    return (name, rest) if ctx.packages.workspace_package(name) is not None else None


def _share_path(ctx: CheckContext, arg: str) -> str | None:
    """The package when ``arg`` is a path inside a workspace package's (virtual) share dir."""
    found = _in_install(ctx, arg)
    return found[0] if found is not None and found[1].startswith(f"share/{found[0]}/") else None


def _unfound_share_file(ctx: CheckContext, path: str) -> tuple[str, str, Any] | None:
    """(package, the path inside its share directory, ``locate``'s answer) of ``path`` in a
    workspace package's share directory when its file is missing or not installed; else None."""
    pkg = _share_path(ctx, path) if "/share/" in path else None
    if pkg is None:
        return None
    loc = ctx.packages.locate(path)
    if loc.status not in ("missing", "not_installed"):
        return None
    return pkg, path.split(f"/share/{pkg}/", 1)[1], loc


@rule("U104", "missing-file")
def missing_file(ctx: CheckContext) -> Iterator[Diagnostic]:
    seen: set[tuple[object, str]] = set()
    for launch in ctx.launches:
        for node in launch.nodes:
            for arg in node.arguments:
                found = _unfound_share_file(ctx, arg) if arg else None
                span = node.spans.get("arguments", node.span)
                if found is None or (span, arg) in seen:
                    continue
                seen.add((span, arg))
                pkg, rel, loc = found
                yield _file_problem(ctx, span, pkg, rel, loc, "passed in the arguments of the node",
                                    check="path", present="exists in", install="add an install rule for it "
                                    "(CMake install(DIRECTORY ...) or setup.py data_files)")
    yield from _parameter_files(ctx, seen)
    yield from _command_files(ctx, seen)
    yield from _opened_files(ctx, seen)


def _parameter_files(ctx: CheckContext, seen: set[tuple[object, str]]) -> Iterator[Diagnostic]:
    """Paths into a workspace package's share directory given as parameter values: built in a
    launch file (a bridge's ``config_file``, a map server's ``yaml_filename``, a behavior tree's
    XML; list items too), or a URL the node resolves itself (``package://<package>/<path>``,
    ``file:///<path>``: camera_info_manager's ``camera_info_url``), in a launch or parameter file:
    the node is given a path that is not there."""
    root = getattr(ctx.packages, "install_root", None)
    for ps in parameter_strings(ctx):
        path = file_url_path(ps.value)
        at_package = package_url(ps.value) if path is None else None
        if at_package is not None:
            pkg, rel = at_package
            if not root or "$" in rel or ctx.packages.workspace_package(pkg) is None:
                continue  # "${NAME}.yaml": camera_info_manager puts the camera's name there
            path = f"{root}/{pkg}/share/{pkg}/{posixpath.normpath(rel)}"
        what = f'given as parameter "{ps.name}" {ps.whose}'
        if path is not None:
            what = f'named by URL "{ps.value}", {what},'
        path = path or ps.value
        if (ps.span, ps.value) in seen or _PATTERN.search(path):
            continue
        glued = _glued_share(ctx, path)
        if glued is not None:
            seen.add((ps.span, ps.value))
            yield _glued_problem(ctx, ps, *glued)
            continue
        found = _unfound_share_file(ctx, path)
        if found is None:
            continue
        pkg, rel, loc = found
        if loc.status == "missing" and (_names_an_output(ps.name) or _is_a_stem(ctx, pkg, rel)):
            continue  # a file the node writes need not exist (output_log_file)
        seen.add((ps.span, ps.value))
        fails = ("; camera_info_manager logs \"Camera calibration file ... not found\" and the camera "
                 "runs uncalibrated (a CameraInfo with K all zero)") if ps.base == "camera_info_url" else ""
        yield _file_problem(ctx, ps.span, pkg, rel, loc, what, fails, fails, check="path", present="exists in")


def _glued_share(ctx: CheckContext, path: str) -> tuple[str, str] | None:
    """(package, what follows) when ``path`` runs a workspace package's share directory into the
    next part with no "/" between (``[FindPackageShare('cam'), 'config/cam.yaml']`` gives
    ".../share/camconfig/cam.yaml"); else None."""
    found = _in_install(ctx, path)
    if found is None:
        return None
    name, rest = found
    share = f"share/{name}"
    if not rest.startswith(share) or len(rest) == len(share) or rest[len(share)] == "/":
        return None
    return name, rest[len(share) :]


def _glued_problem(ctx: CheckContext, ps: ParamString, pkg: str, after: str) -> Diagnostic:
    """U104 for a parameter path that runs package ``pkg``'s share directory into ``after``."""
    word = after.split("/", 1)[0]
    return Diagnostic(
        "U104", ps.span,
        f'path given as parameter "{ps.name}" {ps.whose} runs the share directory of package "{pkg}" '
        f'into "{word}": it names "share/{pkg}{after}", which does not exist; a "/" is missing between '
        f'"share/{pkg}" and "{after}"',
        help=f'put a "/" before "{after}" (or build the path with PathJoinSubstitution, which adds it)',
        key=f"{pkg}{after}")


# A value that is no single path: a glob (config/*.yaml), a search path (models:/other)
_PATTERN = re.compile(r"[*?\[:;]")
# Words of a parameter name for a file the node writes, which need not exist (Autoware's
# output_log_file, a map saver's save_path, rtabmap's database_path), unless the name says the
# node reads it (log_config_file).
_OUTPUT_WORDS = frozenset({"output", "out", "log", "logs", "save", "saved", "write", "dump", "record",
                           "result", "results", "export", "dest", "destination", "cache", "tmp",
                           "database", "db"})
_INPUT_WORDS = frozenset({"config", "conf", "cfg", "param", "params", "settings"})


def _names_an_output(name: str) -> bool:
    words = set(re.split(r"[^a-z0-9]+", re.sub(r"([a-z0-9])([A-Z])", r"\1_\2", name).lower()))
    return bool(words & _OUTPUT_WORDS) and not words & _INPUT_WORDS


def _is_a_stem(ctx: CheckContext, pkg: str, rel: str) -> bool:
    """``rel`` names files by their stem (slam_toolbox's map_file_name: maps/office for
    office.posegraph and office.data)."""
    files = getattr(ctx.packages.workspace_package(pkg), "files", None) or ()
    return any(f.startswith(rel + ".") for f in files)


def _file_problem(ctx: CheckContext, span: Span, pkg: str, rel: str, loc: Any, what: str,
                  fails: str = "", fails_uninstalled: str = "", check: str = "file name",
                  present: str = "is in", install: str = "add an install rule for it") -> Diagnostic:
    """U104 for file ``rel`` of workspace package ``pkg`` that ``loc`` (``locate``) finds missing
    or not installed; ``what`` says how the launch file uses it, ``fails`` what then fails."""
    if loc.status == "missing":
        msg = (f'file "{rel}" {what} does not exist in package "{pkg}" (it would be opened as '
               f'"share/{pkg}/{rel}"){fails}{_near_file(ctx, pkg, rel)}')
        fix = f'check the {check}, or add "{rel}" to package "{pkg}" and install it'
    else:
        msg = (f'file "{rel}" {what} {present} the sources of package "{pkg}" but is not installed to '
               f'"share/{pkg}/{rel}"{fails_uninstalled}')
        fix = loc.install_hint or install
    return Diagnostic("U104", span, msg, help=fix, key=f"{pkg}/{rel}")


def _near_file(ctx: CheckContext, pkg: str, rel: str) -> str:
    """"; did you mean ..." naming files of package ``pkg`` in the folder of ``rel`` whose name is
    close, else ""."""
    wp = ctx.packages.workspace_package(pkg)
    folder = posixpath.dirname(rel)
    close = suggestion(rel, [f for f in getattr(wp, "files", None) or () if posixpath.dirname(f) == folder])
    return f"; {close}" if close else ""


def _opened_files(ctx: CheckContext, seen: set[tuple[object, str]]) -> Iterator[Diagnostic]:
    """Files a Python launch file opens while its description is built (``open(path)``,
    ``Path(path).read_text()``), in a workspace package's share directory."""
    for launch in ctx.launches:
        for path, span in launch.opened_files:
            found = _unfound_share_file(ctx, path)
            if found is None or (span, path) in seen:
                continue
            seen.add((span, path))
            pkg, rel, loc = found
            fails = "; launch fails with FileNotFoundError"
            yield _file_problem(ctx, span, pkg, rel, loc, "opened while the launch description is built",
                                fails, fails)


def _known_share_path(ctx: CheckContext, join: PathJoin) -> tuple[str, str] | None:
    """(package, relative path) of ``PathJoin([FindPackageShare('p'), 'a', 'b'])`` with literals."""
    if not join.parts or len(join.parts[0]) != 1 or not isinstance(join.parts[0][0], FindPackage):
        return None
    find = join.parts[0][0]
    pkg = literal_of(find.package)
    if find.kind != "share" or pkg is None or ctx.packages.workspace_package(pkg) is None:
        return None
    rest = [literal_of(p) for p in join.parts[1:]]
    if not rest or any(r is None or r == "" for r in rest):
        return None
    return pkg, "/".join(r.strip("/") for r in rest if r)


def _command_files(ctx: CheckContext, seen: set[tuple[object, str]]) -> Iterator[Diagnostic]:
    """Files given to ``Command([...])`` (xacro, cat) as a known ``PathJoinSubstitution``."""
    root = getattr(ctx.packages, "install_root", None)
    if not root:
        return
    for path in sorted(ctx.launch_files):
        for cmd in ir_objects(ctx, path):
            if not isinstance(cmd, Command):
                continue
            for part in cmd.command:
                if not isinstance(part, PathJoin) or part.span is None:
                    continue
                known = _known_share_path(ctx, part)
                if known is None:
                    continue
                pkg, rel = known
                if (part.span, rel) in seen:
                    continue
                loc = ctx.packages.locate(f"{root}/{pkg}/share/{pkg}/{rel}")
                if loc.status not in ("missing", "not_installed"):
                    continue
                seen.add((part.span, rel))
                yield _file_problem(ctx, part.span, pkg, rel, loc, "given to Command(...)",
                                    "; the command fails at launch")
