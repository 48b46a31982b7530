"""``--format github``: GitHub Actions workflow commands (annotations on the pull request)."""
from __future__ import annotations

from typing import Any, Mapping

from physai_lint.report import ReportLike, ordered, rel

_COMMAND = {"error": "error", "warning": "warning", "note": "notice"}


def escape_data(text: str) -> str:
    return text.replace("%", "%25").replace("\r", "%0D").replace("\n", "%0A")


def escape_property(text: str) -> str:
    return escape_data(text).replace(":", "%3A").replace(",", "%2C")


def render(report: ReportLike, catalog: Mapping[str, Any], **_: Any) -> str:
    lines = []
    for f in ordered(report):
        s = f.span
        props = {
            "file": rel(s.file, report.cwd),
            "line": str(s.line),
            "col": str(s.col),
            "endLine": str(max(s.end_line, s.line)),
            "endColumn": str(s.end_col),
            "title": f"{f.code} {f.name}",
        }
        head = ",".join(f"{k}={escape_property(v)}" for k, v in props.items())
        body = f.message + (f"\nhelp: {f.help}" if f.help else "")
        lines.append(f"::{_COMMAND[f.severity]} {head}::{escape_data(body)}")
    return "".join(line + "\n" for line in lines)
