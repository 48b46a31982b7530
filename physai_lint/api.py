"""Programmatic entry points behind ``physai-lint graph``, ``plan`` and ``params``.

``graph(opts, entry, "json")`` follows ``schemas/contracts/graph.schema.json``: what ROS 2 would
launch from one entry file under the given arguments, with ``null`` wherever a value cannot be known
statically.
"""
from __future__ import annotations

import json
import math
import os
from typing import Any

from physai_lint.engine import CheckOptions, Project, build_project, name_nodes
from physai_lint.errors import UnloadableLaunch, UsageError
from physai_lint.resolve.model import LaunchResult, NodeInstance, ResolvedParamFile

GRAPH_FORMATS = ("text", "json", "dot", "mermaid", "html")


def _project(opts: CheckOptions, entry: str) -> tuple[Project, LaunchResult]:
    from dataclasses import replace

    project = build_project(replace(opts, paths=[entry]))
    name_nodes(project)
    entry_abs = os.path.abspath(entry).replace(os.sep, "/")
    for launch in project.launches:
        if launch.entry == entry_abs:
            ensure_loaded(project, entry_abs)
            return project, launch
    raise UsageError(not_a_launch_file(project, entry_abs))


def ensure_loaded(project: Project, entry: str) -> None:
    """Raise ``UnloadableLaunch`` with the findings that keep ``entry`` (absolute) from loading,
    worded as ``check`` words them, when its file could not be parsed."""
    if project.store.launches.get(entry) is not None:
        return
    from physai_lint.catalog import load_catalog
    from physai_lint.engine import to_findings
    from physai_lint.report import one_line, rel

    found = to_findings([d for d in project.diagnostics if d.span.file == entry and d.code.startswith("X")],
                        load_catalog(), {})
    lines = [one_line(f, project.cwd) for f in sorted(found, key=lambda f: (f.span.line, f.span.col, f.code))]
    raise UnloadableLaunch(lines or [f"{rel(entry, project.cwd)}: the launch file cannot be loaded"])


def not_a_launch_file(project: Project, target: str) -> str:
    """Why ``target`` (absolute), named on the command line, has no launch to show."""
    from physai_lint.report import rel

    reason = next((why for path, why in project.skipped if path == target),
                  "a parameter file" if target in project.param_files else "")
    reason = reason.removeprefix("not a launch file: ")  # the sniffer's reason may say it too
    return f'"{rel(target, project.cwd)}" is not a launch file' + (f": {reason}" if reason else "")


def _rel(path: str | None, cwd: str) -> str | None:
    if path is None:
        return None
    try:
        return os.path.relpath(path, cwd).replace(os.sep, "/")
    except ValueError:
        return path


def _effective(project: Project, node: NodeInstance) -> dict[str, Any]:
    from physai_lint.params.effective import node_parameters

    return node_parameters(node, project.param_files)


def _jsonable(value: Any) -> Any:
    if isinstance(value, (list, tuple)):
        return [_jsonable(v) for v in value]
    if isinstance(value, float) and (math.isnan(value) or math.isinf(value)):
        return str(value)
    if isinstance(value, bytes):
        return list(value)
    return value


def graph_document(project: Project, launch: LaunchResult) -> dict[str, Any]:
    """The graph JSON document (contract: physai-lint/graph/1)."""
    from physai_lint.graph.system import build_graph
    from physai_lint.params.effective import sources_complete

    cwd = project.cwd
    nodes = []
    for n in launch.nodes:
        params = {name: (_jsonable(ep.value) if ep.certain or ep.value is not None else None)
                  for name, ep in sorted(_effective(project, n).items())}
        nodes.append({
            "id": n.id, "kind": n.kind, "package": n.package, "executable": n.executable,
            "name": n.name, "namespace": n.namespace, "fqn": n.fqn,
            "active": "unknown" if n.active is None else n.active,
            "remappings": [[r.src, r.dst] for r in n.remaps],
            "parameters": params,
            # False when a parameter source (a file or dict) cannot be known statically: the node may
            # receive more parameters than listed, and listed values may be overridden.
            "parameters_complete": sources_complete(n.param_sources, project.param_files),
            "parameter_files": [_rel(s.path, cwd) if s.status != "ok" else _rel(s.source or s.path, cwd)
                                for s in n.param_sources if isinstance(s, ResolvedParamFile)],
            "container": n.container,
            "source": {"file": _rel(n.span.file, cwd), "line": n.span.line, "column": n.span.col},
            "include_chain": [_rel(f, cwd) for f in n.include_chain],
            "timer_lost": list(n.timer_lost),
            "arguments": list(n.arguments),
        })
    g = build_graph(launch, project.interfaces)
    topics: dict[str, dict[str, Any]] = {}
    for e in g.endpoints:
        if e.resolved is None or e.kind not in ("publisher", "subscriber"):
            continue
        t = topics.setdefault(e.resolved, {"name": e.resolved, "type": None, "publishers": [],
                                           "subscribers": []})
        t["type"] = t["type"] or e.type
        side = "publishers" if e.kind == "publisher" else "subscribers"
        if e.node not in t[side]:
            t[side].append(e.node)
    return {
        "format": "physai-lint-graph", "version": 1,
        "entries": [{"file": _rel(launch.entry, cwd),
                     "arguments": dict(sorted(launch.arguments.items()))}],
        "nodes": nodes,
        "topics": [topics[k] for k in sorted(topics)],
    }


def graph(opts: CheckOptions, entry: str, fmt: str) -> str:
    if fmt not in GRAPH_FORMATS:
        raise UsageError(f'unknown graph format "{fmt}" (expected one of: {", ".join(GRAPH_FORMATS)})')
    project, launch = _project(opts, entry)
    doc = graph_document(project, launch)
    if fmt == "json":
        return json.dumps(doc, indent=2, ensure_ascii=False, sort_keys=False)
    from physai_lint.report import graph_render

    return graph_render.render(doc, fmt)  # type: ignore[no-any-return]


def plan(opts: CheckOptions, entry: str, fmt: str) -> str:
    try:
        from physai_lint.api_plan import plan as plan_impl
    except ImportError as exc:
        raise UsageError(f"the startup plan is not available in this build: {exc}") from None
    return plan_impl(opts, entry, fmt)  # type: ignore[no-any-return]


def params(opts: CheckOptions, entry: str, node: str | None, fmt: str) -> str:
    """Effective parameters of the nodes (or of one node by fqn) with where every value came from."""
    project, launch = _project(opts, entry)
    cwd = project.cwd
    chosen = [n for n in launch.nodes if n.kind != "process" and (node is None or n.fqn == node)]
    if node is not None and not chosen:
        known = ", ".join(sorted({n.fqn for n in launch.nodes if n.fqn})) or "none"
        raise UsageError(f'no node "{node}" in this launch (nodes: {known})')
    out = []
    for n in chosen:
        entries = []
        for name, ep in sorted(_effective(project, n).items()):
            entries.append({
                "name": name, "value": _jsonable(ep.value), "type": ep.kind, "certain": ep.certain,
                "chain": [{"source": b.source_desc, "value": _jsonable(b.value), "overridden": b.overridden,
                           "node_key": b.node_key,
                           "file": _rel(b.span.file, cwd) if b.span else None,
                           "line": b.span.line if b.span else None} for b in ep.chain],
            })
        out.append({"id": n.id, "fqn": n.fqn, "package": n.package, "executable": n.executable,
                    "parameters": entries})
    if fmt == "json":
        return json.dumps({"format": "physai-lint-params", "version": 1, "nodes": out}, indent=2,
                          ensure_ascii=False)
    lines = []
    for n in out:
        lines.append(f"{n['fqn'] or '(unnamed)'}  [{n['package']}/{n['executable']}]")
        if not n["parameters"]:
            lines.append("  (no parameters from the launch)")
        for p in n["parameters"]:
            val = json.dumps(p["value"]) if p["value"] is not None else "unknown"
            lines.append(f"  {p['name']} = {val}  ({p['type'] or 'unknown'})")
            for b in p["chain"]:
                mark = "overridden" if b["overridden"] else "wins"
                where = f"{b['file']}:{b['line']}" if b["file"] else "?"
                lines.append(f"      {mark:10} {json.dumps(b['value'])}  from {b['source']} at {where}")
        lines.append("")
    return "\n".join(lines)
