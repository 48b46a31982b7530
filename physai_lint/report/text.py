"""``--format text``: what a person reads in a terminal.

    launch/robot.launch.py:12:18: N101 [duplicate-node-name] duplicate node name "/talker"
       |
    12 |     Node(package="demo", name="talker"),
       |                               ^^^^^^^^
       = help: give one of the nodes another name
       = note: launch/robot.launch.py:8:31: first defined here

Colour is decided by the caller (``color=True`` only on a TTY without ``NO_COLOR``). Without colour
the report is built as plain text, which is what rich prints then (control codes stripped, no
wrapping, tabs expanded by cell width); rich, ~15-20 ms to import, is used for colour and
``--statistics``.
"""
from __future__ import annotations

import io
from collections import Counter
from typing import Any, Callable, Mapping

from physai_lint.model.findings import Finding
from physai_lint.report import ReportLike, counts, ordered, plural, rel

SourceReader = Callable[[str], "str | None"]
_SEVERITY_STYLE = {"error": "bold red", "warning": "bold yellow", "note": "bold cyan"}


def read_file(path: str) -> str | None:
    try:
        with open(path, encoding="utf-8", errors="replace") as fh:
            return fh.read()
    except OSError:
        return None


def render(
    report: ReportLike,
    catalog: Mapping[str, Any],
    *,
    color: bool = False,
    show_source: bool = True,
    statistics: bool = False,
    quiet: bool = False,
    read_source: SourceReader | None = None,
    **_: Any,
) -> str:
    if not color and not statistics:
        return render_plain(report, show_source=show_source, quiet=quiet, read_source=read_source)
    return render_rich(report, color=color, show_source=show_source, statistics=statistics, quiet=quiet,
                       read_source=read_source)


def render_plain(
    report: ReportLike, *, show_source: bool = True, quiet: bool = False, read_source: SourceReader | None = None
) -> str:
    """The report without colour, built as plain text: what ``render_rich`` prints without colour."""
    console = _PlainConsole()
    _render(console, _PlainText, report, show_source, False, quiet, read_source)
    return console.file.getvalue()


def render_rich(
    report: ReportLike,
    *,
    color: bool = False,
    show_source: bool = True,
    statistics: bool = False,
    quiet: bool = False,
    read_source: SourceReader | None = None,
) -> str:
    from rich.console import Console
    from rich.text import Text

    buf = io.StringIO()
    console = Console(
        file=buf,
        force_terminal=color,
        no_color=not color,
        color_system="standard" if color else None,
        highlight=False,
        soft_wrap=True,
        emoji=False,
        markup=False,
        width=100,
    )
    _render(console, Text, report, show_source, statistics, quiet, read_source)
    return buf.getvalue()


def _render(
    console: Any, Text: Any, report: ReportLike, show_source: bool, statistics: bool, quiet: bool,
    read_source: SourceReader | None,
) -> None:
    findings = ordered(report)
    if statistics:
        _statistics(console, findings)
    else:
        lines_of = _source_cache(read_source or read_file)
        for f in findings:
            _finding(console, f, report.cwd, lines_of if show_source else None, Text)
    if not quiet:
        console.print(Text(summary(report, findings), style="bold" if findings else "bold green"))


# rich.control.STRIP_CONTROL_CODES: bell, backspace, vertical tab, form feed, carriage return
_STRIP = dict.fromkeys((7, 8, 11, 12, 13))


class _PlainText:
    """The part of ``rich.text.Text`` the report uses, without styles."""

    def __init__(self, text: str = "", style: str | None = None) -> None:
        self.plain = text.translate(_STRIP)

    def append(self, text: str, style: str | None = None) -> _PlainText:
        self.plain += text.translate(_STRIP)
        return self


class _PlainConsole:
    """The part of ``rich.console.Console`` the report uses: one line per ``print``."""

    def __init__(self) -> None:
        self.file = io.StringIO()

    def print(self, text: _PlainText | None = None) -> None:
        plain = text.plain if text is not None else ""
        if "\t" in plain:
            plain = "\n".join(_expand_tabs(line) for line in plain.split("\n"))
        self.file.write(f"{plain}\n")


def _expand_tabs(line: str, tab_size: int = 8) -> str:
    """A tab as ``rich.text.Text.expand_tabs`` prints it: a space, then up to the next multiple of
    ``tab_size`` cells (wide characters count two)."""
    if line.isascii() and line.replace("\t", "").isprintable():  # else: control codes are 0 cells
        return line.expandtabs(tab_size)
    from rich.cells import cell_len

    out, position = [], 0
    parts = line.split("\t")
    for part in parts[:-1]:
        position += cell_len(part) + 1
        spaces = -position % tab_size
        position += spaces
        out.append(part + " " * (1 + spaces))
    out.append(parts[-1])
    return "".join(out)


def summary(report: ReportLike, findings: list[Finding]) -> str:
    n_files = len(report.files)
    suppressed = (
        f" ({plural(report.baseline_suppressed, 'finding')} hidden by the baseline)" if report.baseline_suppressed else ""
    )
    if not findings:
        return f"All checks passed! ({plural(n_files, 'file')}){suppressed}"
    c = counts(findings)
    notes = f" ({plural(c['note'], 'note')})" if c["note"] else ""
    return f"Found {plural(c['error'], 'error')}, {plural(c['warning'], 'warning')}{notes} in {plural(n_files, 'file')}.{suppressed}"


def _source_cache(reader: SourceReader) -> Callable[[str], list[str] | None]:
    cache: dict[str, list[str] | None] = {}

    def lines_of(path: str) -> list[str] | None:
        if path not in cache:
            text = reader(path)
            cache[path] = None if text is None else text.splitlines()
        return cache[path]

    return lines_of


def _finding(console: Any, f: Finding, cwd: str, lines_of: Callable[[str], list[str] | None] | None, Text: Any) -> None:
    head = Text()
    head.append(f"{rel(f.span.file, cwd)}:{f.span.line}:{f.span.col}:", style="bold")
    head.append(" ")
    head.append(f.code, style=_SEVERITY_STYLE[f.severity])
    head.append(f" [{f.name}]", style="dim")
    head.append(" " + " ".join(f.message.split()))
    console.print(head)
    lines = lines_of(f.span.file) if lines_of else None
    gutter = len(str(f.span.line))
    if lines is not None and 1 <= f.span.line <= len(lines):
        source = lines[f.span.line - 1].rstrip("\r\n")
        start = min(f.span.col, len(source) + 1)
        end = f.span.end_col if f.span.end_line == f.span.line else len(source) + 1
        width = max(end - start, 1)
        pad = "".join(ch if ch == "\t" else " " for ch in source[: start - 1])
        bar = " " * gutter + " |"
        console.print(Text(bar, style="blue"))
        line = Text(f"{f.span.line} | ", style="blue")
        line.append(source)
        console.print(line)
        marks = Text(bar + " ", style="blue")
        marks.append(pad + "^" * width, style=_SEVERITY_STYLE[f.severity])
        console.print(marks)
    indent = " " * gutter + " = " if lines is not None else "  = "
    if f.help:
        console.print(Text(indent).append("help", style="bold").append(f": {f.help}"))
    for r in f.related:
        where = f"{rel(r.span.file, cwd)}:{r.span.line}:{r.span.col}"
        console.print(Text(indent).append("note", style="bold").append(f": {where}: {r.message}"))
    console.print()


def _statistics(console: Any, findings: list[Finding]) -> None:
    from rich import box
    from rich.table import Table

    by_code = Counter((f.code, f.name, f.severity) for f in findings)
    table = Table(box=box.SIMPLE_HEAD, show_edge=False, pad_edge=False)
    for header, justify in (("count", "right"), ("code", "left"), ("name", "left"), ("severity", "left")):
        table.add_column(header, justify=justify)  # type: ignore[arg-type]
    for (code, name, severity), n in sorted(by_code.items(), key=lambda kv: (-kv[1], kv[0])):
        table.add_row(str(n), code, name, severity)
    if findings:
        console.print(table)
