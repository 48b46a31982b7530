"""Parameter values against declarations: P105 parameter-type-mismatch, P107 parameter-out-of-range,
P108 parameter-not-in-choices, P109 undeclared-parameter, P111 inconsistent-use-sim-time."""
from __future__ import annotations

from collections.abc import Iterator
from typing import Any

from physai_lint.checks._params import decl_source as _source
from physai_lint.checks._params import declarations, effective, fully_known, interface, nodes_with_params
from physai_lint.checks._util import CONTAINER_EXECUTABLES, did_you_mean, where
from physai_lint.checks.base import CheckContext, rule
from physai_lint.model.findings import Diagnostic, Related


def _fmt(value: Any) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, str):
        return f'"{value}"'
    return repr(value)


def _article(word: str | None) -> str:
    return "an" if (word or "x")[0] in "aeiou" else "a"


def _builtin() -> dict[str, Any]:
    """Parameters every ROS 2 node declares, whatever its sources say: the clock's
    ``use_sim_time``, a bool (rclcpp ``TimeSource::NodeState::attachNode``, rclpy
    ``TimeSource.attach_node``: declared with the default false and no dynamic typing, so a value
    of another type makes the node throw InvalidParameterTypeException at start-up)."""
    from physai_lint.interfaces.model import ParamDecl

    return {"use_sim_time": ParamDecl("use_sim_time", "bool", default=False, has_default=True,
                                      source="the ROS 2 client library's TimeSource")}


def _declared(ctx: CheckContext) -> Iterator[tuple[Any, Any, Any, Any]]:
    """(node, effective param, declaration, interface) for params whose declaration is known:
    from the node's interface, or one every node declares (``_builtin``)."""
    builtin = _builtin()
    for _, node in nodes_with_params(ctx):
        iface = interface(ctx, node)
        params = effective(ctx, node)
        declared = declarations(ctx, node, iface, params)
        for name, ep in sorted(params.items()):
            decl = declared(name) or builtin.get(name)
            if decl is not None and ep.value is not None and ep.origin is not None:
                yield node, ep, decl, iface


@rule("P105", "parameter-type-mismatch")
def type_mismatch(ctx: CheckContext) -> Iterator[Diagnostic]:
    from physai_lint.interfaces.gpl import type_compatible, value_kind

    seen: set[object] = set()
    for node, ep, decl, iface in _declared(ctx):
        if decl.dynamic_type or type_compatible(decl.type, ep.value) is not False:
            continue
        if (ep.origin, ep.name) in seen:
            continue
        seen.add((ep.origin, ep.name))
        got = value_kind(ep.value)
        fix = ""
        if decl.type == "double" and got == "integer":
            fix = f" (write {ep.value}.0)"
        elif decl.type == "double_array" and got == "integer_array":
            fix = " (write every item with a decimal point, e.g. 1.0)"
        elif decl.type == "bool" and got == "string" and (word := ep.value.strip().lower()) in ("true", "false"):
            fix = f" (write {word.title() if ep.origin.file.endswith('.py') else word} without quotes)"
        where = f" ({_source(decl.source)})" if decl.source else ""
        yield Diagnostic(
            "P105", ep.origin,
            f'parameter "{ep.name}" of {node.fqn or node.executable} is declared {decl.type}{where} '
            f"but is given {_fmt(ep.value)}, {_article(got)} {got}{_kept_slot(ep)}; the node fails "
            f"at start-up with InvalidParameterTypeException{fix}",
            help=f"give {_article(decl.type)} {decl.type} value{fix}",
            related=((Related(decl.span, "declared here"),) if decl.span else ()),
            key=f"{node.fqn}:{ep.name}")


def _kept_slot(ep: Any) -> str:
    """Why a later value of another type under the same node key does not replace the one read:
    rcl_variant_t keeps one slot per type and the client library reads the first set one (bool >
    int > double > string > arrays; rclcpp ``parameter_value_from``), SEMANTICS §4b."""
    from physai_lint.checks._util import line_ref

    won = next((i for i, b in enumerate(ep.chain) if not b.overridden), None)
    if won is None:
        return ""
    later = next((b for b in ep.chain[won + 1:] if b.span is not None and b.kind is not None
                  and b.kind != ep.chain[won].kind and b.node_key == ep.chain[won].node_key), None)
    if later is None:
        return ""
    return (f" (the later {_fmt(later.value)} at {line_ref(later.span, ep.origin)} does not replace "
            f"it: rcl keeps one value per type under a node key and the node reads the "
            f"{ep.chain[won].kind} first)")


@rule("P107", "parameter-out-of-range")
def out_of_range(ctx: CheckContext) -> Iterator[Diagnostic]:
    yield from _validate(ctx, choices=False)


@rule("P108", "parameter-not-in-choices")
def not_in_choices(ctx: CheckContext) -> Iterator[Diagnostic]:
    yield from _validate(ctx, choices=True)


def _validate(ctx: CheckContext, choices: bool) -> Iterator[Diagnostic]:
    from physai_lint.interfaces.gpl import type_compatible, validate

    seen: set[object] = set()
    for node, ep, decl, _ in _declared(ctx):
        if type_compatible(decl.type, ep.value) is False:
            continue
        problems = []
        is_choice = bool(decl.choices) or any(n in ("one_of", "subset_of") for n, _ in decl.validators)
        if is_choice != choices:
            continue
        if decl.choices and ep.value not in decl.choices:
            problems.append(f"{_fmt(ep.value)} is not one of {decl.choices}")
        if decl.min is not None and isinstance(ep.value, (int, float)) and ep.value < decl.min:
            problems.append(f"{_fmt(ep.value)} is below the minimum {decl.min}")
        if decl.max is not None and isinstance(ep.value, (int, float)) and ep.value > decl.max:
            problems.append(f"{_fmt(ep.value)} is above the maximum {decl.max}")
        problems += validate(decl, ep.value)
        if not problems or (ep.origin, ep.name) in seen:
            continue
        seen.add((ep.origin, ep.name))
        code = "P108" if choices else "P107"
        yield Diagnostic(
            code, ep.origin,
            f'parameter "{ep.name}" of {node.fqn or node.executable}: {"; ".join(dict.fromkeys(problems))}'
            f"{f' ({_source(decl.source)})' if decl.source else ''}; the node rejects it at start-up",
            help="use a value the declaration accepts",
            related=((Related(decl.span, "declared here"),) if decl.span else ()),
            key=f"{node.fqn}:{ep.name}")


# The default of P109's ``ignore`` option (rules/P/P109-undeclared-parameter.md): parameters every
# node takes without declaring them in its sources (rclcpp declares use_sim_time; QoS overrides
# are read by the publishers and subscriptions).
P109_IGNORE = ("use_sim_time", "qos_overrides.*")


@rule("P109", "undeclared-parameter")
def undeclared(ctx: CheckContext) -> Iterator[Diagnostic]:
    from fnmatch import fnmatchcase

    from physai_lint.interfaces.gpl import is_template

    seen: set[object] = set()
    ignore = tuple(ctx.option("P109", "ignore", P109_IGNORE))
    for _, node in nodes_with_params(ctx):
        iface = interface(ctx, node)
        if iface is None or not iface.parameters_complete or node.fqn is None:
            continue
        for name, ep in sorted(effective(ctx, node).items()):
            if name.startswith("ros__") or any(fnmatchcase(name, p) for p in ignore):
                continue
            if iface.is_declared(name) is not False or ep.origin is None:
                continue
            if ep.node_key and "*" in ep.node_key:
                continue  # a wildcard key hands every node every parameter: not this node's mistake
            if (ep.origin, name) in seen:
                continue
            seen.add((ep.origin, name))
            close = did_you_mean(name, [n for n in iface.parameters or {} if not is_template(n)])
            hint = ("; did you mean " + " or ".join(f'"{c}"' for c in close) + "?") if close else ""
            yield Diagnostic(
                "P109", ep.origin,
                f'{where(node)} does not declare parameter "{name}"{hint}; the value is ignored',
                help="fix the parameter name, or remove it", key=f"{node.fqn}:{name}")


# Nodes whose output does not depend on the clock: leaving them on wall time is harmless.
# Nodes whose output does not depend on their own clock: static transforms, and the Gazebo
# bridges, which copy each message's stamp from the other side (ros_gz_bridge convert_*_header);
# one of them is usually the /clock source itself. The simulators' spawn tools put a model in the
# world and exit (ros_gz_sim create.cpp, gazebo_ros spawn_entity.py). A component container's
# own node only loads components, each with its own parameters (use_sim_time included).
_TIME_AGNOSTIC = frozenset({("tf2_ros", "static_transform_publisher"),
                            *(("rclcpp_components", exe) for exe in CONTAINER_EXECUTABLES),
                            ("ros_gz_bridge", "parameter_bridge"), ("ros_ign_bridge", "parameter_bridge"),
                            ("ros_gz_image", "image_bridge"), ("ros_ign_image", "image_bridge"),
                            ("ros_gz_sim", "create"), ("ros_ign_gazebo", "create"),
                            ("gazebo_ros", "spawn_entity.py")})
# Teleoperation nodes that publish an unstamped Twist unless the parameter named here is true
# (teleop_twist_keyboard.py `stamped`, teleop_twist_joy.cpp `publish_stamped_twist`): their
# output carries no time, so wall time is harmless unless they are told to stamp it.
_UNSTAMPED_UNLESS = {("teleop_twist_keyboard", "teleop_twist_keyboard"): "stamped",
                     ("teleop_twist_joy", "teleop_node"): "publish_stamped_twist"}


def _time_agnostic(node: Any, params: dict[str, Any]) -> bool:
    key = (node.package, node.executable)
    if key in _TIME_AGNOSTIC:
        return True
    flag = _UNSTAMPED_UNLESS.get(key)
    if flag is None:
        return False
    ep = params.get(flag)
    return ep is None or ep.value is False


def _publishes_clock(ctx: CheckContext, node: Any) -> bool:
    """The node publishes /clock (its code or declaration says so): the time source of the others."""
    iface = interface(ctx, node)
    if iface is None:
        return False
    return any(e.name == "/clock" or (e.name == "clock" and node.namespace in ("/", ""))
               for e in iface.endpoints("publishers"))


@rule("P111", "inconsistent-use-sim-time")
def use_sim_time(ctx: CheckContext) -> Iterator[Diagnostic]:
    seen: set[object] = set()
    for launch in ctx.launches:
        values: dict[bool, list[tuple[Any, Any]]] = {True: [], False: []}
        unset: list[Any] = []
        for node in launch.nodes:
            if node.active is False or node.kind == "process":
                continue
            if _publishes_clock(ctx, node):
                continue  # the /clock source itself runs on wall time (a simulator's bridge)
            params = effective(ctx, node)
            ep = params.get("use_sim_time")
            if ep is not None and isinstance(ep.value, bool) and ep.origin is not None:
                values[ep.value].append((node, ep))
            elif ep is None and node.kind != "container" and fully_known(ctx, node, params) and \
                    not _time_agnostic(node, params):
                unset.append(node)
        if values[True] and values[False]:
            minority = min(values[True], values[False], key=len)
            majority = values[True] if minority is values[False] else values[False]
            for node, ep in minority:
                other = majority[0][0]
                if (ep.origin, node.fqn) in seen:
                    continue
                seen.add((ep.origin, node.fqn))
                yield Diagnostic(
                    "P111", ep.origin,
                    f'{node.fqn or node.executable} has use_sim_time {_fmt(ep.value)} but '
                    f"{len(majority)} other node(s) of this launch (e.g. {other.fqn or other.executable}) "
                    f"have {_fmt(not ep.value)}",
                    help="set use_sim_time the same way for every node (SetParameter('use_sim_time', ...))",
                    key=f"{node.fqn}:use_sim_time")
        if not values[True] or launch.use_sim_time_actions:
            continue  # SetUseSimTime may cover the unset nodes; its scope is not tracked here
        other = values[True][0][0]
        for node in unset:
            if (node.span, node.fqn) in seen:
                continue
            seen.add((node.span, node.fqn))
            yield Diagnostic(
                "P111", node.span,
                f"{where(node)} never gets use_sim_time, so it runs on wall-clock time (default false), "
                f"but {len(values[True])} other node(s) of this launch (e.g. {other.fqn or other.executable}) "
                "have use_sim_time true",
                help="give every node use_sim_time, e.g. one SetParameter(name='use_sim_time', "
                     "value=...) before the nodes, or add it to this node's parameters",
                related=(Related(values[True][0][1].origin, "use_sim_time true here"),),
                key=f"{node.fqn}:use_sim_time")
