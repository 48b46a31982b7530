"""Reading and parsing files, once each, with bounds: the engine's file loader.

Bad input becomes a finding here (X002 unreadable-file: binary, undecodable, too large, unreadable)
and never a traceback; each frontend is called at most once per file per run.
"""
from __future__ import annotations

import os
from collections.abc import Callable
from dataclasses import dataclass, field

from physai_lint.model.findings import Diagnostic
from physai_lint.model.launch import LaunchFile
from physai_lint.model.span import Span

MAX_FILE_BYTES = 64 * 1024 * 1024


def launch_format(path: str) -> str | None:
    """The frontend for a path by extension (``AnyLaunchDescriptionSource`` picks by extension)."""
    low = path.lower()
    if low.endswith(".py"):
        return "python"
    if low.endswith(".xml"):
        return "xml"
    if low.endswith((".yaml", ".yml")):
        return "yaml"
    return None


@dataclass
class FileStore:
    """Texts and parse results, keyed by absolute path; diagnostics collected per file."""

    texts: dict[str, str | None] = field(default_factory=dict)
    launches: dict[str, LaunchFile | None] = field(default_factory=dict)
    diagnostics: list[Diagnostic] = field(default_factory=list)
    failed: set[str] = field(default_factory=set)

    def text(self, path: str) -> str | None:
        if path in self.texts:
            return self.texts[path]
        self.texts[path] = text = self._read(path)
        return text

    def _read(self, path: str) -> str | None:
        span = Span.whole_file(path)
        try:
            size = os.path.getsize(path)
            if size > MAX_FILE_BYTES:
                self._fail(path, span, f"file is {size // (1024 * 1024)} MiB, larger than the "
                           f"{MAX_FILE_BYTES // (1024 * 1024)} MiB limit")
                return None
            with open(path, "rb") as fh:
                data = fh.read(MAX_FILE_BYTES + 1)
        except OSError as exc:
            self._fail(path, span, f"cannot read file: {exc.strerror or exc}")
            return None
        if b"\0" in data[:8192] or b"\0" in data:
            self._fail(path, span, "file is binary (contains NUL bytes)")
            return None
        try:
            text = data.decode("utf-8")
        except UnicodeDecodeError as exc:
            line = data[: exc.start].count(b"\n") + 1
            col = exc.start - (data.rfind(b"\n", 0, exc.start) + 1) + 1
            self._fail(path, Span.point(path, line, col),
                       f"file is not valid UTF-8: byte 0x{data[exc.start]:02x} at line {line}, column {col}")
            return None
        return text.removeprefix("\ufeff")

    def _fail(self, path: str, span: Span, message: str) -> None:
        self.failed.add(path)
        self.diagnostics.append(Diagnostic("X002", span, message,
                                           help="make it a UTF-8 text file, or exclude it from the check",
                                           key=message.split(":")[0]))

    def launch(self, path: str, reader: Callable[[str], str | None] | None = None) -> LaunchFile | None:
        if path in self.launches:
            return self.launches[path]
        self.launches[path] = None  # guards against re-entry while parsing
        text = self.text(path)
        result = None
        if text is not None:
            result = parse_launch_text(path, text, reader or self.text, self.diagnostics)
        self.launches[path] = result
        return result


def parse_launch_text(path: str, text: str, reader: Callable[[str], str | None],
                      sink: list[Diagnostic]) -> LaunchFile | None:
    fmt = launch_format(path)
    try:
        if fmt == "python":
            from physai_lint.frontends.python import parse_python_launch

            res = parse_python_launch(path, text, reader)
        elif fmt == "xml":
            from physai_lint.frontends.xml_launch import parse_xml_launch

            res = parse_xml_launch(path, text)
        elif fmt == "yaml":
            from physai_lint.frontends.yaml_launch import parse_yaml_launch

            res = parse_yaml_launch(path, text)
        else:
            return None
    except RecursionError:
        sink.append(Diagnostic("X001", Span.whole_file(path),
                               "file is nested too deeply to analyse",
                               help="split deeply nested expressions into smaller pieces"))
        return None
    except Exception as exc:  # a crash is a bug and a finding, never a traceback
        sink.append(internal_error(path, f"{fmt} frontend", exc))
        return None
    sink.extend(res.diagnostics)
    return res.launch


def internal_error(path: str, where: str, exc: BaseException) -> Diagnostic:
    return Diagnostic(
        "X003", Span.whole_file(path),
        f"internal error in {where}: {type(exc).__name__}: {exc}",
        help="this is a bug in physai-lint; please report it with the file that triggers it",
        key=f"{where}:{type(exc).__name__}",
    )
