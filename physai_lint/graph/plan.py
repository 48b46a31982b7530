"""The startup plan of one resolved launch: who starts when, waiting for whom, and why.

Vertices are the active (not ``False``) nodes, processes and components of a ``LaunchResult``.

Hard edges (launch enforces them, or the system cannot come up without them):

- ``LaunchResult.edges``: event handlers (``OnProcessStart``/``OnProcessExit``/
  ``OnExecutionComplete``/``OnStateTransition``: the handler's actions after the target) and
  containers before their components;
- lifecycle managers after the nodes they manage (``node_names`` expanded against the manager's
  namespace), and ``node_names[i]`` before ``node_names[i + 1]`` ("lifecycle order": the manager
  configures and activates them in that order).

Soft edges: a subscriber after the publishers of the topics it subscribes to (from the
``SystemGraph``). They are reported, not enforced: launch starts both at once and ROS 2 delivers
messages whenever the publisher appears, and robots are full of topic loops (odometry -> controller
-> cmd_vel -> base -> odometry), so ordering by topics would invent a long chain of stages that
does not exist. A soft edge whose publisher starts in a later stage than its subscriber is marked
``against`` (the subscriber waits for data at start-up).

Stages are the topological generations of the hard edges, hard cycles condensed into one vertex
(so a cyclic plan still has stages). ``cycles`` lists the simple cycles of the hard edges
(bounded); a cycle is ``deadlock`` when none of its members can ever start: every member only
runs from event handlers whose targets only run from handlers of the cycle (the resolver walks a
handler's actions as if the event came, so it records such actions as started). A cycle with a
member that does start is launch executing one action twice, not a deadlock.

``critical_path``: the chain of hard edges with the largest total timer delay
(``LaunchResult.delays``, relative to the event that started the timer).
"""
from __future__ import annotations

import itertools
import re
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

from physai_lint.resolve.model import LIFECYCLE_MANAGERS
from physai_lint.resolve.roots import nodes_on_cycles

if TYPE_CHECKING:
    from physai_lint.graph.system import SystemGraph
    from physai_lint.model.span import Span
    from physai_lint.resolve.model import LaunchResult, NodeInstance

MAX_CYCLES = 50
MANAGERS = LIFECYCLE_MANAGERS
HANDLER_REASONS = ("on_process_start", "on_process_exit", "on_execution_complete",
                   "on_state_transition")
IGNORED_TOPICS = ("/rosout", "/parameter_events")


@dataclass(frozen=True)
class PlanVertex:
    id: str
    label: str  # unique within the plan: fqn, else executable (+ first argument / line)
    fqn: str | None
    kind: str
    package: str | None
    executable: str | None
    file: str
    line: int
    active: bool | None
    delay: float | None  # timer delay after its trigger (0 when none); None when unknown
    stage: int = 0  # 1-based


@dataclass(frozen=True)
class PlanEdge:
    before: str
    after: str
    reason: str  # "on_process_start", "on_process_exit", ..., "container", "lifecycle manager",
    #              "lifecycle order", "topic /x"
    soft: bool
    delay: float | None = None
    span: Span | None = None


@dataclass(frozen=True)
class PlanCycle:
    nodes: tuple[str, ...]  # vertex ids in cycle order, first not repeated
    edges: tuple[PlanEdge, ...]  # nodes[i] -> nodes[i + 1], last back to nodes[0]
    deadlock: bool  # no member can ever start

    def text(self, labels: dict[str, str]) -> str:
        return " -> ".join(labels.get(n, n) for n in (*self.nodes, self.nodes[0]))


@dataclass
class Plan:
    entry: str
    vertices: dict[str, PlanVertex] = field(default_factory=dict)
    stages: list[list[str]] = field(default_factory=list)
    edges: list[PlanEdge] = field(default_factory=list)
    cycles: list[PlanCycle] = field(default_factory=list)
    cycles_truncated: bool = False
    critical_path: list[str] = field(default_factory=list)
    critical_delay: float = 0.0
    never_started: list[tuple[Span, str]] = field(default_factory=list)
    never_starts: set[str] = field(default_factory=set)  # their handlers wait on events that never come
    # parts of the launch the linter cannot know statically (an OpaqueFunction it cannot follow,
    # an include outside the workspace): they may start processes the plan does not show
    unknown: list[tuple[Span, str]] = field(default_factory=list)

    def never_order(self) -> list[str]:
        """The vertices that never start (they are in no stage), in plan order."""
        return sorted(self.never_starts, key=lambda v: vertex_key(self.vertices[v]))

    @property
    def labels(self) -> dict[str, str]:
        return {v.id: v.label for v in self.vertices.values()}

    def waits_for(self, vid: str) -> list[PlanEdge]:
        return [e for e in self.edges if e.after == vid]


def _natural(s: str) -> tuple[Any, ...]:
    return tuple(int(p) if p.isdigit() else p for p in re.split(r"(\d+)", s))


def vertex_key(v: PlanVertex) -> tuple[Any, ...]:
    return (v.fqn is None, _natural(v.fqn or v.label), _natural(v.id))


# Options of controller_manager's spawner scripts that take a value (controller_manager/spawner.py,
# unspawner.py, hardware_spawner.py, humble to rolling): the value is not a controller's name.
# --fallback_controllers takes every name up to the next option.
SPAWNER_VALUE_OPTIONS = frozenset({
    "-c", "--controller-manager", "-p", "--param-file", "-n", "--namespace", "-t", "--controller-type",
    "--controller-manager-timeout", "--switch-timeout", "--service-call-timeout", "--controller-ros-args"})
_SPAWNERS = frozenset({"spawner", "unspawner", "hardware_spawner", "spawner.py", "unspawner.py"})


def first_positional(args: tuple[str | None, ...], limit: int = 32, package: str | None = None,
                     executable: str | None = None) -> str | None:
    """The first positional argument before ``--ros-args`` (``spawner [arm_controller]``); a path
    is shortened to its file name, a long value cut to ``limit`` characters. For controller_manager's
    spawners, every controller name, without the options' values (``spawner [jsb, arm]``)."""
    spawner = package == "controller_manager" and executable in _SPAWNERS
    found: list[str] = []
    skip = nargs = False
    for a in args:
        if a is None or a == "--ros-args":
            break  # unknown, or ROS arguments (log levels, remaps) from here on
        if skip:
            skip = False
            continue
        if a.startswith("-"):
            if spawner:
                skip = "=" not in a and a in SPAWNER_VALUE_OPTIONS
                nargs = a == "--fallback_controllers"
            continue
        if a and not nargs:
            found.append(a.rstrip("/").rsplit("/", 1)[-1] or a)
            if not spawner:
                break
    text = ", ".join(found)
    if not text:
        return None
    return text if len(text) <= limit else text[:limit - 1] + "…"


def _labels(nodes: list[NodeInstance]) -> dict[str, str]:
    """Unique labels: the fqn, else the executable; duplicates get "(component)" when one of
    them is a composable node, then the first positional argument (``spawner [arm_controller]``),
    then the line."""
    base = {n.id: n.fqn or n.executable or ("process" if n.kind == "process" else "node") for n in nodes}

    def refine(labels: dict[str, str], how: Callable[[NodeInstance, str], str]) -> dict[str, str]:
        counts: dict[str, int] = {}
        for lbl in labels.values():
            counts[lbl] = counts.get(lbl, 0) + 1
        return {n.id: how(n, labels[n.id]) if counts[labels[n.id]] > 1 else labels[n.id] for n in nodes}

    out = refine(base, lambda n, lbl: f"{lbl} (component)" if n.kind == "composable_node" else lbl)
    out = refine(out, lambda n, lbl: f"{lbl} [{a}]" if (a := first_positional(
        n.arguments, package=n.package, executable=n.executable)) else lbl)
    out = refine(out, lambda n, lbl: f"{lbl} (line {n.span.line})")
    return refine(out, lambda n, lbl: f"{lbl} #{n.id}")


def _param_value(params: dict[str, Any], name: str) -> Any:
    p = params.get(name)
    if p is None:
        return None
    if getattr(p, "certain", True) is False:
        return None
    return getattr(p, "value", p)


def _node_names(mgr: NodeInstance, params: dict[str, Any]) -> Any:
    """``node_names`` of a manager. An unknown parameter source makes every parameter uncertain,
    but launch_ros applies the sources in order and the last write wins, so a value from a launch
    dict with no unknown source after it is known (nav2: ``[params_file, {'node_names': [...]}]``)."""
    value = _param_value(params, "node_names")
    if value is not None:
        return value
    p = params.get("node_names")
    if p is None or getattr(p, "value", None) is None or getattr(p, "origin", None) is None:
        return None
    from physai_lint.resolve.model import ResolvedParamDict, ResolvedParamFile

    last = None
    for i, src in enumerate(mgr.param_sources):
        if isinstance(src, ResolvedParamDict) and any(
                prm.name == "node_names" and prm.span == p.origin for prm in src.params):
            last = i
    if last is None:
        return None
    for src in mgr.param_sources[last + 1:]:
        if not (isinstance(src, ResolvedParamDict) or (isinstance(src, ResolvedParamFile)
                                                       and src.status == "missing")):
            return None  # a file or unknown source after it may set node_names again
        if isinstance(src, ResolvedParamDict) and any(prm.name == "node_names" for prm in src.params):
            return None
    return p.value


def _lifecycle_edges(nodes: list[NodeInstance], effective_params: Callable[[NodeInstance], dict[str, Any]]
                     ) -> list[PlanEdge]:
    from physai_lint.resolve.names import expand_topic_name

    by_fqn: dict[str, list[str]] = {}
    for n in nodes:
        if n.fqn:
            by_fqn.setdefault(n.fqn, []).append(n.id)
    out: list[PlanEdge] = []
    for mgr in nodes:
        if (mgr.package, mgr.executable) not in MANAGERS:
            continue
        try:
            names = _node_names(mgr, effective_params(mgr))
        except (KeyError, TypeError, ValueError, OSError):  # unknown parameters: no edges
            names = None
        if not isinstance(names, list):
            continue
        managed: list[list[str]] = []
        for name in names:
            target = expand_topic_name(str(name), mgr.name, mgr.namespace)
            ids = by_fqn.get(target or "", [])
            managed.append(ids)
            for mid in ids:
                if mid != mgr.id:
                    out.append(PlanEdge(mid, mgr.id, "lifecycle manager", False, None, mgr.span))
        for prev, nxt in itertools.pairwise(managed):
            for a in prev:
                for b in nxt:
                    if a != b:
                        out.append(PlanEdge(a, b, "lifecycle order", False, None, mgr.span))
    return out


def _container_edges(nodes: list[NodeInstance]) -> list[PlanEdge]:
    """Components after their container, also when loaded by name (``LoadComposableNodes``
    with ``target_container``) into a container started elsewhere in the launch."""
    by_fqn: dict[str, list[str]] = {}
    for n in nodes:
        if n.fqn and (n.kind == "container" or (n.executable or "").startswith("component_container")):
            by_fqn.setdefault(n.fqn, []).append(n.id)
    ids = {n.id for n in nodes}
    out = []
    for n in nodes:
        if n.kind != "composable_node":
            continue
        targets = [n.container_id] if n.container_id in ids else by_fqn.get(n.container or "", [])
        out += [PlanEdge(c, n.id, "container", False, None, n.span) for c in targets if c and c != n.id]
    return out


def _topic_edges(graph: SystemGraph | None, ids: set[str]) -> list[PlanEdge]:
    if graph is None:
        return []
    pubs: dict[str, set[str]] = {}
    subs: dict[str, set[str]] = {}
    for e in graph.endpoints:
        if e.resolved is None or e.resolved in IGNORED_TOPICS or e.node not in ids:
            continue
        if e.kind == "publisher":
            pubs.setdefault(e.resolved, set()).add(e.node)
        elif e.kind == "subscriber":
            subs.setdefault(e.resolved, set()).add(e.node)
    out = []
    for topic in sorted(subs):
        for p in sorted(pubs.get(topic, ()), key=_natural):
            for s in sorted(subs[topic], key=_natural):
                if p != s:
                    out.append(PlanEdge(p, s, f"topic {topic}", True))
    return out


def _startable(vertices: set[str], hard: list[PlanEdge], active: dict[str, bool | None],
               dead: frozenset[Any] = frozenset()) -> set[str]:
    """Vertices that can start: every handler trigger (edges grouped by handler span) has a
    startable target instance (OR within a trigger, AND across nested triggers). A handler of
    ``dead`` (the spans of handlers that never fire: ``LaunchResult.never_started``) starts nothing."""
    groups: dict[str, dict[Any, set[str]]] = {v: {} for v in vertices}
    for e in hard:
        if e.reason in HANDLER_REASONS and e.after in groups:
            befores = groups[e.after].setdefault((e.reason, e.span), set())
            if e.span not in dead:
                befores.add(e.before)
    ok: set[str] = set()
    changed = True
    while changed:
        changed = False
        for v in vertices:
            if v in ok or active.get(v) is False:
                continue
            if all(befores & ok for befores in groups[v].values()):
                ok.add(v)
                changed = True
    return ok


def _skeleton(launch: LaunchResult, effective_params: Callable[[NodeInstance], dict[str, Any]]
              ) -> tuple[Plan, set[str], list[PlanEdge], set[str]]:
    """The plan's vertices, ``never_starts``, the vertex ids, the hard edges (first reason per
    pair) and the startable vertices: everything before any graph work."""
    nodes = [n for n in launch.nodes if n.active is not False]
    labels = _labels(nodes)
    plan = Plan(launch.entry, never_started=list(launch.never_started),
                unknown=sorted(set(launch.opaque) - set(launch.inactive_opaque),  # those start nothing now
                               key=lambda o: (o[0].file, o[0].line, o[0].col, o[1])))
    for n in nodes:
        plan.vertices[n.id] = PlanVertex(
            n.id, labels[n.id], n.fqn, n.kind, n.package, n.executable, n.file, n.span.line,
            n.active, launch.delays.get(n.id, 0.0) if n.id in launch.delays else 0.0)
    ids = set(plan.vertices)

    hard: list[PlanEdge] = []
    seen: set[tuple[str, str, str]] = set()
    for se in launch.edges:
        if se.before in ids and se.after in ids and not se.soft and (se.before, se.after, se.reason) not in seen:
            seen.add((se.before, se.after, se.reason))
            hard.append(PlanEdge(se.before, se.after, se.reason, False, se.delay, se.span))
    for e in _container_edges(nodes) + _lifecycle_edges(nodes, effective_params):
        if (e.before, e.after, e.reason) not in seen and not any(
                (e.before, e.after) == (h.before, h.after) for h in hard):
            seen.add((e.before, e.after, e.reason))
            hard.append(e)
    # a handler whose every target is off under the analysed arguments never fires: what only it
    # starts never starts (the off targets are no vertices, but their edges still count here)
    off = {n.id for n in launch.nodes if n.active is False} - ids
    dead = [PlanEdge(se.before, se.after, se.reason, False, se.delay, se.span) for se in launch.edges
            if se.before in off and se.after in ids and not se.soft and se.reason in HANDLER_REASONS]
    startable = _startable(ids | off, hard + dead, {**dict.fromkeys(off, False), **{n.id: n.active for n in nodes},
                                                    **dict.fromkeys(launch.unstartable, False)},
                           frozenset(span for span, _ in launch.never_started))
    startable &= ids
    plan.never_starts = ids - startable
    # nodes only an action that never starts would start (a cycle through a TimerAction, a
    # GroupAction or a lifecycle node's transitions: LaunchResult.trigger_cycles)
    blocked = set(launch.blocked) & ids
    if blocked:
        plan.never_starts |= blocked
        startable -= blocked
        plan.never_started.extend((span, f"startup cycle {text}: {steps}")
                                  for span, text, steps, _, _ in launch.trigger_cycles)
    return plan, ids, hard, startable


def _cycles(plan: Plan, ids: set[str], hard: list[PlanEdge], startable: set[str], nx: Any) -> Any:
    """Fill ``plan.cycles`` (and ``cycles_truncated``); return the hard edges' networkx graph."""
    H = nx.DiGraph()
    H.add_nodes_from(sorted(ids, key=_natural))
    first_edge: dict[tuple[str, str], PlanEdge] = {}
    for e in hard:
        H.add_edge(e.before, e.after)
        first_edge.setdefault((e.before, e.after), e)

    found: list[PlanCycle] = []
    for cyc in nx.simple_cycles(H):
        if len(found) >= MAX_CYCLES:
            plan.cycles_truncated = True
            break
        # rotate so that it starts at its smallest member: deterministic text
        i = min(range(len(cyc)), key=lambda k: vertex_key(plan.vertices[cyc[k]]))
        cyc = cyc[i:] + cyc[:i]
        edges = tuple(first_edge[(cyc[k], cyc[(k + 1) % len(cyc)])] for k in range(len(cyc)))
        found.append(PlanCycle(tuple(cyc), edges, deadlock=not (set(cyc) & startable)))
    plan.cycles = sorted(found, key=lambda c: [vertex_key(plan.vertices[n]) for n in c.nodes])
    return H


def _has_cycle(hard: list[PlanEdge]) -> bool:
    """Do the hard edges close a cycle (a self-loop included)?"""
    succ: dict[str, set[str]] = {}
    for e in hard:
        succ.setdefault(e.before, set()).add(e.after)
    return bool(nodes_on_cycles(succ))


def startup_cycles(launch: LaunchResult,
                   effective_params: Callable[[NodeInstance], dict[str, Any]]) -> Plan:
    """What S101 reads of ``build_plan``: the vertices, ``never_starts`` and the cycles (stages,
    edges and the critical path are left empty). When the hard edges close no cycle there is none
    to list, and networkx (0.08-0.15 s to import, the costliest import of a run) is not needed."""
    plan, ids, hard, startable = _skeleton(launch, effective_params)
    if not _has_cycle(hard):
        return plan
    import networkx as nx  # type: ignore[import-untyped]

    _cycles(plan, ids, hard, startable, nx)
    return plan


def build_plan(launch: LaunchResult, graph: SystemGraph | None,
               effective_params: Callable[[NodeInstance], dict[str, Any]]) -> Plan:
    import networkx as nx

    plan, ids, hard, startable = _skeleton(launch, effective_params)
    # ---- cycles among hard edges ------------------------------------------------------------------
    H = _cycles(plan, ids, hard, startable, nx)

    # ---- stages from the hard edges (condensed); soft edges are shown, never move a stage -------------
    # what never starts is no stage: it is listed apart (``Plan.never_starts``), and waits on nothing
    H = H.subgraph(ids - plan.never_starts).copy() if plan.never_starts else H
    cond = nx.condensation(H)
    member = cond.graph["mapping"]
    D = nx.DiGraph(cond.edges())
    D.add_nodes_from(cond.nodes())
    hard_pairs = {(e.before, e.after) for e in hard}
    soft = [e for e in _topic_edges(graph, ids - plan.never_starts)
            if member[e.before] != member[e.after] and (e.before, e.after) not in hard_pairs]

    for gen in nx.topological_generations(D):
        members = [m for c in gen for m in cond.nodes[c]["members"]]
        stage = sorted(members, key=lambda m: vertex_key(plan.vertices[m]))
        plan.stages.append(stage)
    for i, stage in enumerate(plan.stages, 1):
        for m in stage:
            v = plan.vertices[m]
            plan.vertices[m] = PlanVertex(v.id, v.label, v.fqn, v.kind, v.package, v.executable,
                                          v.file, v.line, v.active, v.delay, i)
    order = {m: i for i, m in enumerate(m for s in [*plan.stages, plan.never_order()] for m in s)}
    plan.edges = sorted(hard + soft, key=lambda e: (e.soft, order[e.after], order[e.before], e.reason))

    # ---- critical path (hard edges, timer delays) --------------------------------------------------
    Dh = nx.DiGraph()
    Dh.add_nodes_from(cond.nodes())
    Dh.add_edges_from(cond.edges())

    def cdelay(c: int) -> float:
        return max((plan.vertices[m].delay or 0.0) for m in cond.nodes[c]["members"])

    best: dict[int, tuple[float, int | None]] = {}
    for c in nx.topological_sort(Dh):
        preds = [(best[p][0], p) for p in Dh.predecessors(c)]
        top = max(preds, key=lambda t: (t[0], -t[1])) if preds else (0.0, None)
        best[c] = (top[0] + cdelay(c), top[1])
    if best:
        def rep(c: int) -> str:
            return str(min(cond.nodes[c]["members"], key=lambda m: vertex_key(plan.vertices[m])))

        # longest total delay; ties: the longest chain, then the first in plan order
        def chain_len(c: int) -> int:
            k, at = 0, c
            while True:
                k += 1
                prev = best[at][1]
                if prev is None:
                    return k
                at = prev

        end = max(best, key=lambda c: (best[c][0], chain_len(c), -order[rep(c)]))
        path = []
        cur: int | None = end
        while cur is not None:
            path.append(rep(cur))
            cur = best[cur][1]
        plan.critical_path = path[::-1]
        plan.critical_delay = best[end][0]
    return plan
