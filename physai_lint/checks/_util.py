"""Small helpers shared by the check modules (no I/O)."""
from __future__ import annotations

import os
from collections.abc import Iterable, Iterator
from typing import Any

from physai_lint.checks.base import CheckContext
from physai_lint.closematch import close_matches
from physai_lint.model.fields import objects
from physai_lint.model.launch import PythonFacts
from physai_lint.model.span import Span
from physai_lint.resolve.model import LaunchResult, NodeInstance

# rclcpp_components' container executables (ComposableNodeContainer's usual ones).
CONTAINER_EXECUTABLES = ("component_container", "component_container_mt", "component_container_isolated")


def command_words(proc: NodeInstance) -> list[str | None] | None:
    """A process's command line split like a shell would (``["ros2 param set /x a 1"]`` with
    ``shell=True`` too), None for each part not known statically; None when a part does not split."""
    import shlex

    out: list[str | None] = []
    for part in (proc.executable, *proc.arguments):
        if part is not None and any(c.isspace() for c in part):
            try:
                out.extend(shlex.split(part))
            except ValueError:
                return None
        else:
            out.append(part)
    return out


def did_you_mean(name: str, candidates: Iterable[str], n: int = 3, cutoff: float = 0.6) -> list[str]:
    return list(close_matches(name, tuple(sorted(set(candidates))), n, cutoff))


def suggestion(name: str, candidates: Iterable[str]) -> str:
    close = did_you_mean(name, candidates)
    if not close:
        return ""
    return "did you mean " + " or ".join(f'"{c}"' for c in close) + "?"


def run_memo(store: dict[Any, Any], key: Any, owner: object, build: Any) -> Any:
    """``build()``, kept in ``store[key]`` for as long as it is asked with the same ``owner`` (by
    identity: the launches or the launch file it was built from)."""
    found = store.get(key)
    if found is None or found[0] is not owner:
        found = store[key] = (owner, build())
    return found[1]


def once(ctx: CheckContext, field: str, key: Any = None) -> Iterator[Any]:
    """The entries of ``LaunchResult.<field>`` over every launch, each once: two launches that
    include one file record its entries twice. ``key(entry)`` says which are the same (default:
    the entry's first item, its position)."""
    seen: set[Any] = set()
    for launch in ctx.launches:
        for entry in getattr(launch, field):
            k = key(entry) if key is not None else entry[0]
            if k not in seen:
                seen.add(k)
                yield entry


def switched_off_by(node: NodeInstance, value: str | None) -> bool:
    """``value`` is empty and the node not certainly started: "" is how an argument switches a node
    off, so with a value that starts it the remap or file would be another (N105, P101)."""
    return not (value or "").strip() and node.active is not True


def all_nodes(ctx: CheckContext, include_inactive: bool = True) -> Iterator[tuple[LaunchResult, NodeInstance]]:
    """Every node instance of every resolved launch, deduplicated by source position and fqn.
    Listed once per run: a dozen rules ask, and hashing every node's key was a tenth of the rules'
    time on a large workspace."""
    key = "_all_nodes" if include_inactive else "_active_nodes"
    return iter(run_memo(ctx.options, key, ctx.launches, lambda: list(_all_nodes(ctx, include_inactive))))


_ACTIVITY = {True: 2, None: 1, False: 0}


def _all_nodes(ctx: CheckContext, include_inactive: bool) -> Iterator[tuple[LaunchResult, NodeInstance]]:
    """In first-seen order; of the instances of one key, the most active (a node that one entry
    includes under a false condition and another starts is checked as started)."""
    best: dict[tuple[object, ...], tuple[LaunchResult, NodeInstance]] = {}
    for launch in ctx.launches:
        for node in launch.nodes:
            if not include_inactive and node.active is False:
                continue
            key = (node.span, node.fqn, node.package, node.executable, node.kind)
            have = best.get(key)
            if have is None or _ACTIVITY.get(node.active, 1) > _ACTIVITY.get(have[1].active, 1):
                best[key] = (launch, node)
    yield from best.values()


def ir_objects(ctx: CheckContext, path: str) -> list[Any]:
    """Every model object in launch file ``path``'s actions (not atoms, lists or positions), in
    depth-first order, at most 60 levels deep. Listed once per file and run for the rules that look
    for one kind of value anywhere (``Command``, substitutions a distro lacks)."""
    lf = ctx.launch_files[path]
    return run_memo(ctx.options.setdefault("_ir_objects", {}), path, lf, lambda: objects(lf.actions))  # type: ignore[no-any-return]


# The launch action class behind a NodeInstance kind, for messages ("process" is ExecuteProcess;
# callers that word a process otherwise give their own default to ``.get``)
ACTION_CLASSES = {"node": "Node", "lifecycle_node": "LifecycleNode", "container": "ComposableNodeContainer"}


def where(node: NodeInstance) -> str:
    return node.fqn or (f'"{node.package}/{node.executable}"' if node.package else "the node")


def line_ref(span: Span, here: Span) -> str:
    """``span`` named from a message about ``here``: "line N" in the same file, else "file:N"."""
    return f"line {span.line}" if span.file == here.file else f"{relpath(span.file)}:{span.line}"


# A relative path launch opens (a parameter file, an included file): workspace.index.locate
# reports it missing, whatever directory the linter runs in
RELATIVE_PATH = ("is relative: launch opens it from the directory `ros2 launch` is started in, not from "
                 "the package or the launch file")


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
