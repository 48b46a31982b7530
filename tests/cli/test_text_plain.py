"""The text report without colour is built without rich; it must be what rich prints, byte for byte."""
from __future__ import annotations

import sys
from dataclasses import dataclass
from pathlib import Path

from hypothesis import given, settings
from hypothesis import strategies as st

sys.path.insert(0, str(Path(__file__).resolve().parents[2]))  # tests run without an install

from physai_lint.model.findings import Finding, Related
from physai_lint.model.span import Span
from physai_lint.report import text

FILE = "/ws/src/demo/launch/a.launch.py"
# Control codes rich strips, wide and combining characters, line breaks other than "\n", tabs.
_ALPHABET = st.sampled_from(list("ab Z_/\"'%:\\{}[]") + ["\x07", "\x08", "\x0b", "\x0c", "\r", "\x1b", "\x00",
                                                       "\t", "\n", "\x85", "\u2028", "é", "e\u0301", "漢",
                                                       "\U0001f600", "\u200b", " "])
_TEXT = st.lists(_ALPHABET, max_size=30).map("".join)


@dataclass
class _Report:
    findings: list[Finding]
    files: list[str]
    cwd: str = "/ws"
    duration_s: float = 0.0
    baseline_suppressed: int = 0


@st.composite
def _reports(draw: st.DrawFn) -> tuple[_Report, str]:
    source = "\n".join(draw(st.lists(_TEXT, min_size=1, max_size=4)))
    findings = []
    for _ in range(draw(st.integers(0, 3))):
        line, col = draw(st.integers(1, 5)), draw(st.integers(1, 40))
        span = Span(FILE, line, col, line + draw(st.integers(0, 1)), col + draw(st.integers(0, 40)))
        related = tuple(Related(span, m) for m in draw(st.lists(_TEXT, max_size=2)))
        findings.append(Finding("N101", "duplicate-node-name", draw(st.sampled_from(["error", "warning", "note"])),
                                span, draw(_TEXT), draw(st.none() | _TEXT), related, ""))
    return _Report(findings, [FILE], baseline_suppressed=draw(st.integers(0, 2))), source


@settings(max_examples=1000, deadline=None)
@given(_reports(), st.booleans(), st.booleans())
def test_plain_text_is_what_rich_prints(drawn: tuple[_Report, str], show_source: bool, quiet: bool) -> None:
    report, source = drawn
    kw = {"show_source": show_source, "quiet": quiet, "read_source": lambda _p: source}
    rich = text.render_rich(report, **kw)  # type: ignore[arg-type]
    assert text.render(report, {}, **kw) == rich  # type: ignore[arg-type]
    assert text.render_plain(report, **kw) == rich  # type: ignore[arg-type]
