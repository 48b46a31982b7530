"""``physai-lint plan``: the startup plan of one entry launch file, rendered."""
from __future__ import annotations

import os
from dataclasses import replace
from typing import Any

from physai_lint.engine import CheckOptions, build_project, name_nodes


def compute_plan(opts: CheckOptions, entry: str, cwd: str | None = None) -> tuple[Any, str]:
    """(Plan, cwd) for ``entry`` (a launch file path, relative to ``cwd``)."""
    from physai_lint.errors import UsageError
    from physai_lint.graph.plan import build_plan
    from physai_lint.graph.system import build_graph
    from physai_lint.params.effective import node_parameters

    cwd = (cwd or os.getcwd()).replace(os.sep, "/")
    target = os.path.normpath(os.path.join(cwd, entry)).replace(os.sep, "/")
    project = build_project(replace(opts, paths=[entry]), cwd)
    name_nodes(project)
    launch = next((l for l in project.launches if l.entry == target), None)
    if launch is None:
        if not project.launches:
            from physai_lint.api import not_a_launch_file

            raise UsageError(not_a_launch_file(project, target))
        launch = project.launches[0]
    else:
        from physai_lint.api import ensure_loaded

        ensure_loaded(project, target)
    graph = build_graph(launch, project.interfaces)
    cache: dict[int, Any] = {}

    def params(node: Any) -> dict[str, Any]:
        if id(node) not in cache:
            cache[id(node)] = node_parameters(node, project.param_files, opts.distro)
        return cache[id(node)]  # type: ignore[no-any-return]

    return build_plan(launch, graph, params), project.cwd


def plan(opts: CheckOptions, entry: str, fmt: str, cwd: str | None = None) -> str:
    """Render the startup plan of ``entry`` as ``fmt`` (text, json, dot, mermaid)."""
    from physai_lint.report.plan_render import render_plan

    p, root = compute_plan(opts, entry, cwd)
    return render_plan(p, fmt, root)
