"""The node/topic graph of one resolved launch, with rcl's naming and remapping rules.

Each interface name a node's code uses is expanded against the node's namespace (``~``, ``{node}``,
relative names) and then rewritten by the node's remap rules in rcl order, first match wins
(rcl ``rcl_remap_first_match``; the rule's own names are expanded the same way). networkx is the
storage; rules use the typed queries below and never read networkx dicts.
"""
from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any, Literal

from physai_lint.interfaces.arguments import ARGUMENT_DECIDED, from_arguments
from physai_lint.interfaces.model import LIFECYCLE_ENDPOINTS, with_lifecycle_endpoints
from physai_lint.resolve.model import EffRemap, LaunchResult, NodeInstance
from physai_lint.resolve.names import expand_topic_name, name_rejected

if TYPE_CHECKING:
    from physai_lint.model.span import Span

EndpointKind = Literal["publisher", "subscriber", "service", "client", "action_server", "action_client"]
KINDS: tuple[EndpointKind, ...] = ("publisher", "subscriber", "service", "client", "action_server",
                                   "action_client")
_ATTR = {"publisher": "publishers", "subscriber": "subscribers", "service": "services",
         "client": "clients", "action_server": "action_servers", "action_client": "action_clients"}


@dataclass(frozen=True)
class Endpoint:
    node: str  # node id
    kind: EndpointKind
    written: str  # the name as the code writes it
    expanded: str | None  # before remapping
    resolved: str | None  # after remapping; None when unknown
    type: str | None
    remap: int | None  # index into node.remaps of the rule that applied
    when: tuple[tuple[str, Any], ...] = ()  # parameter values it exists under (interfaces Endpoint.when)
    where: Span | None = None  # the launch file's text that makes it (a bridge's argument)


@dataclass
class SystemGraph:
    launch: LaunchResult
    endpoints: list[Endpoint] = field(default_factory=list)
    known: set[str] = field(default_factory=set)  # node ids whose interface is known
    # node ids launch refuses (an invalid name or namespace), and their endpoints: such a node
    # never runs and connects to nothing; only the names its code uses are checked (N104)
    rejected: set[str] = field(default_factory=set)
    rejected_endpoints: list[Endpoint] = field(default_factory=list)
    # a lifecycle node whose name is unknown: its own endpoints (``~/transition_event``...) are
    # left out rather than unresolved, which would hide every dangling topic of the launch
    unnamed_lifecycle: bool = False
    # (node id, kind, type) of the endpoints nodes make under names not known statically
    unnamed: list[tuple[str, EndpointKind, str | None]] = field(default_factory=list)
    nx: Any = None
    _by_node: Any = field(default=None, init=False, repr=False, compare=False)
    _nodes: Any = field(default=None, init=False, repr=False, compare=False)

    # ---- queries --------------------------------------------------------------------------------
    # The rules ask these once per node and per remap: indexes built on first use (and again if
    # endpoints were added since) instead of a scan of every endpoint per question.
    def _index(self) -> dict[str, list[Endpoint]]:
        cached = self._by_node
        if cached is not None and cached[0] == len(self.endpoints):
            return cached[1]  # type: ignore[no-any-return]
        by_node: dict[str, list[Endpoint]] = {}
        for e in self.endpoints:
            by_node.setdefault(e.node, []).append(e)
        self._by_node = (len(self.endpoints), by_node)
        return by_node

    def node(self, node_id: str) -> NodeInstance:
        nodes = self._nodes
        if nodes is None or nodes[0] != len(self.launch.nodes):
            table: dict[str, NodeInstance] = {}
            for n in self.launch.nodes:
                table.setdefault(n.id, n)  # the first node with the id, as a scan finds it
            nodes = self._nodes = (len(self.launch.nodes), table)
        try:
            return nodes[1][node_id]  # type: ignore[no-any-return]
        except KeyError:
            raise KeyError(node_id) from None

    def of_kind(self, kind: EndpointKind, name: str | None = None) -> list[Endpoint]:
        return [e for e in self.endpoints if e.kind == kind and (name is None or e.resolved == name)]

    def topics(self) -> list[str]:
        return sorted({e.resolved for e in self.endpoints
                       if e.resolved and e.kind in ("publisher", "subscriber")})

    def endpoints_of(self, node_id: str) -> list[Endpoint]:
        return list(self._index().get(node_id, ()))

    def remap_used(self, node_id: str, index: int) -> bool:
        return any(e.remap == index for e in self._index().get(node_id, ()))

    def has_unknown_endpoints(self) -> bool:
        """True when some active node's interface is unknown, a name could not be resolved, or the
        launch has a part that cannot be known statically (an include outside the workspace, an
        action the evaluator could not follow), which may start any node."""
        if self.launch.opaque:
            return True
        active = [n for n in self.launch.nodes if n.active is not False and n.kind != "process"]
        return any(n.id not in self.known for n in active) or any(e.resolved is None for e in self.endpoints)


def _expand(name: str | None, node: NodeInstance) -> str | None:
    if name is None:
        return None
    return expand_topic_name(name, node.name, node.namespace)


def apply_remaps(name: str, node: NodeInstance) -> tuple[str | None, int | None]:
    """(remapped name, index of the matching rule) — rcl first match; unknown rules make it unknown."""
    for i, rule in enumerate(node.remaps):
        if rule.node_prefix is not None and rule.node_prefix != node.name:
            if node.name is None:
                return None, None
            continue
        src = _expand(rule.src, node) if rule.src is not None else None
        if src is None:
            if rule.src is None or node.namespace is None:
                return None, None  # an unknown rule might match: unknown result
            continue
        if src == name:
            dst = _expand(rule.dst, node) if rule.dst is not None else None
            return dst, i
    return name, None


def remap_target(rule: EffRemap, node: NodeInstance) -> tuple[str | None, str | None]:
    return _expand(rule.src, node), _expand(rule.dst, node)


def build_graph(launch: LaunchResult, interfaces: Any, include_inactive: bool = False) -> SystemGraph:
    g = SystemGraph(launch)
    for node in launch.nodes:
        if node.kind == "process" or (node.active is False and not include_inactive):
            continue
        if name_rejected(node.name, node.namespace):
            # launch raises on it (N102/N103): it never runs, so it connects to nothing; its
            # endpoints stay for the rules about the names its code uses (N104)
            g.rejected.add(node.id)
        iface = interfaces.get(node.package, node.executable) if interfaces is not None else None
        decided = (node.package, node.executable) in ARGUMENT_DECIDED
        if decided:
            iface = from_arguments(iface, node)  # the Gazebo bridges: their topics are arguments
        if iface is None:
            continue
        if node.kind == "lifecycle_node" or getattr(iface, "lifecycle", False):
            iface = _as_lifecycle(iface)  # launched as one, or its code makes one
        g.known.add(node.id)
        for kind_attr, type_ in getattr(iface, "unnamed", None) or ():
            if kind_attr in _KIND_OF:
                g.unnamed.append((node.id, _KIND_OF[kind_attr], type_))
        for kind in KINDS:
            for ep in getattr(iface, _ATTR[kind], None) or ():
                name = getattr(ep, "name", None)
                if not isinstance(name, str):
                    continue
                expanded = _expand(name, node)
                if expanded is None and (_ATTR[kind], name) in _LIFECYCLE_KEYS:
                    g.unnamed_lifecycle = True
                    continue
                resolved, idx = apply_remaps(expanded, node) if expanded else (None, None)
                (g.rejected_endpoints if node.id in g.rejected else g.endpoints).append(Endpoint(
                    node.id, kind, name, expanded, resolved, getattr(ep, "type", None), idx,
                    getattr(ep, "when", ()), getattr(ep, "span", None) if decided else None))
    return g


_KIND_OF = {attr: kind for kind, attr in _ATTR.items()}
_LIFECYCLE_KEYS = frozenset((kind, name) for kind, name, _ in LIFECYCLE_ENDPOINTS)


def _as_lifecycle(iface: Any) -> Any:
    """A copy of ``iface`` with the endpoints every lifecycle node has (the code may not show
    them: a class derived from a project's own lifecycle base, or no source found)."""
    return with_lifecycle_endpoints(iface)


def to_networkx(g: SystemGraph) -> Any:
    """A networkx DiGraph: ``n:<id>`` node vertices, ``t:<name>`` topic vertices (pub n->t, sub t->n)."""
    import networkx as nx  # type: ignore[import-untyped]

    dg = nx.DiGraph()
    for n in g.launch.nodes:
        if n.kind != "process":
            dg.add_node(f"n:{n.id}", kind="node")
    for e in g.endpoints:
        if e.resolved is None:
            continue
        t = f"t:{e.resolved}"
        dg.add_node(t, kind="topic")
        if e.kind in ("publisher", "service", "action_server"):
            dg.add_edge(f"n:{e.node}", t, kind=e.kind)
        else:
            dg.add_edge(t, f"n:{e.node}", kind=e.kind)
    return dg


def similar(name: str, candidates: Iterable[str], cutoff: float = 0.6) -> list[str]:
    from physai_lint.closematch import close_matches

    pool = sorted(set(candidates) - {name})
    close = list(close_matches(name, tuple(pool), 3, cutoff))
    base = name.rsplit("/", 1)[-1]
    by_base = [c for c in pool if c.rsplit("/", 1)[-1] == base and c not in close]
    return (close + by_base)[:3]


def span_for(node: NodeInstance, field_name: str) -> Span:
    return node.spans.get(field_name, node.span)
