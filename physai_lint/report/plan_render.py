"""Render a startup ``Plan``: ``text`` (stage by stage), ``json``, ``dot`` (Graphviz), ``mermaid``.

All outputs are deterministic (the plan is already ordered) and paths are relative to ``cwd``.

JSON (``"version": 1``)::

    {"version": 1, "entry": "src/.../x.launch.py",
     "vertices": [{"id", "label", "fqn", "kind", "package", "executable", "file", "line",
                   "stage", "delay", "active", "never_starts"}],          # in stage order, then
                                                                          # those that never start (stage 0)
     "stages": [["n1", "n2"], ["n3"]],                  # vertex ids, stage 1 first
     "edges": [{"before", "after", "reason", "soft", "delay", "file", "line", "against"}],
     "cycles": [{"nodes": [...], "text": "a -> b -> a", "deadlock": bool, "file", "line"}],
     "cycles_truncated": bool,
     "critical_path": {"nodes": [...], "delay": 3.0},
     "never_started": [{"file", "line", "message"}]}

``reason`` is one of ``on_process_start``, ``on_process_exit``, ``on_execution_complete``,
``on_state_transition``, ``container``, ``lifecycle manager``, ``lifecycle order``, ``topic <name>``.
Stages come from the hard edges only; a soft (topic) edge is ``against`` the plan when its publisher
starts in a later stage than its subscriber.
"""
from __future__ import annotations

import io
import json
import os
from typing import Any

from physai_lint.graph.plan import Plan, PlanEdge, PlanVertex

FORMATS = ("text", "json", "dot", "mermaid")

_EVENT = {"on_process_start": ("starts", "OnProcessStart"), "on_process_exit": ("exits", "OnProcessExit"),
          "on_execution_complete": ("completes", "OnExecutionComplete"),
          "on_state_transition": ("changes lifecycle state", "OnStateTransition")}


def _rel(path: str | None, cwd: str) -> str | None:
    if path is None:
        return None
    try:
        rel = os.path.relpath(path, cwd)
    except ValueError:
        return path
    return path if rel.startswith("../../..") else rel.replace(os.sep, "/")


def _secs(x: float | None) -> str:
    if x is None:
        return "? s"
    return f"{x:g} s"


def render_plan(plan: Plan, fmt: str, cwd: str) -> str:
    if fmt == "text":
        return _text(plan, cwd)
    if fmt == "json":
        return json.dumps(_json(plan, cwd), indent=2) + "\n"
    if fmt == "dot":
        return _dot(plan)
    if fmt == "mermaid":
        return _mermaid(plan)
    raise ValueError(f'unknown plan format "{fmt}" (expected one of: {", ".join(FORMATS)})')


# ---- text ------------------------------------------------------------------------------------------
MAX_LISTED = 6  # names listed on one line before "and N more"


def _names(items: list[str]) -> str:
    if len(items) <= MAX_LISTED:
        return ", ".join(items)
    return ", ".join(items[:MAX_LISTED]) + f" and {len(items) - MAX_LISTED} more"


def _hard_why(reason: str, befores: list[str], e: PlanEdge, cwd: str) -> str:
    b = _names(befores)
    where = f", {_rel(e.span.file, cwd)}:{e.span.line}" if e.span is not None else ""
    if reason in _EVENT:
        verb, cls = _EVENT[reason]
        timer = f", then a {_secs(e.delay)} timer" if e.delay else ""
        return f"after {b} {verb} ({cls}{where}){timer}"
    if reason == "container":
        return f"after container {b} (loaded into it)"
    if reason == "lifecycle manager":
        return f"after {b} (manages {'it' if len(befores) == 1 else 'them'}: node_names)"
    if reason == "lifecycle order":
        return f"after {b} (the lifecycle manager brings node_names up in order)"
    return f"after {b} ({reason}{where})"


def _waits(plan: Plan, vid: str, cwd: str) -> list[str]:
    """One line per (reason, handler) for the hard edges, one line for all topic needs."""
    labels = plan.labels
    groups: dict[tuple[str, Any, Any], list[PlanEdge]] = {}
    soft: dict[str, list[str]] = {}
    against: set[str] = set()
    for e in plan.waits_for(vid):
        if e.soft:
            soft.setdefault(e.before, []).append(e.reason.removeprefix("topic "))
            if plan.vertices[e.before].stage > plan.vertices[vid].stage:
                against.add(e.before)
        else:
            groups.setdefault((e.reason, e.span, e.delay), []).append(e)
    out = [f"<- {_hard_why(r, [labels[e.before] for e in es], es[0], cwd)}" for (r, _, _), es in groups.items()]
    if soft:
        pubs = []
        for pub in sorted(soft, key=lambda p: (plan.vertices[p].stage, labels[p])):
            late = f", stage {plan.vertices[pub].stage}: starts later" if pub in against else ""
            pubs.append(f"{labels[pub]} ({_names(soft[pub])}{late})")
        out.append("~  data from " + _names(pubs))
    return out


def _vertex_line(v: PlanVertex, width: int, cwd: str, never: bool = False) -> str:
    what = f"{v.package}/{v.executable}" if v.package else (v.executable or "?")
    tags = ["NEVER STARTS: the event it waits for never comes"] if never else []
    if v.kind != "node":
        tags.append(v.kind.replace("_", " "))
    if v.active is None:
        tags.append("conditional")
    if v.delay is not None and v.delay < 0:
        tags.append(f"timer of {_secs(v.delay)}: negative")
    elif v.delay:
        tags.append(f"timer +{_secs(v.delay)}")
    elif v.delay is None:
        tags.append("timer of unknown length")
    tail = f"  [{', '.join(tags)}]" if tags else ""
    return f"{v.label:<{width}}  {what}{tail}  {_rel(v.file, cwd)}:{v.line}"


_MAX_UNKNOWN = 10  # unknown parts listed in the text form


def _text(plan: Plan, cwd: str) -> str:
    from rich.console import Console
    from rich.text import Text
    from rich.tree import Tree

    buf = io.StringIO()
    console = Console(file=buf, width=4000, no_color=True, color_system=None, highlight=False,
                      soft_wrap=True, emoji=False, markup=False)
    labels = plan.labels
    n_hard = sum(1 for e in plan.edges if not e.soft)
    n_soft = len(plan.edges) - n_hard
    console.print(f"Startup plan: {_rel(plan.entry, cwd)}")
    never = plan.never_order()
    n = len(plan.vertices) - len(never)
    console.print(f"{n} process{'' if n == 1 else 'es'} in {len(plan.stages)} stage(s)"
                  + (f", {len(never)} that never start{'s' if len(never) == 1 else ''}" if never else "")
                  + f"; {n_hard} ordering edge(s); {n_soft} topic need(s) (shown with ~, they do not change "
                  "the stages)")
    groups = [(f"Stage {i}: " + ("starts with the launch" if i == 1 else f"after stage {i - 1}"), stage)
              for i, stage in enumerate(plan.stages, 1)]
    if never:
        groups.append(("Never starts", never))
    for title, stage in groups:
        width = min(max(len(plan.vertices[v].label) for v in stage), 40)
        tree = Tree(Text(f"{title} ({len(stage)})"), guide_style="none")
        for vid in stage:
            branch = tree.add(Text(_vertex_line(plan.vertices[vid], width, cwd, vid in plan.never_starts)))
            for line in _waits(plan, vid, cwd):
                branch.add(Text(line))
        console.print()
        console.print(tree)
    console.print()
    if len(plan.critical_path) > 1 or plan.critical_delay:
        path = " -> ".join(labels[p] for p in plan.critical_path)
        if plan.critical_delay:
            console.print(f"Critical path ({_secs(plan.critical_delay)} of timers): {path}")
        else:
            console.print(f"Longest chain (no timers): {path}")
    for c in plan.cycles:
        kind = "DEADLOCK, none of them ever starts" if c.deadlock else "executes an action twice"
        console.print(f"Cycle ({kind}): {c.text(labels)}")
    if plan.cycles_truncated:
        console.print("  (more cycles not shown)")
    for span, msg in plan.never_started:
        console.print(f"Never fires: handler at {_rel(span.file, cwd)}:{span.line}: {msg}")
    if plan.unknown:
        console.print(f"Not shown: {len(plan.unknown)} part(s) of the launch cannot be known statically "
                      "and may start more:")
        for span, reason in plan.unknown[:_MAX_UNKNOWN]:
            console.print(f"  {_rel(span.file, cwd)}:{span.line}: {reason}")
        if len(plan.unknown) > _MAX_UNKNOWN:
            console.print(f"  ... and {len(plan.unknown) - _MAX_UNKNOWN} more (--format json lists them all)")
    console.print("Legend: <- must start first (event handler, timer, container, lifecycle manager); "
                  "~ data it subscribes to (soft)")
    return "\n".join(line.rstrip() for line in buf.getvalue().rstrip().splitlines()) + "\n"


# ---- json ------------------------------------------------------------------------------------------
def _json(plan: Plan, cwd: str) -> dict[str, Any]:
    labels = plan.labels
    verts = [plan.vertices[v] for s in [*plan.stages, plan.never_order()] for v in s]
    return {
        "version": 1,
        "entry": _rel(plan.entry, cwd),
        "vertices": [{"id": v.id, "label": v.label, "fqn": v.fqn, "kind": v.kind, "package": v.package,
                      "executable": v.executable, "file": _rel(v.file, cwd), "line": v.line,
                      "stage": v.stage, "delay": v.delay, "active": v.active,
                      "never_starts": v.id in plan.never_starts} for v in verts],
        "stages": plan.stages,
        "edges": [{"before": e.before, "after": e.after, "reason": e.reason, "soft": e.soft,
                   "delay": e.delay, "file": _rel(e.span.file, cwd) if e.span else None,
                   "line": e.span.line if e.span else None,
                   "against": e.soft and plan.vertices[e.before].stage > plan.vertices[e.after].stage}
                  for e in plan.edges],
        "cycles": [{"nodes": list(c.nodes), "text": c.text(labels), "deadlock": c.deadlock,
                    "file": _rel(c.edges[0].span.file, cwd) if c.edges and c.edges[0].span else None,
                    "line": c.edges[0].span.line if c.edges and c.edges[0].span else None}
                   for c in plan.cycles],
        "cycles_truncated": plan.cycles_truncated,
        "critical_path": {"nodes": plan.critical_path, "delay": plan.critical_delay},
        "never_started": [{"file": _rel(s.file, cwd), "line": s.line, "message": m}
                          for s, m in plan.never_started],
        "unknown": [{"file": _rel(s.file, cwd), "line": s.line, "reason": m} for s, m in plan.unknown],
    }


# ---- dot / mermaid ---------------------------------------------------------------------------------
def _q(s: str) -> str:
    return '"' + s.replace("\\", "\\\\").replace('"', '\\"') + '"'


def _edge_label(e: PlanEdge) -> str:
    lbl = e.reason
    if e.delay:
        lbl += f" +{_secs(e.delay)}"
    return lbl


def _dot(plan: Plan) -> str:
    out = ["digraph startup {", "  rankdir=LR;", "  node [shape=box, fontname=\"Helvetica\"];",
           "  edge [fontname=\"Helvetica\", fontsize=10];"]
    never = plan.never_order()
    for i, stage in enumerate([*plan.stages, never] if never else plan.stages, 1):
        out.append(f"  subgraph cluster_stage_{i} {{" if stage is not never else "  subgraph cluster_never {")
        out.append(f"    label={_q(f'stage {i}' if stage is not never else 'never starts')};")
        out.append("    style=rounded; color=gray;")
        for vid in stage:
            v = plan.vertices[vid]
            lbl = v.label + (f"\\n{v.package}/{v.executable}" if v.package else "")
            if v.delay:
                lbl += f"\\n+{_secs(v.delay)}"
            extra = ", color=red, style=dashed" if vid in plan.never_starts else ""
            out.append(f"    {_q(vid)} [label=\"{lbl.replace(chr(34), chr(92) + chr(34))}\"{extra}];")
        out.append("  }")
    cyc_edges = {(e.before, e.after) for c in plan.cycles for e in c.edges}
    for e in plan.edges:
        attrs = [f"label={_q(_edge_label(e))}"]
        if e.soft:  # shown, but the stages come from the hard edges: do not let it move ranks
            attrs += ["style=dashed", "constraint=false"]
        if (e.before, e.after) in cyc_edges:
            attrs.append("color=red")
        out.append(f"  {_q(e.before)} -> {_q(e.after)} [{', '.join(attrs)}];")
    out.append("}")
    return "\n".join(out) + "\n"


def _m(s: str) -> str:
    return '"' + s.replace('"', "#quot;") + '"'


def _mermaid(plan: Plan) -> str:
    out = ["flowchart LR"]
    never = plan.never_order()
    for i, stage in enumerate([*plan.stages, never] if never else plan.stages, 1):
        out.append(f"  subgraph stage{i}[{_m(f'stage {i}')}]" if stage is not never else
                   f"  subgraph never[{_m('never starts')}]")
        for vid in stage:
            v = plan.vertices[vid]
            lbl = v.label + (f"<br/>{v.package}/{v.executable}" if v.package else "")
            if v.delay:
                lbl += f"<br/>+{_secs(v.delay)}"
            out.append(f"    {vid}[{_m(lbl)}]")
        out.append("  end")
    cyc_edges = {(e.before, e.after) for c in plan.cycles for e in c.edges}
    red = []
    for i, e in enumerate(plan.edges):
        arrow = "-.->" if e.soft else "-->"
        out.append(f"  {e.before} {arrow}|{_m(_edge_label(e))}| {e.after}")
        if (e.before, e.after) in cyc_edges and not e.soft:
            red.append(str(i))
    if red:
        out.append(f"  linkStyle {','.join(red)} stroke:#d00,stroke-width:2px")
    if plan.never_starts:
        out.append("  classDef never stroke:#d00,stroke-dasharray:4 3,color:#d00")
        out.append("  class " + ",".join(plan.never_order()) + " never")
    return "\n".join(out) + "\n"
