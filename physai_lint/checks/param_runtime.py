"""Parameters changed after start-up: P110 read-only-parameter.

Giving a read-only parameter a value at start-up (``parameters=``, ``--params-file``, ``<param>``)
is how read-only parameters are meant to be set: rclcpp applies the overrides inside
``declare_parameter`` (``__declare_parameter_common`` -> ``__set_parameters_atomically_common``,
which has no read-only test) and rclpy skips the test when a descriptor is being applied
(``_set_parameters_atomically_common``). Only a later ``set_parameters`` call, which is what
``ros2 param set`` / ``ros2 param load`` do, is refused with "cannot be set because it is read-only".
"""
from __future__ import annotations

import os
from collections.abc import Iterator
from typing import Any

from physai_lint.checks._params import decl_source, interface
from physai_lint.checks._util import command_words
from physai_lint.checks.base import CheckContext, rule
from physai_lint.model.findings import Diagnostic, Related
from physai_lint.resolve.model import LaunchResult, NodeInstance, ResolvedParamFile

# ``ros2 param set|load`` options that take a value (ros2cli ros2param/verb/*.py, NodeStrategy).
_OPTS_WITH_VALUE = frozenset({"--spin-time", "--timeout"})


def _argv(proc: NodeInstance) -> list[str] | None:
    """The process command line, split like a shell would; None when any part is unknown."""
    words = command_words(proc)
    return None if words is None or None in words else words  # type: ignore[return-value]


def _is_number(text: str) -> bool:
    try:
        float(text)
    except ValueError:
        return False
    return True


def ros2_param_command(argv: list[str]) -> tuple[str, str, str, str | None] | None:
    """``ros2 param set NODE NAME VALUE`` -> ("set", NODE, NAME, VALUE);
    ``ros2 param load NODE FILE`` -> ("load", NODE, FILE, None); else None."""
    if len(argv) < 3 or os.path.basename(argv[0]) != "ros2" or argv[1] != "param":
        return None
    verb = argv[2]
    if verb not in ("set", "load"):
        return None
    positional: list[str] = []
    skip = False
    for a in argv[3:]:
        if skip:
            skip = False
        elif a.startswith("-") and not _is_number(a):  # argparse: "-1.5" is a positional
            skip = a in _OPTS_WITH_VALUE
        else:
            positional.append(a)
    if verb == "set" and len(positional) >= 3:
        return "set", positional[0], positional[1], positional[2]
    if verb == "load" and len(positional) >= 2:
        return "load", positional[0], positional[1], None
    return None


def _absolute(name: str) -> str:
    return name if name.startswith("/") else "/" + name


def _param_file(ctx: CheckContext, launch: LaunchResult, path: str) -> Any:
    if path in ctx.param_files:
        return ctx.param_files[path]
    for node in launch.nodes:
        for src in node.param_sources:
            if isinstance(src, ResolvedParamFile) and src.path == path and src.source in ctx.param_files:
                return ctx.param_files[src.source]
    return None


def _loaded_names(model: Any, fqn: str) -> list[tuple[str, Any]]:
    """(name, FileParam) that ``ros2 param load`` sends to ``fqn``: blocks keyed by the node's
    full name or ``/**`` (ros2param ``load_parameter_file``, wildcard on by default)."""
    out: list[tuple[str, Any]] = []
    for block in model.blocks:
        if block.key in (fqn, fqn.lstrip("/"), "/**"):
            out.extend((p.name, p) for p in block.params)
    return out


@rule("P110", "read-only-parameter")
def read_only(ctx: CheckContext) -> Iterator[Diagnostic]:
    seen: set[object] = set()
    for launch in ctx.launches:
        targets: dict[str, NodeInstance] = {}
        for n in launch.nodes:
            if n.kind != "process" and n.fqn is not None and n.active is not False:
                targets.setdefault(n.fqn, n)
        for proc in launch.nodes:
            if proc.kind != "process" or proc.active is False:
                continue
            argv = _argv(proc)
            cmd = ros2_param_command(argv) if argv else None
            if cmd is None:
                continue
            verb, node_name, what, value = cmd
            fqn = _absolute(node_name)
            target = targets.get(fqn)
            iface = interface(ctx, target) if target is not None else None
            if iface is None or not iface.parameters:
                continue
            if verb == "set":
                names: list[tuple[str, Any]] = [(what, None)]
            else:
                model = _param_file(ctx, launch, what)
                names = _loaded_names(model, fqn) if model is not None else []
            for name, _ in names:
                decl = iface.parameters.get(name)
                if decl is None or not decl.read_only or (proc.span, name) in seen:
                    continue
                seen.add((proc.span, name))
                how = (f'"ros2 param set {node_name} {name} {value}"' if verb == "set"
                       else f'"ros2 param load {node_name} {what}"')
                where = f" ({decl_source(decl.source)})" if decl.source else ""
                related = [Related(target.span, "node started here")]  # type: ignore[union-attr]
                if decl.span is not None:
                    related.append(Related(decl.span, "declared read-only here"))
                yield Diagnostic(
                    "P110", proc.span,
                    f'{how} changes parameter "{name}" of {fqn} after start-up, but it is declared '
                    f"read-only{where}; the node refuses it (\"parameter '{name}' cannot be set "
                    "because it is read-only\") and keeps its start-up value",
                    help=f'give "{name}" at start-up instead, in the node\'s parameters '
                         f"(parameters=[{{'{name}': ...}}] or its params file)",
                    related=tuple(related), key=f"{fqn}:{name}")
