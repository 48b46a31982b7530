"""Reporters: each ``render(report, catalog, **options) -> str``.

``report`` is the engine's ``Report`` (findings, files, cwd, duration_s, baseline_suppressed);
``catalog`` maps codes to ``RuleDoc``s. Paths are shown relative to ``report.cwd``, ``/``-separated.
"""
from __future__ import annotations

import functools
import importlib
import os
from typing import Any, Mapping, Protocol, Sequence

from physai_lint.model.findings import SEVERITY_RANK, Finding

FORMATS = ("text", "json", "sarif", "github", "junit")
_MODULES = {"text": "text", "json": "json_report", "sarif": "sarif", "github": "github", "junit": "junit"}


class ReportLike(Protocol):
    findings: list[Finding]
    files: list[str]
    cwd: str
    duration_s: float
    baseline_suppressed: int


def render(fmt: str, report: ReportLike, catalog: Mapping[str, Any], **options: Any) -> str:
    """Render ``report`` in ``fmt`` (one of ``FORMATS``)."""
    module = importlib.import_module(f"physai_lint.report.{_MODULES[fmt]}")
    return str(module.render(report, catalog, **options))


def rel(path: str, cwd: str) -> str:
    if os.path.isabs(path) and os.path.isabs(cwd):
        return _rel_abs(path, cwd)
    return _rel(path, cwd)  # depends on the process's working directory: not memoised


def _rel(path: str, cwd: str) -> str:
    try:
        out = os.path.relpath(path, cwd)
    except ValueError:
        out = path
    return out.replace(os.sep, "/")


# A report names a few hundred files in thousands of places (the finding, its related spans, the
# sort key): ``os.path.relpath`` was a third of rendering a 1,100-finding JSON report.
_rel_abs = functools.lru_cache(maxsize=8192)(_rel)


def one_line(f: Finding, cwd: str) -> str:
    """``path:line:col: CODE [name] message``: a finding on one line."""
    return f"{rel(f.span.file, cwd)}:{f.span.line}:{f.span.col}: {f.code} [{f.name}] {f.message}"


def ordered(report: ReportLike) -> list[Finding]:
    """Findings in output order: file (as shown), line, column, code, message."""
    return sorted(report.findings, key=lambda f: (rel(f.span.file, report.cwd), *f.sort_key()[1:]))


def counts(findings: Sequence[Finding]) -> dict[str, int]:
    out = {"error": 0, "warning": 0, "note": 0}
    for f in findings:
        out[f.severity] += 1
    return out


def at_least(findings: Sequence[Finding], fail_on: str) -> list[Finding]:
    """Findings whose severity is at or above ``fail_on``."""
    floor = SEVERITY_RANK[fail_on]
    return [f for f in findings if SEVERITY_RANK[f.severity] >= floor]


def plural(n: int, word: str) -> str:
    return f"{n} {word}{'' if n == 1 else 's'}"
