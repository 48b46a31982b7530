"""``--format sarif``: SARIF 2.1.0, one run, as GitHub code scanning ingests it.

Rules listed are those the results reference (sorted by code; ``ruleIndex`` points into that list).
No ``primaryLocationLineHash`` is invented: ``upload-sarif`` computes it; our own stable key is
``partialFingerprints["physaiLint/v1"]``.
"""
from __future__ import annotations

import json
import re
from pathlib import Path
from typing import Any, Mapping
from urllib.parse import quote

from physai_lint import __version__
from physai_lint.model.findings import SEVERITY_RANK, Finding
from physai_lint.model.span import Span
from physai_lint.report import ReportLike, ordered, rel

SCHEMA_URI = "https://json.schemastore.org/sarif-2.1.0.json"
INFORMATION_URI = "https://github.com/physai/physai-lint"
DOCS_URI = "https://github.com/physai/physai-lint/blob/main/docs/rules.md"
MAX_RESULTS = 25_000
MAX_LOCATIONS = 10
MAX_TEXT = 1024
_PROBLEM_SEVERITY = {"error": "error", "warning": "warning", "note": "recommendation"}



def _uri(path: str) -> str:
    """A relative URI reference (SARIF 3.4.3): spaces and non-ASCII bytes percent-encoded."""
    return quote(path, safe="/")

def _clip(text: str, limit: int = MAX_TEXT) -> str:
    text = text.strip()
    return text if len(text) <= limit else text[: limit - 1].rstrip() + "\u2026"


def _plain(markdown: str) -> str:
    """Markdown paragraph to one line of text (drops code fences, backticks and link targets)."""
    text = re.sub(r"```.*?```", "", markdown, flags=re.DOTALL)
    text = re.sub(r"\[([^\]]+)\]\([^)]+\)", r"\1", text)
    return " ".join(text.replace("`", "").split())


def rule_descriptor(code: str, name: str, severity: str, doc: Any) -> dict[str, Any]:
    summary = str(getattr(doc, "summary", "") or name)
    sections = getattr(doc, "sections", {}) or {}
    full = _plain(sections.get("What it does", "")) or summary
    markdown = str(getattr(doc, "markdown", "") or summary)
    category = str(getattr(doc, "category", "") or code[0])
    return {
        "id": code,
        "name": name,
        "shortDescription": {"text": _clip(summary)},
        "fullDescription": {"text": _clip(full)},
        "help": {"text": _plain(markdown) or summary, "markdown": markdown.strip() or summary},
        "helpUri": f"{DOCS_URI}#{code.lower()}",
        "defaultConfiguration": {"level": str(getattr(doc, "severity", "") or severity)},
        "properties": {
            "tags": [category],
            "precision": str(getattr(doc, "precision", "") or "high"),
            "problem.severity": _PROBLEM_SEVERITY[str(getattr(doc, "severity", "") or severity)],
        },
    }


def _physical(span: Span, cwd: str) -> dict[str, Any]:
    return {
        "artifactLocation": {"uri": _uri(rel(span.file, cwd)), "uriBaseId": "%SRCROOT%"},
        "region": {
            "startLine": span.line,
            "startColumn": span.col,
            "endLine": max(span.end_line, span.line),
            "endColumn": max(span.end_col, span.col + 1) if span.end_line <= span.line else max(span.end_col, 1),
        },
    }


def _sentence(text: str) -> str:
    text = text.strip()
    if not text:
        return text
    text = text[0].upper() + text[1:]
    return text if text.endswith((".", "!", "?")) else text + "."


def result(f: Finding, index: int, cwd: str) -> dict[str, Any]:
    file = rel(f.span.file, cwd)
    message = _sentence(f.message) + (f" {_sentence(f.help)}" if f.help else "")
    out: dict[str, Any] = {
        "ruleId": f.code,
        "ruleIndex": index,
        "level": f.severity,
        "message": {"text": message},
        "locations": [{"physicalLocation": _physical(f.span, cwd)}][:MAX_LOCATIONS],
    }
    if f.related:
        out["relatedLocations"] = [
            {"id": i, "physicalLocation": _physical(r.span, cwd), "message": {"text": _sentence(r.message)}}
            for i, r in enumerate(f.related[:MAX_LOCATIONS])
        ]
    out["partialFingerprints"] = {"physaiLint/v1": f.fingerprint(file)}
    return out


def to_dict(report: ReportLike, catalog: Mapping[str, Any]) -> dict[str, Any]:
    findings = ordered(report)
    dropped = 0
    if len(findings) > MAX_RESULTS:
        # GitHub keeps the most severe results: keep those, in output order.
        keep = sorted(findings, key=lambda f: -SEVERITY_RANK[f.severity])[:MAX_RESULTS]
        kept_ids = {id(f) for f in keep}
        dropped = len(findings) - MAX_RESULTS
        findings = [f for f in findings if id(f) in kept_ids]
    codes = sorted({f.code for f in findings})
    index = {code: i for i, code in enumerate(codes)}
    first = {}
    for f in findings:
        first.setdefault(f.code, f)
    rules = [rule_descriptor(c, first[c].name, first[c].severity, catalog.get(c)) for c in codes]
    run: dict[str, Any] = {
        "tool": {
            "driver": {
                "name": "physai-lint",
                "version": __version__,
                "semanticVersion": __version__,
                "informationUri": INFORMATION_URI,
                "rules": rules,
            }
        },
        "automationDetails": {"id": "physai-lint/"},
        "originalUriBaseIds": {"%SRCROOT%": {"uri": Path(report.cwd).as_uri().rstrip("/") + "/"}},
        "columnKind": "unicodeCodePoints",
        "results": [result(f, index[f.code], report.cwd) for f in findings],
    }
    if dropped:
        run["invocations"] = [
            {
                "executionSuccessful": True,
                "toolExecutionNotifications": [
                    {"level": "warning", "message": {"text": f"{dropped} results left out (SARIF upload limit {MAX_RESULTS})."}}
                ],
            }
        ]
    return {"$schema": SCHEMA_URI, "version": "2.1.0", "runs": [run]}


def render(report: ReportLike, catalog: Mapping[str, Any], **_: Any) -> str:
    return json.dumps(to_dict(report, catalog), indent=2, ensure_ascii=False) + "\n"
