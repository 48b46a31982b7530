"""Topics and remappings over the node/topic graph: T101 identity-remap, T102 unused-remap,
T103 set-remap-no-effect, T104 remap-wrong-side, T201 subscription-without-publisher,
T202 publication-without-subscriber, T203 topic-type-mismatch, T204 duplicate-service-server."""
from __future__ import annotations

from collections.abc import Iterator
from typing import Any

from physai_lint.checks._params import effective, fully_known, interface
from physai_lint.checks._util import all_nodes, line_ref, run_memo, where
from physai_lint.checks.base import CheckContext, rule
from physai_lint.graph.system import (
    Endpoint,
    SystemGraph,
    apply_remaps,
    build_graph,
    remap_target,
    similar,
)
from physai_lint.interfaces.model import LIFECYCLE_ENDPOINTS
from physai_lint.model.findings import Diagnostic, Related
from physai_lint.model.values import literal_of, span_of
from physai_lint.resolve.model import EffRemap, NodeInstance
from physai_lint.resolve.names import validate_full_topic_name

_CACHE_KEY = "_graphs"


def graphs(ctx: CheckContext) -> list[SystemGraph]:
    return run_memo(ctx.options, _CACHE_KEY, ctx.launches,  # type: ignore[no-any-return]
                    lambda: [build_graph(l, ctx.interfaces) for l in ctx.launches])


@rule("T101", "identity-remap")
def identity_remap(ctx: CheckContext) -> Iterator[Diagnostic]:
    # A rule is reported when it is an identity for every node it reaches, in every launch, and
    # whatever the launch arguments. Autoware's <remap from="input" to="$(var input)"/> maps a
    # name to itself only while the argument keeps its default "/input". Sides written differently
    # that meet after expansion in the root namespace are the namespacing idioms: nav2's
    # ('/tf', 'tf') keeps /tf inside the namespace a PushROSNamespace gives (under a condition on
    # the namespace argument), ('scan', '/scan') pins the global topic once the node is namespaced;
    # in a namespace the launch file fixes, they are the same name spelled twice.
    verdict: dict[object, bool] = {}
    first: dict[object, EffRemap] = {}
    for _, node in all_nodes(ctx):
        for r in node.remaps:
            if r.origin != "node" or r.src is None:
                continue
            if verdict.get(r.span) is False:
                continue
            first.setdefault(r.span, r)
            written = _written_remap(node, r)
            if written is not None and not all(_fixed(v) for v in written):
                verdict[r.span] = False  # a side comes from a launch argument
            elif r.src == r.dst:
                verdict[r.span] = True
            else:
                src, dst = remap_target(r, node)
                verdict[r.span] = (src is not None and src == dst and node.namespace not in (None, "/")
                                   and _namespace_fixed(node))
    for span, identity in verdict.items():
        if identity:
            r = first[span]
            yield Diagnostic("T101", r.span, f'remap "{r.src}" -> "{r.dst}" maps a name to itself',
                             help="remove the rule, or remap to the topic you meant", key=f"{r.src}")


def _written_remap(node: NodeInstance, r: EffRemap) -> tuple[Any, Any] | None:
    """The two sides of ``r`` as the launch file wrote them (None when not found)."""
    for w in getattr(node.action, "remappings", ()):
        if w.span == r.span:
            return w.src, w.dst
    for field in ("arguments", "ros_arguments"):  # a -r rule on the command line: one value
        for value in getattr(node.action, field, None) or ():
            if span_of(value) == r.span:
                return value, value
    return None


def _fixed(value: Any) -> bool:
    """Written as text only (no launch configuration or other substitution)."""
    return literal_of(value) is not None


def _namespace_fixed(node: NodeInstance) -> bool:
    """The node's own namespace is absent or written as text: its expansion does not depend on a
    launch argument (a namespace pushed by an includer is part of that include's context)."""
    written = getattr(node.action, "namespace", None)
    return written is None or _fixed(written)


def _shadowing(node: NodeInstance, index: int) -> tuple[EffRemap, str] | None:
    """(earlier rule, the name both match) when an earlier rule of the node matches the same name
    as rule ``index`` and maps it elsewhere: rcl applies the first rule that matches
    (``rcl_remap_first_match``), so rule ``index`` never applies to this node. None when it may."""
    r = node.remaps[index]
    if r.src is None or r.src.startswith("__") or not _applies(r, node):
        return None
    src, dst = remap_target(r, node)
    if src is None:
        return None
    for earlier in node.remaps[:index]:
        if earlier.src is None:
            return None  # an unknown rule may match first: nothing known
        if earlier.src.startswith("__") or not _applies(earlier, node):
            continue
        e_src, e_dst = remap_target(earlier, node)
        if e_src is None:
            return None
        if e_src == src:
            return (earlier, src) if e_dst != dst else None
    return None


def _applies(r: EffRemap, node: NodeInstance) -> bool:
    return r.node_prefix is None or (node.name is not None and r.node_prefix == node.name)


def _rule_words(r: EffRemap) -> str:
    if r.origin == "global":
        return {".xml": "<set_remap>", ".yaml": "set_remap"}.get(
            r.span.file[r.span.file.rfind("."):], "the SetRemap")
    return "the rule"


def _shadowed_rules(ctx: CheckContext) -> Iterator[Diagnostic]:
    verdict: dict[object, tuple[NodeInstance, EffRemap, EffRemap, str] | None] = {}
    for _, node in all_nodes(ctx):
        if node.active is False or node.kind == "process":
            continue
        for i, r in enumerate(node.remaps):
            if r.origin != "node" or verdict.get(r.span, 0) is None:
                continue
            hit = _shadowing(node, i)
            verdict[r.span] = (node, r, *hit) if hit is not None else None
    for found in verdict.values():
        if found is None:
            continue
        node, r, earlier, name = found
        yield Diagnostic(
            "T102", r.span,
            f'remap "{r.src}" -> "{r.dst}" never applies to {node.fqn or node.executable}: '
            f'{_rule_words(earlier)} "{earlier.src}" -> "{earlier.dst}" ({line_ref(earlier.span, r.span)}) '
            f'matches "{name}" first, and rcl applies only the first rule that matches',
            help=("remove one of the two rules, or give the SetRemap a narrower scope (a GroupAction "
                  "around the nodes it is meant for)" if earlier.origin == "global" else
                  "remove one of the two rules: only the first one that matches counts"),
            related=(Related(earlier.span, "the rule that applies"),),
            key=f"{node.fqn}:{r.src}")


def _foreign_prefix_rules(ctx: CheckContext) -> Iterator[Diagnostic]:
    """A node's own ``node:from:=to`` rule whose prefix is not the node's name: rcl compares the
    prefix with the node's final name (remap.c :: rcl_remap_first_match, given rcl_node_get_name),
    and launch's ``-r __node:=<name>`` (``name=``) renames every node of the process, so no node
    there has the prefix's name."""
    seen: set[object] = set()
    for _, node in all_nodes(ctx, include_inactive=False):
        # a container's own rules reach the components that forward its global arguments
        if node.kind in ("process", "container") or not node.name_explicit or not node.name:
            continue
        for r in node.remaps:
            if r.origin != "node" or r.node_prefix is None or r.node_prefix == node.name or \
                    r.src is None or r.src.startswith("__") or r.span in seen:
                continue
            seen.add(r.span)
            yield Diagnostic(
                "T102", r.span,
                f'remap "{r.node_prefix}:{r.src}" -> "{r.dst}" never applies: it is only for a node named '
                f'"{r.node_prefix}", and this node is named "{node.name}" (rcl matches the prefix against '
                f'the node\'s final name)',
                help=f'write the rule as "{r.src}:={r.dst}", or as "{node.name}:{r.src}:={r.dst}"',
                key=f"{node.fqn}:{r.node_prefix}:{r.src}")


@rule("T102", "unused-remap")
def unused_remap(ctx: CheckContext) -> Iterator[Diagnostic]:
    seen: set[object] = set()
    for d in _shadowed_rules(ctx):
        seen.add(d.span)
        yield d
    for d in _foreign_prefix_rules(ctx):
        if d.span not in seen:
            seen.add(d.span)
            yield d
    # One remapping list written once and handed to several nodes (nav2's ('/tf', 'tf') list on
    # every server) is meant for whichever of them uses each rule: a rule is unused only when no
    # node it reaches uses it, or may use it (its interface unknown or not complete).
    for g in graphs(ctx):
        for node in g.launch.nodes:
            if node.active is False or node.id in g.rejected:  # launch refuses it: it uses nothing
                continue
            for i, r in enumerate(node.remaps):
                if r.origin == "node" and (g.remap_used(node.id, i) or node.id not in g.known
                                           or not _trusted(ctx, node)):
                    seen.add(r.span)
    for g in graphs(ctx):
        for node in g.launch.nodes:
            if node.id not in g.known or node.active is False or node.id in g.rejected:
                continue
            if not _trusted(ctx, node):
                continue  # bundled declarations may omit optional topics: only trust declared ones
            eps = g.endpoints_of(node.id)
            if any(e.expanded is None for e in eps):
                continue
            for i, r in enumerate(node.remaps):
                if r.origin != "node" or r.src is None or r.src.startswith("__") or r.span in seen:
                    continue
                if g.remap_used(node.id, i):
                    continue
                src, dst = remap_target(r, node)
                if src is None or src == dst:
                    continue
                if any(e.expanded == src for e in eps):
                    continue  # shadowed by an earlier rule: not "no effect" for this rule's purpose
                if wrong_side(g, node, i, True) is not None:
                    continue  # T104 explains this one better
                seen.add(r.span)
                names = sorted({e.expanded for e in eps if e.expanded})
                detail = _relative_hint(r.src, src, names, node, "the node") or (
                    "; its names are " + ", ".join(f'"{n}"' for n in names[:6]) if names else "")
                yield Diagnostic(
                    "T102", r.span,
                    f'remap "{r.src}" matches no topic of {node.fqn or node.executable} '
                    f'(it would match "{src}"){detail}',
                    help="remap a name the node actually uses (relative names resolve against the "
                         "node's namespace)",
                    key=f"{node.fqn}:{r.src}")


def _trusted(ctx: CheckContext, node: NodeInstance) -> bool:
    """Whether the node's topics are known to be all of them: only an ``--interfaces`` declaration
    says so. Bundled declarations may omit optional topics, and sources miss what a base class or
    a library member creates (a costmap's tf listener, autoware's polling subscribers, image
    transport): on public repositories nearly every "matches no topic" from extracted C++ was one."""
    iface = ctx.interfaces.get(node.package, node.executable)
    if iface is None:
        return False
    layers = str(getattr(iface, "source", "")).split(" + ")
    return any(x and not x.startswith(("bundled", "extracted", "generate_parameter_library")) for x in layers)


def wrong_side(g: SystemGraph, node: NodeInstance, index: int, trusted: bool) -> tuple[str, str] | None:
    """(expanded from, expanded to) when rule ``index`` is written backwards: its match is none of the
    node's names but its replacement is one, and (unless the interface is trusted to be complete) the
    match is a name another node uses."""
    r = node.remaps[index]
    if r.origin != "node" or r.src is None or r.dst is None or r.src.startswith("__"):
        return None
    eps = g.endpoints_of(node.id)
    if not eps or any(e.expanded is None for e in eps) or g.remap_used(node.id, index):
        return None
    src, dst = remap_target(r, node)
    if src is None or dst is None or src == dst:
        return None
    own = {e.expanded for e in eps}
    if src in own or dst not in own:
        return None
    if not trusted and not any(e.node != node.id and src in (e.resolved, e.expanded) for e in g.endpoints):
        return None
    return src, dst


@rule("T104", "remap-wrong-side")
def remap_wrong_side(ctx: CheckContext) -> Iterator[Diagnostic]:
    seen: set[object] = set()
    for g in graphs(ctx):
        for node in g.launch.nodes:
            if node.id not in g.known or node.active is False:
                continue
            trusted = _trusted(ctx, node)
            for i, r in enumerate(node.remaps):
                found = wrong_side(g, node, i, trusted)
                if found is None or r.span in seen:
                    continue
                seen.add(r.span)
                src, dst = found
                others = sorted({g.node(e.node).fqn or "" for e in g.endpoints
                                 if e.node != node.id and src in (e.resolved, e.expanded)} - {""})
                other = f'; "{src}" is what {", ".join(others[:3])} use' if others else ""
                yield Diagnostic(
                    "T104", r.span,
                    f'remap "{r.src}" -> "{r.dst}" on {node.fqn or node.executable} looks written backwards: '
                    f'the node uses "{dst}" (the replacement) and no name matching "{src}"{other}, so '
                    "the rule has no effect",
                    help=f'swap the sides: "{r.dst}" -> "{r.src}" (a rule is name_in_the_node:=new_name)',
                    key=f"{node.fqn}:{r.src}")


@rule("T103", "set-remap-no-effect")
def set_remap_no_effect(ctx: CheckContext) -> Iterator[Diagnostic]:
    seen: set[object] = set()
    for launch in ctx.launches:
        for span, src, dst, reached in launch.set_remaps:
            if reached or span in seen or launch.opaque:
                continue
            seen.add(span)
            yield Diagnostic("T103", span, f'SetRemap "{src}" -> "{dst}" reaches no node',
                             help="put the SetRemap before the nodes it should apply to, in the same scope",
                             key=f"{src}:{dst}")
    yield from _set_remaps_matching_nothing(ctx, seen)


def _relative_hint(written: str, src: str, names: list[str], node: NodeInstance, who: str) -> str:
    """The hint for a rule matching none of ``names``: the node's name with the same last token
    (an absolute rule for a relative name in a namespace), else ""."""
    relative = [n for n in names if n.rsplit("/", 1)[-1] == src.rsplit("/", 1)[-1]]
    if relative and written.startswith("/"):
        return (f'; {who} uses "{relative[0]}" (a relative name in namespace "{node.namespace}"): '
                f'write the rule as "{relative[0].rsplit("/", 1)[-1]}"')
    return f'; did you mean "{relative[0]}"?' if relative else ""


# Names rcl gives every node, through rcl_node_resolve_name like any other (so a rule may remap
# them), that interfaces do not list: /rosout, /parameter_events and the parameter services.
_EVERY_NODE_NAMES = frozenset({"rosout", "parameter_events", "describe_parameters", "get_parameters",
                               "get_parameter_types", "list_parameters", "set_parameters",
                               "set_parameters_atomically", "get_type_description"})


def _set_remaps_matching_nothing(ctx: CheckContext, seen: set[object]) -> Iterator[Diagnostic]:
    """A SetRemap every node it reaches ignores: each has a complete, trusted interface (T102's
    conditions) and no name the rule matches once expanded in that node's namespace. One that a
    node may use (its names unknown, or not all known) is left alone."""
    reached: dict[object, list[tuple[Any, NodeInstance, int]]] = {}
    for g in graphs(ctx):
        for node in g.launch.nodes:
            if node.active is False or node.kind == "process" or node.id in g.rejected:
                continue
            for i, r in enumerate(node.remaps):
                if r.origin == "global" and r.span not in seen:
                    reached.setdefault(r.span, []).append((g, node, i))
    for span, uses in reached.items():
        first = uses[0][1].remaps[uses[0][2]]
        if first.src is None or first.src.startswith("__") or \
                first.src.rstrip("/").rsplit("/", 1)[-1] in _EVERY_NODE_NAMES:
            continue
        names: list[tuple[NodeInstance, str, list[str]]] = []
        for g, node, i in uses:
            r = node.remaps[i]
            if node.id not in g.known or not _trusted(ctx, node) or not _applies(r, node):
                break
            eps = g.endpoints_of(node.id)
            src, dst = remap_target(r, node)
            if src is None or g.remap_used(node.id, i) or any(e.expanded is None or e.expanded == src for e in eps):
                break
            names.append((node, src, sorted({e.expanded for e in eps if e.expanded})))
        else:
            seen.add(span)
            node, src, own = names[0]
            detail = _relative_hint(first.src, src, own, node, node.fqn or node.executable or "the node")
            reach = ", ".join(sorted({n.fqn or n.executable or "?" for n, _, _ in names})[:4])
            yield Diagnostic(
                "T103", span,
                f'SetRemap "{first.src}" -> "{first.dst}" matches no topic or service of the nodes it '
                f'reaches ({reach}; for {node.fqn or node.executable} it would match "{src}"){detail}',
                help="remap a name the nodes actually use (a relative name resolves against each "
                     "node's namespace), or move the SetRemap to where the nodes that use it are",
                key=f"{first.src}:{first.dst}")


@rule("T201", "subscription-without-publisher")
def subscription_without_publisher(ctx: CheckContext) -> Iterator[Diagnostic]:
    yield from _dangling(ctx, "subscriber", "publisher", "T201")


@rule("T202", "publication-without-subscriber")
def publication_without_subscriber(ctx: CheckContext) -> Iterator[Diagnostic]:
    yield from _dangling(ctx, "publisher", "subscriber", "T202")


# Topics rcl gives every node (each publishes /rosout and both ends of /parameter_events): never
# dangling whatever the interfaces list.
_IMPLICIT_TOPICS = frozenset({"/rosout", "/parameter_events"})
# The defaults of the rules' ``ignore-topics`` option (rules/T/T201-*.md, T202-*.md).
# "*/tf" is /tf and a robot's namespaced /r1/tf alike (multi-robot launches remap them so).
T201_IGNORE_TOPICS = ("/clock", "*/tf", "*/tf_static", "/parameter_events", "*/initialpose", "*/goal_pose",
                      "*/set_pose")
T202_IGNORE_TOPICS = ("/rosout", "/parameter_events", "*/tf", "*/tf_static", "*/diagnostics", "*/joint_states",
                      "*/robot_description")


_LIFECYCLE_SERVICES = frozenset(name for kind, name, _ in LIFECYCLE_ENDPOINTS if kind == "services")


def _valid(topic: str) -> bool:
    return validate_full_topic_name(topic) is None


def _dangling(ctx: CheckContext, mine: str, other: str, code: str) -> Iterator[Diagnostic]:
    from fnmatch import fnmatchcase

    seen: set[object] = set()
    ignore = tuple(ctx.option(code, "ignore-topics",
                              T201_IGNORE_TOPICS if code == "T201" else T202_IGNORE_TOPICS))
    near_miss_only = mine == "publisher" and bool(ctx.option(code, "only-with-near-miss", True))
    for g in graphs(ctx):
        if g.has_unknown_endpoints():
            continue  # some node's topics are unknown: it might be the missing end
        if len({e.node for e in g.endpoints if e.kind in ("publisher", "subscriber") and e.resolved
                and e.resolved not in _IMPLICIT_TOPICS
                and not any(fnmatchcase(e.resolved, p) for p in ignore)}) < 2:
            # a launch of one node (a filter, a driver) whose inputs and outputs are others': a
            # static transform or a clock beside it changes nothing
            continue
        by_topic: dict[str, set[str]] = {}  # topic -> nodes with an endpoint of the other kind
        types: dict[str, set[str | None]] = {}  # topic -> the message types of those endpoints
        for o in g.of_kind(other):  # type: ignore[arg-type]
            if o.when and _exists(ctx, g, o) is False:
                continue  # off under the node's parameters (imu/mag with use_mag false)
            if o.resolved and _valid(o.resolved):  # an invalid name (N104) is never suggested
                by_topic.setdefault(o.resolved, set()).add(o.node)
                types.setdefault(o.resolved, set()).add(o.type)
        clocks: dict[str, list[str]] = {}  # topic -> the nodes whose sim time reads it
        if other == "subscriber":
            for node, topic in _sim_time_clocks(ctx, g):
                by_topic.setdefault(topic, set()).add(node.id)
                types.setdefault(topic, set()).add(CLOCK_TYPE)
                clocks.setdefault(topic, []).append(node.fqn or node.id)
        others = set(by_topic)
        # T202's near miss has subscribers and no publisher (a topic somebody publishes, under its
        # name or one known only at run time, is connected already)
        served: set[str] = set()
        if mine == "publisher":
            served = {e.resolved for e in g.of_kind(mine) if e.resolved}
            served |= {t for t in others
                       if any(kind == mine and (typ is None or None in types[t] or typ in types[t])
                              for _, kind, typ in g.unnamed)}
        # A near miss is another node's topic: a filter's "output/pointcloud" is not a misspelt
        # "input/pointcloud" of the same filter (its own topics are left out of the suggestions).
        own: dict[str, set[str]] = {}
        for topic, nodes in by_topic.items():
            if len(nodes) == 1:
                own.setdefault(next(iter(nodes)), set()).add(topic)
        namespaces = {n.namespace for n in g.launch.nodes if n.namespace}
        connected = {e.resolved for e in g.of_kind(mine) if e.resolved}  # both ends known
        for e in g.of_kind(mine):  # type: ignore[arg-type]
            if e.resolved is None or e.resolved in others or e.resolved.split("/")[-1].startswith("_"):
                continue
            if e.when and not _exists(ctx, g, e):
                continue  # off, or maybe off, under the node's parameters
            if g.unnamed_lifecycle and e.resolved.endswith("/transition_event"):
                continue  # a lifecycle node of unknown name publishes one: maybe this one
            if any(nid != e.node and kind == other and (t is None or e.type is None or t == e.type)
                   for nid, kind, t in g.unnamed):
                continue  # another node's end of this type under a name known only at run time
            if not _valid(e.resolved):
                continue  # N104 reports the name itself; no node could ever match it
            if e.resolved in _IMPLICIT_TOPICS or any(fnmatchcase(e.resolved, p) for p in ignore):
                continue
            node = g.node(e.node)
            span = node.span
            if e.remap is not None:
                span = node.remaps[e.remap].span
            elif e.where is not None:
                span = e.where
            if (span, e.resolved) in seen:
                continue
            seen.add((span, e.resolved))
            # a near miss carries the same messages: /joint_states is no misspelt /tf_static
            candidates = {t for t in others - own.get(e.node, set()) - served
                          if e.type is None or None in types[t] or e.type in types[t]}
            close = [c for c in similar(e.resolved, candidates, 0.8 if mine == "publisher" else 0.6)
                     if not (c in connected and _sibling_copy(e.resolved, c, namespaces))]
            if near_miss_only and not close:
                continue  # an output nobody reads is normal (sensors, diagnostics); a near miss is not
            hint = (" (did you mean " + " or ".join(f'"{c}"' + _clock_readers(clocks.get(c)) for c in close)
                    + "?)") if close else ""
            verb, missing = ("subscribes to", "nothing publishes it") if mine == "subscriber" else (
                "publishes", "nothing subscribes to it")
            yield Diagnostic(
                code, span, f'{node.fqn or node.executable} {verb} "{e.resolved}" but {missing}{hint}',
                help="remap one end so both use the same name, or launch the missing node",
                key=f"{node.fqn}:{e.resolved}")


CLOCK_TYPE = "rosgraph_msgs/msg/Clock"


def _clock_readers(nodes: list[str] | None) -> str:
    """What the hint says of a topic the time source of nodes with use_sim_time reads."""
    if not nodes:
        return ""
    names = sorted(set(nodes))
    shown = ", ".join(names[:3]) + (f" and {len(names) - 3} more" if len(names) > 3 else "")
    return f", which the time source of {shown} (use_sim_time true) subscribes to"


def _sim_time_clocks(ctx: CheckContext, g: SystemGraph) -> Iterator[tuple[NodeInstance, str]]:
    """(node, topic) of the clock subscription of each node whose use_sim_time is certainly
    true: rclcpp's and rclpy's time source subscribe to the absolute "/clock" then (rclcpp
    ``TimeSource::NodeState::create_clock_sub``, rclpy ``TimeSource._subscribe_to_clock_topic``),
    which the node's remap rules apply to like any name. No interface lists it: the node's code
    never names it."""
    for node in g.launch.nodes:
        if node.id not in g.known or node.id in g.rejected:
            continue
        ep = effective(ctx, node).get("use_sim_time")
        if ep is not None and ep.certain and ep.value is True:
            topic, _ = apply_remaps("/clock", node)
            if topic is not None:
                yield node, topic


def _sibling_copy(name: str, candidate: str, namespaces: set[str]) -> bool:
    """``candidate`` is ``name`` in another node namespace at the same depth (``/robot2/cmd_vel``
    for ``/robot1/cmd_vel``): once connected there, the other robot's copy of the topic, no near
    miss of this one (an unconnected one is: a camera's info beside its rectifier's)."""
    a, c = name.split("/"), candidate.split("/")
    if len(a) != len(c):
        return False
    diff = [i for i, (x, y) in enumerate(zip(a, c)) if x != y]
    if len(diff) != 1 or diff[0] == len(a) - 1:
        return False
    i = diff[0] + 1
    return "/".join(a[:i]) in namespaces and "/".join(c[:i]) in namespaces


def _exists(ctx: CheckContext, g: SystemGraph, e: Endpoint) -> bool | None:
    """Whether the node has ``e``, which exists only under some parameter values (``e.when``):
    each parameter's effective value, else its declared default once every parameter source of
    the node is known. None when that cannot be told."""
    node = g.node(e.node)
    params = effective(ctx, node)
    decls = getattr(interface(ctx, node), "parameters", None) or {}
    exists: bool | None = True
    for name, wanted in e.when:
        ep = params.get(name)
        if ep is not None:
            if not ep.certain:
                return None
            value = ep.value
        elif name in decls and decls[name].has_default and fully_known(ctx, node, params):
            value = decls[name].default
        else:
            return None
        if type(value) is not type(wanted) or value != wanted:
            exists = False
    return exists


@rule("T203", "topic-type-mismatch")
def type_mismatch(ctx: CheckContext) -> Iterator[Diagnostic]:
    seen: set[object] = set()
    known: dict[str, bool] = {}

    def typed(t: str | None) -> bool:
        """A type whose package is known: ``gm/msg/Pose`` read from ``namespace gm = geometry_msgs;``
        code is an alias the extraction did not resolve, not a type of its own."""
        if not t:
            return False
        pkg = t.split("/", 1)[0]
        if pkg not in known:
            has = getattr(ctx.packages, "has_package", None)
            known[pkg] = has is None or bool(has(pkg))
        return known[pkg]

    for g in graphs(ctx):
        by_topic: dict[str, list[Endpoint]] = {}  # typed publishers and subscribers, in endpoint order
        for e in g.endpoints:
            if e.resolved and typed(e.type) and e.kind in ("publisher", "subscriber"):
                by_topic.setdefault(e.resolved, []).append(e)
        for topic in g.topics():
            eps = by_topic.get(topic, [])
            types = sorted({e.type for e in eps if e.type})
            if len(types) < 2:
                continue
            pubs = [e for e in eps if e.kind == "publisher"]
            for e in eps:
                if e.kind != "subscriber" or all(p.type == e.type for p in pubs):
                    continue
                node = g.node(e.node)
                if (node.span, topic) in seen:
                    continue
                seen.add((node.span, topic))
                pub = next(p for p in pubs if p.type != e.type)
                pnode = g.node(pub.node)
                yield Diagnostic(
                    "T203", node.span,
                    f'{where(node)} subscribes to "{topic}" as "{e.type}" but {where(pnode)} publishes "{pub.type}"',
                    help="make both ends use the same message type, or remap one of them",
                    related=(Related(pnode.span, f'publishes "{pub.type}" here'),), key=topic)


@rule("T204", "duplicate-service-server")
def duplicate_service(ctx: CheckContext) -> Iterator[Diagnostic]:
    seen: set[object] = set()
    for g in graphs(ctx):
        for kind in ("service", "action_server"):
            first: dict[str, str] = {}
            for e in g.of_kind(kind):
                if e.resolved is None or (kind == "service" and e.written in _LIFECYCLE_SERVICES):
                    continue  # (every lifecycle node serves these: two only meet under one name)
                if g.node(e.node).active is not True:
                    continue  # as N101: a condition that cannot be evaluated often excludes the other
                if e.resolved not in first:
                    first[e.resolved] = e.node
                    continue
                if first[e.resolved] == e.node:
                    continue
                node, prev = g.node(e.node), g.node(first[e.resolved])
                if (node.span, e.resolved) in seen:
                    continue
                seen.add((node.span, e.resolved))
                what = "service" if kind == "service" else "action"
                yield Diagnostic("T204", node.span,
                                 f'{where(node)} and {where(prev)} both serve {what} "{e.resolved}"',
                                 help="only one server per name: rename or namespace one of them",
                                 related=(Related(prev.span, "the other server"),), key=e.resolved)
