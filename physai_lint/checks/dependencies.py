"""Package dependencies of launch files: U103 missing-exec-depend (ECOSYSTEM §5)."""
from __future__ import annotations

from typing import Iterator

from physai_lint.checks.base import CheckContext, rule
from physai_lint.model.findings import Diagnostic
from physai_lint.model.span import Span


def _references(ctx: CheckContext) -> Iterator[tuple[str, Span, str]]:
    """(referenced package, where, launch file) in a deterministic order."""
    for launch in ctx.launches:
        for node in launch.nodes:
            if node.package:
                yield node.package, node.spans.get("package", node.span), node.file
        for name, span, file in launch.package_refs:
            if span is not None:
                yield name, span, file


@rule("U103", "missing-exec-depend")
def missing_exec_depend(ctx: CheckContext) -> Iterator[Diagnostic]:
    refs = sorted(set(_references(ctx)), key=lambda r: (r[2], r[1].line, r[1].col, r[0]))
    reported: set[tuple[str, str]] = set()
    for name, span, file in refs:
        owner = ctx.packages.package_of_source(span.file or file)
        if owner is None or not owner.valid or name == owner.name:
            continue
        if (owner.name, name) in reported or not ctx.packages.has_package(name):
            continue
        if name in ctx.packages.exec_depends(owner.name):
            continue
        reported.add((owner.name, name))
        yield Diagnostic(
            "U103", span,
            f'package "{owner.name}" uses package "{name}" in its launch files but its package.xml '
            f'does not declare it (no <exec_depend> or <depend>)',
            help=f'add <exec_depend>{name}</exec_depend> to the package.xml of "{owner.name}"',
            key=f"{owner.name}->{name}")
