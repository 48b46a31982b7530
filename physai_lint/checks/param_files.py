"""Parameter files: P101 parameter-file-missing, P102 parameter-file-not-installed,
P103 parameter-file-no-match, P104 parameter-file-structure, P106 mixed-type-array."""
from __future__ import annotations

import os
from collections.abc import Iterator

from physai_lint.checks._util import all_nodes
from physai_lint.checks._util import relpath as _rel
from physai_lint.checks.base import CheckContext, rule
from physai_lint.model.findings import Diagnostic, Related
from physai_lint.resolve.model import ResolvedParamFile


@rule("P101", "parameter-file-missing")
def missing(ctx: CheckContext) -> Iterator[Diagnostic]:
    seen: set[object] = set()
    for _, node in all_nodes(ctx):
        for src in node.param_sources:
            if isinstance(src, ResolvedParamFile) and src.status == "missing" and src.span not in seen:
                seen.add(src.span)
                what = ("is empty" if not (src.path or "").strip()
                        else "is a directory" if src.source and os.path.isdir(src.source) else "does not exist")
                shown = f'parameter file path "{src.path}"' if what != "does not exist" else f'parameter file "{src.path}"'
                yield Diagnostic(
                    "P101", src.span,
                    f'{shown} {what}; launch only warns "Parameter file '
                    f'path is not a file" and starts {node.fqn or node.executable} without it',
                    help="fix the path (package, folder or file name) or create the file",
                    key=src.path or "")


@rule("P102", "parameter-file-not-installed")
def not_installed(ctx: CheckContext) -> Iterator[Diagnostic]:
    seen: set[object] = set()
    for _, node in all_nodes(ctx):
        for src in node.param_sources:
            if isinstance(src, ResolvedParamFile) and src.status == "not_installed" and src.span not in seen:
                seen.add(src.span)
                hint = ctx.packages.locate(src.path).install_hint if src.path else None
                yield Diagnostic(
                    "P102", src.span,
                    f'parameter file "{_rel(src.source)}" is in the source tree but is not installed, '
                    f'so "{src.path}" will not exist at run time',
                    help=hint or "install it (CMake install(DIRECTORY ...) or setup.py data_files)",
                    key=src.path or "")


@rule("P103", "parameter-file-no-match")
def no_match(ctx: CheckContext) -> Iterator[Diagnostic]:
    from physai_lint.params.effective import file_binds
    from physai_lint.params.match import explain_no_match

    loaders: dict[str, list[tuple[object, object]]] = {}
    for _, node in all_nodes(ctx, include_inactive=False):
        for src in node.param_sources:
            if isinstance(src, ResolvedParamFile) and src.status == "ok" and src.source in ctx.param_files:
                loaders.setdefault(src.source, []).append((node, src))
    for path, users in sorted(loaders.items()):
        model = ctx.param_files[path]
        if not model.ok or not model.blocks:
            continue
        nodes = [n for n, _ in users]
        if any(n.fqn is None for n in nodes):  # type: ignore[attr-defined]
            continue
        if any(file_binds(n.fqn, model, n.kind == "composable_node") for n in nodes):  # type: ignore[attr-defined]
            continue
        block = model.blocks[0]
        node, src = users[0]
        fqns = ", ".join(sorted({f'"{n.fqn}"' for n in nodes}))  # type: ignore[attr-defined]
        explain = explain_no_match(block.key, node.fqn)  # type: ignore[attr-defined]
        yield Diagnostic(
            "P103", block.key_span,
            f'no node key of "{_rel(path)}" matches the node(s) that load it ({fqns}): {explain}; '
            "the whole file is silently ignored",
            help=f'key the file by the node\'s full name, e.g. "{node.fqn}:", or use a wildcard such as '  # type: ignore[attr-defined]
                 f'"/**/{node.name}:"',  # type: ignore[attr-defined]
            related=(Related(src.span, "loaded here"),),  # type: ignore[attr-defined]
            key=f"{_rel(path)}:{block.key}")


@rule("P104", "parameter-file-structure")
def structure(ctx: CheckContext) -> Iterator[Diagnostic]:
    for path in sorted(ctx.param_files):
        for d in ctx.param_files[path].diagnostics:
            if d.code == "P104":
                yield d


@rule("P106", "mixed-type-array")
def mixed_array(ctx: CheckContext) -> Iterator[Diagnostic]:
    for path in sorted(ctx.param_files):
        for d in ctx.param_files[path].diagnostics:
            if d.code == "P106":
                yield d
    seen: set[object] = set()
    for _, node in all_nodes(ctx):
        for src in node.param_sources:
            for prm in getattr(src, "params", ()):
                if prm.typed_by == "yaml" and prm.value is None and prm.raw and prm.raw.strip().startswith("[") \
                        and prm.span not in seen:
                    seen.add(prm.span)
                    yield Diagnostic(
                        "P106", prm.span,
                        f'parameter "{prm.name}" value "{prm.raw}" is a list with items of different types; '
                        'launch raises "Expected a non-empty sequence, with items of uniform type"',
                        help="make every item the same type (e.g. all floats: 1.0, 2.5)", key=prm.name)
