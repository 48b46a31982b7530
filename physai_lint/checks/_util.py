"""Small helpers shared by the check modules (no I/O)."""
from __future__ import annotations

import os
from collections.abc import Iterable, Iterator

from physai_lint.checks.base import CheckContext
from physai_lint.closematch import close_matches
from physai_lint.model.launch import PythonFacts
from physai_lint.resolve.model import LaunchResult, NodeInstance


def did_you_mean(name: str, candidates: Iterable[str], n: int = 3, cutoff: float = 0.6) -> list[str]:
    return list(close_matches(name, tuple(sorted(set(candidates))), n, cutoff))


def suggestion(name: str, candidates: Iterable[str]) -> str:
    close = did_you_mean(name, candidates)
    if not close:
        return ""
    return "did you mean " + " or ".join(f'"{c}"' for c in close) + "?"


def all_nodes(ctx: CheckContext, include_inactive: bool = True) -> Iterator[tuple[LaunchResult, NodeInstance]]:
    """Every node instance of every resolved launch, deduplicated by source position and fqn."""
    seen: set[tuple[object, ...]] = set()
    for launch in ctx.launches:
        for node in launch.nodes:
            if not include_inactive and node.active is False:
                continue
            key = (node.span, node.fqn, node.package, node.executable, node.kind)
            if key in seen:
                continue
            seen.add(key)
            yield launch, node


def where(node: NodeInstance) -> str:
    return node.fqn or (f'"{node.package}/{node.executable}"' if node.package else "the node")


def relpath(path: str | None) -> str:
    """A path for messages, relative to the working directory when possible."""
    if not path:
        return "?"
    try:
        return os.path.relpath(path).replace(os.sep, "/")
    except ValueError:
        return path


def python_facts(ctx: CheckContext) -> Iterator[tuple[str, PythonFacts]]:
    """(path, PythonFacts) of the parsed Python launch files, in path order."""
    for path in sorted(ctx.launch_files):
        facts = ctx.launch_files[path].python
        if facts is not None:
            yield path, facts
