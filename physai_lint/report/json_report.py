"""``--format json``: the contract ``schemas/contracts/report.schema.json`` plus ``summary``."""
from __future__ import annotations

import json
from collections import Counter
from typing import Any, Mapping

from physai_lint import __version__
from physai_lint.model.findings import Finding
from physai_lint.model.span import Span
from physai_lint.report import ReportLike, counts, ordered, rel


def _loc(span: Span, cwd: str) -> dict[str, Any]:
    return {
        "file": rel(span.file, cwd),
        "line": span.line,
        "column": span.col,
        "end_line": span.end_line,
        "end_column": span.end_col,
    }


def finding_dict(f: Finding, cwd: str) -> dict[str, Any]:
    file = rel(f.span.file, cwd)
    loc = _loc(f.span, cwd)
    return {
        "code": f.code,
        "name": f.name,
        "severity": f.severity,
        "message": f.message,
        **loc,
        "help": f.help,
        "fingerprint": f.fingerprint(file),
        "related": [{**_loc(r.span, cwd), "message": r.message} for r in f.related],
        "fix": None
        if f.fix is None
        else {**_loc(f.fix.span, cwd), "replacement": f.fix.replacement, "description": f.fix.description},
    }


def to_dict(report: ReportLike) -> dict[str, Any]:
    findings = ordered(report)
    by_sev = counts(findings)
    return {
        "format": "physai-lint-report",
        "version": 1,
        "tool": {"name": "physai-lint", "version": __version__},
        "findings": [finding_dict(f, report.cwd) for f in findings],
        "summary": {
            "files": len(report.files),
            "findings": len(findings),
            "errors": by_sev["error"],
            "warnings": by_sev["warning"],
            "notes": by_sev["note"],
            "baseline_suppressed": report.baseline_suppressed,
            "by_code": dict(sorted(Counter(f.code for f in findings).items())),
        },
    }


def render(report: ReportLike, catalog: Mapping[str, Any], **_: Any) -> str:
    return json.dumps(to_dict(report), indent=2, ensure_ascii=False) + "\n"
