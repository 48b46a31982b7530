"""Lifecycle managers and containers: S201 lifecycle-node-not-launched, S202 lifecycle-node-unmanaged,
S203 container-not-launched, S204 controller-type-not-set, S205 extra-argument-not-bool,
S206 unknown-extra-argument, S207 lifecycle-event-reaches-nothing."""
from __future__ import annotations

from collections.abc import Iterator
from typing import Any

from physai_lint.checks._params import effective, fully_known
from physai_lint.checks._util import (
    ACTION_CLASSES,
    CONTAINER_EXECUTABLES,
    all_nodes,
    command_words,
    did_you_mean,
    once,
    where,
)
from physai_lint.checks.base import CheckContext, rule
from physai_lint.graph.plan import SPAWNER_VALUE_OPTIONS
from physai_lint.model.findings import Diagnostic, Related
from physai_lint.model.launch import NodeAction
from physai_lint.resolve.model import (
    LIFECYCLE_MANAGERS,
    LaunchResult,
    NodeInstance,
    ResolvedParamDict,
    ResolvedParamFile,
)
from physai_lint.resolve.names import expand_topic_name

MANAGERS = LIFECYCLE_MANAGERS


def managers(ctx: CheckContext, launch: LaunchResult) -> Iterator[tuple[NodeInstance, list[str], Any]]:
    """(manager node, node_names, the effective parameter) for every lifecycle manager launched."""
    for node in launch.nodes:
        if node.active is False or (node.package, node.executable) not in MANAGERS:
            continue
        ep = effective(ctx, node).get("node_names")
        if ep is None or not isinstance(ep.value, list) or not ep.certain:
            continue
        yield node, [str(x) for x in ep.value], ep


def _item_span(node: NodeInstance, ep: Any, index: int) -> Any:
    if ep.item_spans and index < len(ep.item_spans):  # from a parameter file
        return ep.item_spans[index]
    for src in node.param_sources:
        if isinstance(src, ResolvedParamDict):
            for prm in src.params:
                if prm.name == "node_names" and prm.item_spans and index < len(prm.item_spans):
                    return prm.item_spans[index]
    return ep.origin or node.span


@rule("S201", "lifecycle-node-not-launched")
def not_launched(ctx: CheckContext) -> Iterator[Diagnostic]:
    seen: set[object] = set()
    for launch in ctx.launches:
        nodes = [n for n in launch.nodes if n.active is not False and n.kind != "process"]
        if any(n.fqn is None and _may_be_lifecycle(ctx, n) for n in nodes) or launch.opaque \
                or any(_starts_ros_nodes(p) for p in launch.nodes if p.kind == "process" and p.active is not False):
            continue  # an unknown node might be the one it manages
        fqns = {n.fqn for n in nodes}
        mgrs = list(managers(ctx, launch))
        # a node some manager already lists, or a manager, is no candidate for a misspelt name
        listed = {expand_topic_name(n, m.name, m.namespace) for m, names, _ in mgrs for n in names}
        listed |= {m.fqn for m, _, _ in mgrs}
        for mgr, names, ep in mgrs:
            for i, name in enumerate(names):
                target = expand_topic_name(name, mgr.name, mgr.namespace)
                if target is None or target in fqns:
                    continue
                span = _item_span(mgr, ep, i)
                if (span, target) in seen:
                    continue
                seen.add((span, target))
                candidates = sorted(f for f in fqns if f and f not in listed)
                close = did_you_mean(target, candidates)
                hint = ("; did you mean " + " or ".join(f'"{c}"' for c in close) + "?") if close else ""
                yield Diagnostic(
                    "S201", span,
                    f'lifecycle manager {where(mgr)} manages "{name}" ({target}) but no such node is '
                    f"launched{hint}; it waits for it and never brings the system up",
                    help="remove the name from node_names or launch the node with that name",
                    related=(Related(mgr.span, "the lifecycle manager"),), key=target)


@rule("S202", "lifecycle-node-unmanaged")
def unmanaged(ctx: CheckContext) -> Iterator[Diagnostic]:
    for launch in ctx.launches:
        mgrs = list(managers(ctx, launch))
        if not mgrs or len(mgrs) < sum(1 for n in launch.nodes if n.active is not False
                                       and (n.package, n.executable) in MANAGERS):
            continue  # no manager here, or one whose node_names are not known
        managed = {expand_topic_name(n, m.name, m.namespace) for m, names, _ in mgrs for n in names}
        managed |= _set_by_command(launch)
        # the launch drives some nodes itself: EmitEvent(ChangeState(lifecycle_node_matcher=...))
        driven = {target for target, _ in launch.lifecycle_changes}
        if None in driven or None in managed:
            continue  # a transition whose target is not known may be any node's
        for node in launch.nodes:
            if node.active is False or node.fqn is None or not _is_lifecycle(ctx, node):
                continue
            if node.fqn not in managed and node.action_id not in driven and not _autostarts(ctx, node):
                yield Diagnostic(
                    "S202", node.spans.get("name", node.span),
                    f"lifecycle node {where(node)} is launched but no lifecycle manager names it; it "
                    "stays unconfigured",
                    help=f'add "{node.name}" to a lifecycle manager\'s node_names', key=node.fqn)


@rule("S207", "lifecycle-event-reaches-nothing")
def event_reaches_nothing(ctx: CheckContext) -> Iterator[Diagnostic]:
    seen: set[object] = set()
    for launch in ctx.launches:
        if not launch.change_matchers:
            continue
        lifecycle = [n for n in launch.nodes if n.kind == "lifecycle_node"]
        names_known = not launch.opaque and all(n.fqn is not None for n in lifecycle)
        for how, value, span in launch.change_matchers:
            if (span, value) in seen:  # a helper called with several names: one finding each
                continue
            if how == "action":
                d = _action_matcher(launch, value, span)
            elif names_known:
                d = _name_matcher(launch, lifecycle, value, span)
            else:
                continue  # a lifecycle node whose name is not known may be the one named
            if d is not None:
                seen.add((span, value))
                yield d


def _action_matcher(launch: LaunchResult, target: str, span: Any) -> Diagnostic | None:
    """``matches_action(x)`` where ``x`` is a process action that is not a ``LifecycleNode``: only
    ``LifecycleNode.execute`` registers a handler for ChangeState events."""
    nodes = [n for n in launch.nodes if n.action_id == target]
    if not nodes or any(n.kind in ("lifecycle_node", "composable_node") for n in nodes):
        return None
    node = nodes[0]
    cls = ACTION_CLASSES.get(node.kind, "ExecuteProcess")
    what = f"{'an' if cls[0] in 'AEIOU' else 'a'} {cls}"
    return Diagnostic(
        "S207", span,
        f"ChangeState is aimed with matches_action() at {what} action ({where(node)}), not a "
        "LifecycleNode: only LifecycleNode actions receive lifecycle transitions, so this one "
        "reaches no node and the node is never configured or activated by it",
        help="launch the node with launch_ros.actions.LifecycleNode (its executable must create a "
             "lifecycle node), or remove the ChangeState",
        related=(Related(node.span, "the action it matches"),), key=target)


def _name_matcher(launch: LaunchResult, lifecycle: list[NodeInstance], name: str, span: Any) -> Diagnostic | None:
    """``matches_node_name('...')``: launch_ros compares ``'/' + name`` (or the name as given when
    it starts with ``/``) with each LifecycleNode's full name; a namespace is not added."""
    full = name if name.startswith("/") else f"/{name}"
    if any(n.fqn == full for n in lifecycle):
        return None
    plain = next((n for n in launch.nodes if n.fqn == full and n.kind != "lifecycle_node"), None)
    hint = how = ""
    if plain is not None:
        why = f"{full} is a {plain.kind.replace('_', ' ')} action, not a LifecycleNode"
    else:
        fqns = sorted({n.fqn for n in lifecycle if n.fqn})
        base = full.rsplit("/", 1)[-1]
        same_base = [f for f in fqns if f.rsplit("/", 1)[-1] == base][:3]
        close = same_base or did_you_mean(full, fqns)
        hint = ("; did you mean " + " or ".join(f'"{c}"' for c in close) + "?") if close else ""
        if same_base:  # the name is right, its namespace is not part of the comparison
            how = " (a namespace of the node, of its file or pushed by an including file is not added)"
        why = "no LifecycleNode of this launch has that name"
    return Diagnostic(
        "S207", span,
        f"ChangeState's matches_node_name({name!r}) compares with the full name \"{full}\"{how}, "
        f"and {why}: the transition reaches no node{hint}",
        help="give matches_node_name the node's full name with its namespace, or match the action "
             "itself with matches_action(<the LifecycleNode>)",
        related=(Related(plain.span, "the node with that name"),) if plain is not None else (), key=full)


# Executables of released packages that make plain nodes (never a lifecycle node a manager could
# bring up), which launch files commonly start without a name: rviz, the ros2_control spawners,
# teleoperation, the simulators' bridges and spawners.
NEVER_LIFECYCLE = frozenset({
    ("rviz2", "rviz2"), ("controller_manager", "spawner"), ("controller_manager", "unspawner"),
    ("controller_manager", "spawner.py"), ("controller_manager", "hardware_spawner"),
    ("robot_state_publisher", "robot_state_publisher"),
    ("joint_state_publisher", "joint_state_publisher"),
    ("joint_state_publisher_gui", "joint_state_publisher_gui"),
    ("tf2_ros", "static_transform_publisher"), ("teleop_twist_keyboard", "teleop_twist_keyboard"),
    ("teleop_twist_joy", "teleop_node"), ("joy", "joy_node"), ("joy", "game_controller_node"),
    ("gazebo_ros", "spawn_entity.py"), ("ros_gz_sim", "create"), ("ros_gz_bridge", "parameter_bridge"),
    ("ros_gz_image", "image_bridge"), ("ros_ign_gazebo", "create"), ("ros_ign_bridge", "parameter_bridge"),
    ("twist_mux", "twist_mux"), ("rqt_gui", "rqt_gui"), ("rqt_robot_steering", "rqt_robot_steering"),
    ("topic_tools", "relay"), ("image_transport", "republish"),
})


def _starts_ros_nodes(proc: NodeInstance) -> bool:
    """A process that starts ROS nodes launch does not name: ``ros2 run <package> <executable>``
    or ``ros2 launch ...`` (``ExecuteProcess(cmd=['ros2', 'run', 'nav2_amcl', 'amcl'])``)."""
    words = command_words(proc)
    if not words:
        return False
    # (the program may be unknown: FindExecutable(name='ros2') is found only at launch time)
    return (words[0] is None or words[0].rsplit("/", 1)[-1] == "ros2") and len(words) > 1 \
        and words[1] in ("run", "launch")


def _may_be_lifecycle(ctx: CheckContext, node: NodeInstance) -> bool:
    """Whether ``node`` (its name unknown) may be a lifecycle node a manager waits for: not an
    executable known to make a plain node (``NEVER_LIFECYCLE``, or a bundled interface that says
    so). What the linter extracted from sources is not trusted for this: a lifecycle base class it
    did not follow would hide the node a manager names."""
    if node.kind == "lifecycle_node":
        return True
    if (node.package, node.executable) in NEVER_LIFECYCLE:
        return False
    iface = ctx.interfaces.get(node.package, node.executable) if ctx.interfaces is not None else None
    return iface is None or not iface.source.startswith("bundled ") or bool(iface.lifecycle)


def _is_lifecycle(ctx: CheckContext, node: NodeInstance) -> bool:
    """A ``LifecycleNode`` action, or a node whose executable is known to make a lifecycle node
    (nav2 starts its servers with ``Node``). Not a ``LifecycleNode`` action whose executable's
    sources make a plain node under a name they decide (ydlidar_ros2_driver's
    ``rclcpp::Node::make_shared("...")``): launch_ros only watches its transition events, and
    there is nothing to configure or activate."""
    if node.kind not in ("lifecycle_node", "node", "composable_node"):
        return False
    iface = ctx.interfaces.get(node.package, node.executable) if ctx.interfaces is not None else None
    if node.kind == "lifecycle_node":
        only_sources = iface is not None and iface.source.startswith("extracted from") and " + " not in iface.source
        return not only_sources or bool(iface.lifecycle) or not (iface.node_name_decided and iface.node_name)
    return iface is not None and bool(iface.lifecycle)


def _autostarts(ctx: CheckContext, node: NodeInstance) -> bool:
    """The node is given ``autostart: true`` (drivers that configure and activate themselves), or
    its ``LifecycleNode`` is given ``autostart=`` (launch_ros since jazzy: launch brings it up)."""
    if isinstance(node.action, NodeAction) and node.action.autostart is not False:
        return True  # true, or not known
    ep = effective(ctx, node).get("autostart")
    return ep is not None and ep.value is True


def _set_by_command(launch: LaunchResult) -> set[str | None]:
    """The nodes a ``ros2 lifecycle set NODE TRANSITION`` process of the launch transitions (None:
    one whose name is not known)."""
    out: set[str | None] = set()
    for p in launch.nodes:
        if p.kind != "process" or p.active is False:
            continue
        words = command_words(p) or []
        for i in range(len(words) - 2):
            if words[i] == "lifecycle" and words[i + 1] == "set":
                name = words[i + 2]
                out.add(expand_topic_name(name, "_", "/") if isinstance(name, str) and name else None)
    return out


def _is_container(node: NodeInstance) -> bool:
    return node.kind == "container" or (
        node.kind == "node" and node.package == "rclcpp_components" and node.executable in CONTAINER_EXECUTABLES)


@rule("S203", "container-not-launched")
def container_not_launched(ctx: CheckContext) -> Iterator[Diagnostic]:
    for span, line, why in once(ctx, "early_loads"):
        target = f"the ComposableNodeContainer action at line {line}, which" if line is not None \
            else "a ComposableNodeContainer action that"
        yield Diagnostic(
            "S203", span,
            f"LoadComposableNodes targets {target} {why}: "
            "LoadComposableNodes.execute reads the container's node_name before it has executed "
            "and raises RuntimeError(\"cannot access 'node_name' before executing action\"), "
            "which ends the launch",
            help="add the container to the launch description before the LoadComposableNodes "
                 "(in the same event handler, if it is started from one), or give "
                 "target_container the container's full name, which the load waits for",
            key=why)
    seen: set[object] = set()
    for launch in ctx.launches:
        started = [n for n in launch.nodes if _is_container(n)]
        if not started:
            continue  # loads into a container started elsewhere (another launch, a running system)
        containers = {n.fqn for n in started}
        if launch.opaque or any(n.fqn is None for n in started):
            continue
        for node in launch.nodes:
            if node.kind != "composable_node" or node.container_id is not None or node.container is None:
                continue
            if node.active is False or node.container in containers or node.span in seen:
                continue
            seen.add(node.span)
            close = did_you_mean(node.container, [c for c in containers if c])
            hint = ("; did you mean " + " or ".join(f'"{c}"' for c in close) + "?") if close else ""
            yield Diagnostic(
                "S203", node.span,
                f'component {node.fqn or node.executable} is loaded into container "{node.container}", '
                f"which this launch never starts{hint}",
                help="start the container (ComposableNodeContainer) or fix target_container",
                key=node.container)


# ---- S204: controllers spawned without a type ---------------------------------------------------

CONTROLLER_MANAGERS = {("controller_manager", "ros2_control_node")}
_CONTROLLER_SPAWNERS = frozenset({"spawner", "spawner.py"})
# Options that give the controller its type another way (a type, a parameter file that may carry
# it: jazzy's spawner reads "type" from it, a namespace that moves the controller manager, or
# per-controller options): the controller manager's own parameters no longer decide.
_TYPE_ELSEWHERE = frozenset({"-t", "--controller-type", "-p", "--param-file", "-n", "--namespace",
                             "--controller", "--params-file", "--fallback_controllers"})
# The other options that take a value: the spawner's (graph.plan reads its controller names too)
# and those of ``ros2 control load_controller`` (ros2controlcli/verb/load_controller.py).
_VALUE_OPTIONS = (SPAWNER_VALUE_OPTIONS - _TYPE_ELSEWHERE) | {"--set-state", "--state", "--spin-time"}


def _loads(node: NodeInstance) -> tuple[list[str], str] | None:
    """(controller names, controller manager FQN) of a spawner, or of a ``ros2 control
    load_controller`` process; None when a word that matters is not known, or when the type may
    come from elsewhere (``_TYPE_ELSEWHERE``)."""
    if node.package == "controller_manager" and node.executable in _CONTROLLER_SPAWNERS:
        # Launch passes the spawner's parameters as --params-file, where jazzy's spawner looks for
        # a "type" (get_parameter_from_param_files): a file may give one; a dict only if it sets "type".
        if any(not isinstance(s, ResolvedParamDict) or any(p.name == "type" for p in s.params)
               for s in node.param_sources):
            return None
        words: list[str | None] = list(node.arguments)
        namespace = node.namespace  # a relative controller manager name is the spawner's namespace's
    elif node.kind == "process":
        all_words = command_words(node) or []
        for i in range(1, len(all_words) - 2):
            if all_words[i] == "control" and all_words[i + 1] == "load_controller" and \
                    (all_words[i - 1] or "").rsplit("/", 1)[-1] == "ros2":
                words, namespace = all_words[i + 2:], "/"  # the ros2 command's node is in /
                break
        else:
            return None
    else:
        return None
    names: list[str] = []
    manager: str | None = "controller_manager"
    pending: str | None = None  # the option whose value comes next
    for i, w in enumerate(words):
        if w is None:
            return None
        if pending is not None:
            manager = w if pending in ("-c", "--controller-manager") else manager
            pending = None
            continue
        if w == "--ros-args":  # ROS arguments from here on; a --params-file among them may type it
            if "--params-file" in words[i:]:
                return None
            break
        option, eq, value = w.partition("=")
        if option in _TYPE_ELSEWHERE:
            return None
        if w.startswith("-"):
            if option in _VALUE_OPTIONS:
                if eq:
                    manager = value if option in ("-c", "--controller-manager") else manager
                else:
                    pending = option
            continue
        names.append(w)
    if pending is not None or not names or not manager:
        return None
    if not manager.startswith("/"):
        if namespace is None:
            return None
        manager = namespace.rstrip("/") + "/" + manager
    return names, manager


@rule("S204", "controller-type-not-set")
def controller_type_not_set(ctx: CheckContext) -> Iterator[Diagnostic]:
    seen: set[object] = set()
    for launch in ctx.launches:
        cms = [n for n in launch.nodes if (n.package, n.executable) in CONTROLLER_MANAGERS and n.active is not False]
        if not cms or launch.opaque or any(n.fqn is None for n in cms):
            continue
        for node in launch.nodes:
            if node.active is False:
                continue
            loads = _loads(node)
            if loads is None:
                continue
            names, manager = loads
            for cm in cms:
                if cm.fqn != manager:
                    continue
                params = effective(ctx, cm)
                if not _all_sources_read(ctx, cm, params):
                    continue
                configured = sorted({k[:-len(".type")] for k in params if k.endswith(".type")})
                for name in names:
                    if f"{name}.type" in params or (node.span, cm.fqn, name) in seen:
                        continue
                    seen.add((node.span, cm.fqn, name))
                    close = did_you_mean(name, configured)
                    has = f"it configures {', '.join(configured)}" if configured else "it configures no controller"
                    if close:
                        has += ": did you mean " + " or ".join(f'"{c}"' for c in close) + "?"
                    yield Diagnostic(
                        "S204", node.spans.get("arguments", node.span),
                        f'{"spawner" if node.kind != "process" else "ros2 control load_controller"} loads '
                        f'controller "{name}" but controller manager {cm.fqn} has no parameter '
                        f'"{name}.type", so loading fails ("The \'type\' param was not defined for '
                        f"'{name}'\"); {has}",
                        help=f'give the controller manager "{name}: type: <package>/<Class>" under its '
                             "ros__parameters" + (", or pass the type to the spawner (--controller-type)"
                                                  if node.kind != "process" else ""),
                        related=(Related(cm.span, "the controller manager"),), key=f"{cm.fqn} {name}")


def _all_sources_read(ctx: CheckContext, node: NodeInstance, params: dict[str, Any]) -> bool:
    """Every parameter source of the controller manager is known and read, so the names it is
    given are all known (a missing file is P101's: the types it would have given are not reported
    again here). A value that is not known (robot_description from xacro) names its parameter all
    the same: it cannot be a controller's type."""
    if any(isinstance(s, ResolvedParamFile) and s.status == "missing" for s in node.param_sources):
        return False
    return fully_known(ctx, node, params, values=False)


# ---- S205/S206: a component's extra_arguments ---------------------------------------------------

# The extra arguments rclcpp's component manager reads from a load request, each required to be a
# bool (component_manager.cpp :: create_node_options). Humble to jazzy read two and ignore any
# other; since rclcpp 29.3 (ros2/rclcpp#2685, kilted on) it reads seven and refuses any other.
_EXTRA_ARGS_OLD = ("use_intra_process_comms", "forward_global_arguments")
_EXTRA_ARGS_NEW = ("forward_global_arguments", "enable_rosout", "use_intra_process_comms",
                   "enable_topic_statistics", "start_parameter_services",
                   "start_parameter_event_publisher", "use_clock_thread", "enable_logger_service")


def _extra_names(distro: str) -> tuple[str, ...]:
    return _EXTRA_ARGS_OLD if distro in ("humble", "iron", "jazzy") else _EXTRA_ARGS_NEW


def _extra_args(ctx: CheckContext) -> Iterator[tuple[NodeInstance, Any]]:
    """(component, typed extra argument) for components that may be loaded, each position once."""
    seen: set[tuple[object, str]] = set()
    for _launch, node in all_nodes(ctx, include_inactive=False):
        if node.kind != "composable_node":
            continue
        for rp in node.extra_args:
            if (rp.span, rp.name) not in seen:
                seen.add((rp.span, rp.name))
                yield node, rp


def _as_sent(rp: Any) -> str:
    value = rp.value
    if isinstance(value, str):
        what = f'the string "{value}"'
        if rp.typed_by == "python" and value.strip().lower() in ("true", "false"):
            what += " (a Python string stays a string: launch_ros types only substitutions by YAML)"
        return what
    kind = {int: "the integer", float: "the double", list: "the array"}.get(type(value), "the value")
    shown = f"{value!r}" if not isinstance(value, list) else str(value)
    return f"{kind} {shown}" + (f" (YAML of \"{rp.raw}\")" if rp.typed_by == "yaml" and rp.raw else "")


@rule("S205", "extra-argument-not-bool")
def extra_argument_not_bool(ctx: CheckContext) -> Iterator[Diagnostic]:
    names = _extra_names(ctx.distro)
    for node, rp in _extra_args(ctx):
        if rp.name not in names or rp.value is None or isinstance(rp.value, bool):
            continue
        yield Diagnostic(
            "S205", rp.span,
            f'extra argument "{rp.name}" of component {where(node)} is {_as_sent(rp)}; the container '
            f"accepts only a bool and refuses to load the component (\"Extra component argument "
            f"'{rp.name}' must be a boolean\")",
            help=f"give {rp.name} a bool: True or False in Python, or a substitution that evaluates "
                 f'to "true" or "false"',
            key=rp.name)


@rule("S206", "unknown-extra-argument")
def unknown_extra_argument(ctx: CheckContext) -> Iterator[Diagnostic]:
    names = _extra_names(ctx.distro)
    refuses = names is _EXTRA_ARGS_NEW
    for node, rp in _extra_args(ctx):
        if rp.name in names or not rp.name:  # no name: one given by a substitution (not known)
            continue
        close = did_you_mean(rp.name, list(names))
        hint = f'; did you mean "{close[0]}"?' if close else ""
        effect = (f"the container refuses to load the component (\"Extra component argument '{rp.name}' "
                  f"is not supported\")" if refuses else
                  "the container ignores it, so it has no effect")
        yield Diagnostic(
            "S206", rp.span,
            f'extra argument "{rp.name}" of component {where(node)} is not one the component '
            f"manager reads on {ctx.distro}; {effect}{hint}",
            help="the extra arguments a container reads: " + ", ".join(names) +
                 "; a parameter of the component goes into parameters=[...]",
            key=rp.name)
