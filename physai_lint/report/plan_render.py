"""Render a startup ``Plan``: ``text`` (stage by stage), ``json``, ``dot`` (Graphviz), ``mermaid``.

All outputs are deterministic (the plan is already ordered) and paths are relative to ``cwd``.

JSON (``"version": 1``)::

    {"version": 1, "entry": "src/.../x.launch.py",
     "vertices": [{"id", "label", "fqn", "kind", "package", "executable", "file", "line",
                   "stage", "delay", "active"}],          # in stage order
     "stages": [["n1", "n2"], ["n3"]],                  # vertex ids, stage 1 first
     "edges": [{"before", "after", "reason", "soft", "delay", "file", "line"}],
     "cycles": [{"nodes": [...], "text": "a -> b -> a", "deadlock": bool, "file", "line"}],
     "cycles_truncated": bool,
     "critical_path": {"nodes": [...], "delay": 3.0},
     "never_started": [{"file", "line", "message"}],
     "skipped_soft_edges": 0}

``reason`` is one of ``on_process_start``, ``on_process_exit``, ``on_execution_complete``,
``on_state_transition``, ``container``, ``lifecycle manager``, ``lifecycle order``, ``topic <name>``.
"""
from __future__ import annotations

import json
import os
from typing import Any

from physai_lint.graph.plan import Plan, PlanEdge

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
def _why(e: PlanEdge, labels: dict[str, str], cwd: str) -> str:
    b = labels.get(e.before, e.before)
    where = f", {_rel(e.span.file, cwd)}:{e.span.line}" if e.span is not None else ""
    if e.reason in _EVENT:
        verb, cls = _EVENT[e.reason]
        timer = f", then a {_secs(e.delay)} timer" if e.delay else ""
        return f"after {b} {verb} ({cls}{where}){timer}"
    if e.reason == "container":
        return f"after container {b} (loaded into it)"
    if e.reason == "lifecycle manager":
        return f"after {b} (manages it: node_names)"
    if e.reason == "lifecycle order":
        return f"after {b} (lifecycle manager brings node_names up in order)"
    if e.reason.startswith("topic "):
        return f"wants {b} (publishes {e.reason[6:]})"
    return f"after {b} ({e.reason}{where})"


def _text(plan: Plan, cwd: str) -> str:
    labels = plan.labels
    n_hard = sum(1 for e in plan.edges if not e.soft)
    n_soft = len(plan.edges) - n_hard
    out = [f"Startup plan: {_rel(plan.entry, cwd)}",
           (f"  {len(plan.vertices)} processes in {len(plan.stages)} stage(s); "
            f"{n_hard} ordering edge(s), {n_soft} topic need(s) (soft)"), ""]
    width = max((len(v.label) for v in plan.vertices.values()), default=0)
    width = min(width, 48)
    for i, stage in enumerate(plan.stages, 1):
        title = "starts with the launch" if i == 1 else "waits for an earlier stage"
        out.append(f"Stage {i} — {title}")
        for vid in stage:
            v = plan.vertices[vid]
            what = f"{v.package}/{v.executable}" if v.package else (v.executable or "?")
            extra = []
            if v.kind not in ("node",):
                extra.append(v.kind.replace("_", " "))
            if v.active is None:
                extra.append("conditional")
            if v.delay:
                extra.append(f"timer +{_secs(v.delay)}")
            elif v.delay is None:
                extra.append("timer of unknown length")
            tail = f"  [{', '.join(extra)}]" if extra else ""
            out.append(f"  {v.label:<{width}}  {what}  ({_rel(v.file, cwd)}:{v.line}){tail}")
            for e in plan.waits_for(vid):
                mark = "~" if e.soft else "<-"
                out.append(f"      {mark} {_why(e, labels, cwd)}")
        out.append("")
    if plan.critical_path and len(plan.critical_path) > 1 or plan.critical_delay:
        path = " -> ".join(labels[p] for p in plan.critical_path)
        out.append(f"Critical path ({_secs(plan.critical_delay)} of timers): {path}")
    for c in plan.cycles:
        kind = "DEADLOCK, none of them ever starts" if c.deadlock else "executes an action twice"
        out.append(f"Cycle ({kind}): {c.text(labels)}")
    if plan.cycles_truncated:
        out.append("  (more cycles not shown)")
    for span, msg in plan.never_started:
        out.append(f"Never fires: handler at {_rel(span.file, cwd)}:{span.line}: {msg}")
    if plan.skipped_soft:
        out.append(f"({plan.skipped_soft} topic need(s) left out: they would close a cycle)")
    out.append("Legend: <- must start first (event handler, container, lifecycle manager); "
               "~ should start first (topic)")
    return "\n".join(out).rstrip() + "\n"


# ---- json ------------------------------------------------------------------------------------------
def _json(plan: Plan, cwd: str) -> dict[str, Any]:
    labels = plan.labels
    verts = [plan.vertices[v] for s in plan.stages for v in s]
    return {
        "version": 1,
        "entry": _rel(plan.entry, cwd),
        "vertices": [{"id": v.id, "label": v.label, "fqn": v.fqn, "kind": v.kind, "package": v.package,
                      "executable": v.executable, "file": _rel(v.file, cwd), "line": v.line,
                      "stage": v.stage, "delay": v.delay, "active": v.active} for v in verts],
        "stages": plan.stages,
        "edges": [{"before": e.before, "after": e.after, "reason": e.reason, "soft": e.soft,
                   "delay": e.delay, "file": _rel(e.span.file, cwd) if e.span else None,
                   "line": e.span.line if e.span else None} for e in plan.edges],
        "cycles": [{"nodes": list(c.nodes), "text": c.text(labels), "deadlock": c.deadlock,
                    "file": _rel(c.edges[0].span.file, cwd) if c.edges and c.edges[0].span else None,
                    "line": c.edges[0].span.line if c.edges and c.edges[0].span else None}
                   for c in plan.cycles],
        "cycles_truncated": plan.cycles_truncated,
        "critical_path": {"nodes": plan.critical_path, "delay": plan.critical_delay},
        "never_started": [{"file": _rel(s.file, cwd), "line": s.line, "message": m}
                          for s, m in plan.never_started],
        "skipped_soft_edges": plan.skipped_soft,
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
    for i, stage in enumerate(plan.stages, 1):
        out.append(f"  subgraph cluster_stage_{i} {{")
        out.append(f"    label={_q(f'stage {i}')};")
        out.append("    style=rounded; color=gray;")
        for vid in stage:
            v = plan.vertices[vid]
            lbl = v.label + (f"\\n{v.package}/{v.executable}" if v.package else "")
            if v.delay:
                lbl += f"\\n+{_secs(v.delay)}"
            out.append(f"    {_q(vid)} [label=\"{lbl.replace(chr(34), chr(92) + chr(34))}\"];")
        out.append("  }")
    cyc_edges = {(e.before, e.after) for c in plan.cycles for e in c.edges}
    for e in plan.edges:
        attrs = [f"label={_q(_edge_label(e))}"]
        if e.soft:
            attrs.append("style=dashed")
        if (e.before, e.after) in cyc_edges:
            attrs.append("color=red")
        out.append(f"  {_q(e.before)} -> {_q(e.after)} [{', '.join(attrs)}];")
    out.append("}")
    return "\n".join(out) + "\n"


def _m(s: str) -> str:
    return '"' + s.replace('"', "#quot;") + '"'


def _mermaid(plan: Plan) -> str:
    out = ["flowchart LR"]
    for i, stage in enumerate(plan.stages, 1):
        out.append(f"  subgraph stage{i}[{_m(f'stage {i}')}]")
        for vid in stage:
            v = plan.vertices[vid]
            lbl = v.label + (f"<br/>{v.package}/{v.executable}" if v.package else "")
            if v.delay:
                lbl += f"<br/>+{_secs(v.delay)}"
            out.append(f"    {vid}[{_m(lbl)}]")
        out.append("  end")
    for e in plan.edges:
        arrow = "-.->" if e.soft else "-->"
        out.append(f"  {e.before} {arrow}|{_m(_edge_label(e))}| {e.after}")
    return "\n".join(out) + "\n"
