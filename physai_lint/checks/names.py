"""Names and namespaces: N101 duplicate-node-name, N102 invalid-node-name, N103 invalid-namespace,
N104 invalid-topic-name, N105 invalid-remap-name, N106 name-style, N107 duplicate-component-name."""
from __future__ import annotations

import re
from collections.abc import Iterator
from typing import Any

from physai_lint.checks._util import all_nodes, line_ref, relpath, switched_off_by
from physai_lint.checks.base import CheckContext, rule
from physai_lint.checks.topics import graphs
from physai_lint.interfaces.naming import default_named, name_note
from physai_lint.model.findings import Diagnostic, Related
from physai_lint.resolve import names
from physai_lint.resolve.model import LaunchResult, NodeInstance
from physai_lint.resolve.nodes import rule_problem


@rule("N101", "duplicate-node-name")
def duplicate_node_name(ctx: CheckContext) -> Iterator[Diagnostic]:
    seen: set[object] = set()
    for launch in ctx.launches:
        first: dict[str, list[NodeInstance]] = {}
        exits: _Edges | None = None
        # the second run of one action object is S104's (launch raises, no second node starts);
        # what a handler whose target never runs would start never starts
        not_started = {again for _, again, _ in launch.repeated} | set(launch.unstartable)
        for node in launch.nodes:
            # Only nodes certainly started under the analysed arguments: a condition that cannot be
            # evaluated (an unknown PythonExpression, say) often excludes the other node.
            if node.kind == "process" or node.active is not True or not _named(node) or node.id in not_started:
                continue
            fqn = node.fqn or _anon_fqn(node)
            if not fqn:
                continue
            earlier = first.setdefault(fqn, [])
            # Two components of one container are N107's; a component and a process, or
            # components of two containers, are two nodes of one name in the graph.
            others = [p for p in earlier if not _same_container(p, node)]
            earlier.append(node)
            if not others:
                continue
            exits = exits or _Edges(launch)
            # A node started again once the other exited (OnProcessExit: the respawn pattern)
            # never runs beside it, unless launch restarts that one itself (respawn=).
            prev = next((p for p in others if not _restarted_after(exits, p, node)
                         and not _restarted_after(exits, node, p)), None)
            if prev is None:
                continue
            span = node.spans.get("name", node.span)
            if span in seen:
                continue
            seen.add(span)
            p = prev
            if node.fqn is None:  # both named $(anon ID)
                first_at = p.spans.get("name", p.span)
                shown = fqn.split("\0", 1)[0]
                ident = shown.rsplit("$(anon ", 1)[1][:-1]
                yield Diagnostic(
                    "N101", span,
                    f'node "{shown}" is launched twice (also at {line_ref(first_at, span)}): AnonName makes '
                    f'the name for "{ident}" once and gives it to every $(anon {ident}) after it, so both '
                    "get the same generated name; services, parameters and topics of the two collide",
                    help=f"give each node its own id ($(anon {ident}_2)) or namespace",
                    related=(Related(first_at, "first launched here"),),
                    key=shown)
                continue
            if "composable_node" in (node.kind, p.kind):
                yield _component_twice(node, p, span)
                continue
            sites = _include_sites(launch, node) if p.span == node.span else []
            if len(sites) > 1:  # one line launched twice because its file is included twice
                yield Diagnostic(
                    "N101", span,
                    f'node "{node.fqn}" is launched twice: {relpath(node.file)} is included '
                    f"{len(sites)} times{_include_cause(node)}; services, parameters and topics of "
                    f"the two collide{name_note((node,))}",
                    help="include the file once, or give each include its own namespace "
                         "(PushRosNamespace in a GroupAction around it)",
                    related=tuple(Related(s, "included here") for s in sites[:5]),
                    key=node.fqn)
                continue
            if p.span == node.span:  # one action run again: a loop, or a function called twice
                yield _repeated(launch, node, sites)
                continue
            first_at = p.spans.get("name", p.span)
            yield Diagnostic(
                "N101", span,
                f'node "{node.fqn}" is launched twice (also at {line_ref(first_at, span)}); '
                f"services, parameters and topics of the two collide{name_note((node, p))}",
                help="give each node its own name or namespace (PushRosNamespace / namespace=)",
                related=(Related(first_at, "first launched here"),),
                key=node.fqn)


def _include_cause(node: NodeInstance) -> str:
    """Why one node of a file included several times ends with one name each time: its absolute
    namespace (a pushed namespace does not apply to it), the launch configurations its name reads
    (an include's arguments stay set for what follows it: launch's IncludeLaunchDescription pushes
    no scope, and a default applies only to an unset argument), or else the same namespace."""
    from physai_lint.model.values import LaunchConfig, literal_of

    action = node.action
    ns_value = getattr(action, "namespace", None)
    ns = literal_of(ns_value) if ns_value else None
    if ns and ns.startswith("/"):
        return (f', and its namespace "{ns}" is absolute, so the namespace each include pushes does '
                "not apply to it")
    configs = sorted({literal_of(p.name) or "?" for value in (ns_value, getattr(action, "name", None))
                      for p in value or () if isinstance(p, LaunchConfig)})
    if configs:
        listed = ", ".join(f'"{c}"' for c in configs)
        return (f" and its name or namespace reads the launch configuration{'s' if len(configs) > 1 else ''} {listed} "
                "with the same value each time (an include's arguments stay set after it, and a "
                "default applies only to an unset argument: pass the argument to every include)")
    return " in the same namespace"


def _anon_fqn(node: NodeInstance) -> str | None:
    """The name of a node named ``$(anon ID)``, as written (``/ns/$(anon rviz)``): nodes with the
    same one get the same generated name (``NodeInstance.anon``)."""
    if node.anon is None or not node.namespace:
        return None
    return names.join_fqn(node.namespace, f"$(anon {node.anon.rsplit('#', 1)[0]})") + "\0" + node.anon


def _same_container(a: NodeInstance, b: NodeInstance) -> bool:
    return a.kind == b.kind == "composable_node" and a.container == b.container


def _where(node: NodeInstance) -> str:
    if node.kind == "composable_node":
        return f'a component of container "{node.container}"' if node.container else "a component"
    return "a container" if node.kind == "container" else "a node"


def _component_twice(node: NodeInstance, p: NodeInstance, span: Any) -> Diagnostic:
    """N101 when one of the two is a component: two containers load one name, or a component
    is named like a node (its own container included)."""
    hint = ""
    cont_ns = (node.container or "").rpartition("/")[0] or "/"
    if node.kind == "composable_node" and node.namespace == "/" and node.container and cont_ns != "/":
        hint = (" (a component does not take its container's namespace: give it "
                "namespace= or push one around the container)")
    first_at = p.spans.get("name", p.span)
    return Diagnostic(
        "N101", span,
        f'node "{node.fqn}" is {_where(node)} here and {_where(p)} at {line_ref(first_at, span)}; '
        f"services, parameters and topics of the two collide{hint}{name_note((node, p))}",
        help="give each node its own name or namespace (namespace= on the composable node, or "
             "PushRosNamespace around it)",
        related=(Related(first_at, "first started here"),),
        key=node.fqn)


def _repeated(launch: LaunchResult, node: NodeInstance, sites: list[Any]) -> Diagnostic:
    """N101 for a node that one action launches several times (its own line, not another's)."""
    times = sum(1 for n in launch.nodes if n.span == node.span and n.fqn == node.fqn
                and n.active is True and n.kind != "composable_node")
    span = node.spans.get("name", node.span)
    count = "twice" if times == 2 else f"{times} times"
    runs = sum(1 for i in launch.includes if sites and i.span == sites[0] and i.active is not False)
    if runs > 1:  # its file is included again and again by one include
        return Diagnostic(
            "N101", span,
            f'node "{node.fqn}" is launched {count}: {relpath(node.file)} is included '
            f"{runs} times through one include (in a loop or a function called again) in the same "
            f"namespace; services, parameters and topics of the copies collide{name_note((node,))}",
            help="give each inclusion its own namespace (PushRosNamespace in a GroupAction around "
                 "the include), or a name built from the loop's value",
            related=(Related(sites[0], "included here"),),
            key=node.fqn)
    return Diagnostic(
        "N101", span,
        f'node "{node.fqn}" is launched {count} by this one action (in a loop or a function '
        f"called again); services, parameters and topics of the copies collide{name_note((node,))}",
        help=f"build the name or namespace from the loop's value (name=f'{node.name}_{{i}}' or "
             "namespace=...)",
        key=node.fqn)


def _named(node: NodeInstance) -> bool:
    """The name is known: launch gives it, or it is the one its code gives (not a computed one)."""
    return node.name_explicit or default_named(node)


def _include_sites(launch: LaunchResult, node: NodeInstance) -> list[Any]:
    """Where the file that launches ``node`` is included (active includes, in file order)."""
    return sorted({i.span for i in launch.includes if i.active is not False
                   and node.file in (i.target, i.target_source)}, key=lambda s: (s.file, s.line, s.col))


def _restarted_after(edges: _Edges, first: NodeInstance, again: NodeInstance) -> bool:
    return "respawn" not in first.spans and edges.after_exit(first.id, again.id)


class _Edges:
    """A launch's startup edges: what starts after each id, and what only once it exited."""

    def __init__(self, launch: LaunchResult) -> None:
        self.after: dict[str, list[str]] = {}
        self.on_exit: dict[str, list[str]] = {}
        for e in launch.edges:
            self.after.setdefault(e.before, []).append(e.after)
            if e.reason == "on_process_exit":
                self.on_exit.setdefault(e.before, []).append(e.after)

    def after_exit(self, before: str, after: str) -> bool:
        """Whether ``after`` starts only once ``before`` exited: reached from ``before`` by a
        path whose first edge is an OnProcessExit of ``before``."""
        todo, seen = list(self.on_exit.get(before, ())), set()
        while todo:
            x = todo.pop()
            if x == after:
                return True
            if x not in seen:
                seen.add(x)
                todo.extend(self.after.get(x, ()))
        return False


@rule("N107", "duplicate-component-name")
def duplicate_component(ctx: CheckContext) -> Iterator[Diagnostic]:
    seen: set[object] = set()
    for launch in ctx.launches:
        first: dict[tuple[str | None, str], list[NodeInstance]] = {}
        for node in launch.nodes:
            if node.kind != "composable_node" or node.active is not True or not node.fqn or not _named(node):
                continue
            key = (node.container, node.fqn)
            earlier = first.setdefault(key, [])
            prev = earlier[0] if earlier else None
            earlier.append(node)
            if prev is None or node.span in seen:
                continue
            seen.add(node.span)
            yield Diagnostic(
                "N107", node.span,
                f'component "{node.fqn}" is loaded twice into container "{node.container}"'
                f"{name_note((node, prev))}",
                help="give each component a distinct name or namespace",
                related=(Related(prev.span, "first loaded here"),),
                key=node.fqn)


@rule("N102", "invalid-node-name")
def invalid_node_name(ctx: CheckContext) -> Iterator[Diagnostic]:
    seen: set[object] = set()
    for _, node in all_nodes(ctx):
        if node.name is None or not node.name_explicit or node.kind == "process":
            continue
        reason = names.validate_node_name(node.name) or _passed_problem(node.name, "__node")
        span = node.spans.get("name", node.span)
        if reason and span not in seen:
            seen.add(span)
            yield Diagnostic("N102", span, f'node name "{node.name}" is invalid: {reason}',
                             help="use only letters, digits and underscores, not starting with a digit; "
                                  "put namespaces in namespace=",
                             key=node.name)


@rule("N103", "invalid-namespace")
def invalid_namespace(ctx: CheckContext) -> Iterator[Diagnostic]:
    seen: set[object] = set()
    bad_pushes: set[str] = set()
    for launch in ctx.launches:
        for span, raw, result in launch.pushed_namespaces:
            if result is None:
                continue
            reason = names.validate_namespace(result) or _passed_problem(result, "__ns")
            if reason:
                bad_pushes.add(result)
            if reason and span not in seen:
                seen.add(span)
                yield Diagnostic(
                    "N103", span,
                    f'pushed namespace "{raw}" gives "{result}", which is invalid: {reason}',
                    help='namespaces use letters, digits, "_" and "/", and no token starts with a digit',
                    key=result)
    for _, node in all_nodes(ctx):
        if node.namespace is None or node.kind == "process":
            continue
        if any(node.namespace == b or node.namespace.startswith(b + "/") for b in bad_pushes):
            continue  # already reported where the namespace was pushed
        ns_span = node.spans.get("namespace")
        if ns_span is None or ns_span in seen:
            continue
        reason = names.validate_namespace(node.namespace) or _passed_problem(node.namespace, "__ns")
        if reason:
            seen.add(ns_span)
            yield Diagnostic("N103", ns_span, f'namespace "{node.namespace}" is invalid: {reason}',
                             help='namespaces use letters, digits, "_" and "/", and no token starts with a digit',
                             key=node.namespace)


def _remap_problem(name: str) -> str | None:
    if name.startswith("/"):
        return names.validate_full_topic_name(name) or (
            None if len(name) <= names.TOPIC_MAX else f"topic name is longer than {names.TOPIC_MAX}") or \
            _rule_problem(name)
    return names.validate_topic_name(name) or _rule_problem(name)


def _rule_problem(name: str) -> str | None:
    """A name rcl accepts but cannot read in a ``-r`` rule, which launch gives it in."""
    reason = names.rule_lex_problem(name)
    return None if reason is None else f"{reason}: rcl exits at start-up with \"Couldn't parse remap rule\""


def _passed_problem(name: str, what: str) -> str | None:
    """A node name or namespace rmw accepts, which launch_ros passes to rcl as ``-r __node:=``/
    ``-r __ns:=`` (a component's, in its load request, which rclcpp makes the same rules of)."""
    reason = names.rule_lex_problem(name)
    return None if reason is None else (
        f'launch passes it to rcl as the rule "{what}:={name}", and {reason}; the node exits at '
        "start-up with \"Couldn't parse remap rule\"")


@rule("N105", "invalid-remap-name")
def invalid_remap(ctx: CheckContext) -> Iterator[Diagnostic]:
    seen: set[object] = set()
    for _, node in all_nodes(ctx):
        for rule_ in node.remaps:
            if rule_.src in ("__ns", "__node", "__name") and rule_.dst is not None:
                reason = rule_problem(rule_.src, rule_.dst)
                if reason and (rule_.span, "to") not in seen:
                    seen.add((rule_.span, "to"))
                    what = "namespace" if rule_.src == "__ns" else "node name"
                    yield Diagnostic(
                        "N105", rule_.span,
                        f'remap rule "{rule_.src}:={rule_.dst}" is invalid: {reason}; rcl cannot '
                        "parse it, so the node fails to start",
                        help=f"give a valid {what}"
                             + (' starting with "/"' if rule_.src == "__ns" else "")
                             + " (or use namespace= / name=, which launch makes valid)",
                        key=f"to:{rule_.dst}")
                continue
            for side, value in (("from", rule_.src), ("to", rule_.dst)):
                if value is None or value.startswith("__") or (rule_.span, side) in seen:
                    continue
                if switched_off_by(node, value):
                    continue
                reason = _remap_problem(value)
                if reason:
                    seen.add((rule_.span, side))
                    yield Diagnostic(
                        "N105", rule_.span,
                        f'remap {side} name "{value}" is invalid: {reason}',
                        help='topic names use letters, digits, "_", "/", a leading "~/" and {node}; '
                             "no token may start with a digit",
                        key=f"{side}:{value}")


@rule("N106", "name-style")
def name_style(ctx: CheckContext) -> Iterator[Diagnostic]:
    # "double-underscore" is read no more: a repeated "_" in these names does not parse in the -r
    # rules launch gives them in (N102, N103, N105)
    trailing = bool(ctx.option("N106", "trailing-underscore", True))
    upper = bool(ctx.option("N106", "uppercase", False))
    seen: set[object] = set()
    for _, node in all_nodes(ctx):
        named: list[tuple[str, str | None, Any]] = [
            ("node name", node.name if node.name_explicit else None, node.spans.get("name")),
            ("namespace", node.namespace if node.namespace_explicit else None, node.spans.get("namespace"))]
        for r in node.remaps:
            if r.origin == "node":
                named += [("remapped name", r.src, r.span), ("remap target", r.dst, r.span)]
        for what, value, span in named:
            if not value or span is None or (span, value) in seen or value.startswith("__"):
                continue
            if (what.startswith("remap") and _remap_problem(value)) or names.rule_lex_problem(value):
                continue  # invalid: N105 reports it, or N102/N103 (a repeated "_" does not parse in a rule)
            tokens = [t for t in value.lstrip("~").split("/") if t and t not in _SPECIAL]
            problems = []
            if trailing and any(t.endswith("_") for t in tokens):
                problems.append('a part ending in "_"')
            if upper and any(c.isupper() for t in tokens for c in t):
                problems.append("capital letters")
            if problems:
                seen.add((span, value))
                yield Diagnostic("N106", span,
                                 f'{what} "{value}" has {" and ".join(problems)} (rcl accepts it, but the '
                                 "ROS 2 naming design rules it out)",
                                 help="use lowercase words joined by single underscores", key=value)


# rcl's special names, kept as they are by N106
_SPECIAL = frozenset({"__node", "__ns", "__name"})


_KNOWN_SUBST = ("node", "ns", "namespace")
_SUBSTITUTION = re.compile(r"\{([^{}]*)\}")
_EP_ATTR = {"publisher": "publishers", "subscriber": "subscribers", "service": "services",
            "client": "clients", "action_server": "action_servers", "action_client": "action_clients"}
_EP_WORD = {"publisher": "publishes", "subscriber": "subscribes to", "service": "serves",
            "client": "calls the service", "action_server": "serves the action",
            "action_client": "calls the action"}


def _written_problem(name: str) -> str | None:
    """rcl_validate_topic_name, then rcl_expand_topic_name's unknown-substitution error."""
    reason = names.validate_topic_name(name)
    if reason:
        return reason
    for sub in _SUBSTITUTION.findall(name):
        if sub not in _KNOWN_SUBST:
            return f'unknown substitution "{{{sub}}}" (only {{node}}, {{ns}} and {{namespace}} exist)'
    return None


def _final_problem(name: str) -> str | None:
    """rmw_validate_full_topic_name on the expanded, remapped name (length included)."""
    reason = names.validate_full_topic_name(name)
    if reason:
        return reason
    if len(name) > names.TOPIC_MAX:
        return f"it is {len(name)} characters long (at most {names.TOPIC_MAX})"
    return None


@rule("N104", "invalid-topic-name")
def invalid_topic_name(ctx: CheckContext) -> Iterator[Diagnostic]:
    seen: set[object] = set()
    for g in graphs(ctx):
        for e in (*g.endpoints, *g.rejected_endpoints):
            node = g.node(e.node)
            reason = _written_problem(e.written)
            written_bad = reason is not None
            shown = f'"{e.written}"'
            if reason is None and e.resolved is not None:
                if node.namespace is None or names.validate_namespace(node.namespace) or (
                        node.name is not None and names.validate_node_name(node.name)):
                    continue  # an invalid namespace or node name is N103/N102's finding, not each topic's
                if e.remap is not None and _remap_problem(node.remaps[e.remap].dst or "") is not None:
                    continue  # the remap's replacement is invalid itself: N105 reports it
                reason = _final_problem(e.resolved)
                if reason and e.resolved != e.written:
                    how = "expanded" if e.remap is None else "expanded and remapped"
                    shown = f'"{e.written}" ({how} to "{e.resolved}")'
            if reason is None or (node.span, e.kind, e.written) in seen:
                continue
            seen.add((node.span, e.kind, e.written))
            related: tuple[Related, ...] = ()
            iface = ctx.interfaces.get(node.package, node.executable)
            for ep in (getattr(iface, _EP_ATTR[e.kind], None) or ()) if iface is not None else ():
                if ep.name == e.written and ep.span is not None:
                    related = (Related(ep.span, "the name is written here"),)
                    break
            yield Diagnostic(
                "N104", node.span,
                f"{node.fqn or node.executable} {_EP_WORD[e.kind]} {shown}, which is not a valid name: "
                f"{reason}",
                help=('topic and service names use letters, digits, "_" and "/", may start with "~/" and '
                      "use {node}/{ns}; no token may start with a digit. Rename it in the node's code "
                      "(rcl checks the name as written before it applies remap rules)") if written_bad else
                     "shorten the namespace or remap the name to a valid one",
                related=related, key=f"{e.kind}:{e.written}")
