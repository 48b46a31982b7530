"""Reading and parsing files, once each, with bounds: the engine's file loader.

Bad input becomes a finding here (X002 unreadable-file: binary, undecodable, too large, unreadable)
and never a traceback; each frontend is called at most once per file per run. ``preload`` parses
many files up front: from the disk cache (``cache.py``) when their content was seen before, else in
a process pool when there are enough of them (``parallel.py``), always merged in path order so the
output does not depend on the number of jobs.
"""
from __future__ import annotations

import os
from collections.abc import Callable, Iterable
from dataclasses import dataclass, field
from typing import Any

from physai_lint.bounded_read import read_at_most
from physai_lint.model.findings import Diagnostic
from physai_lint.model.launch import LaunchFile
from physai_lint.model.span import Span
from physai_lint.sniff import format_by_name, launch_format

MAX_FILE_BYTES = 64 * 1024 * 1024


def _size(n: int) -> str:
    mib = 1024 * 1024
    if n % mib == 0:
        return f"{n // mib} MiB"
    return f"{n / mib:.1f} MiB" if n >= mib else f"{n:,} bytes"


@dataclass
class FileStore:
    """Texts and parse results, keyed by absolute path; diagnostics collected per file."""

    texts: dict[str, str | None] = field(default_factory=dict)
    launches: dict[str, LaunchFile | None] = field(default_factory=dict)
    diagnostics: list[Diagnostic] = field(default_factory=list)
    failed: set[str] = field(default_factory=set)
    params: dict[str, Any] = field(default_factory=dict)  # path -> ParamFile model or None
    param_diagnostics: list[Diagnostic] = field(default_factory=list)  # crashes of the param loader
    cache: Any = None  # a cache.ParseCache, or None
    distro: str = ""  # what Python launch files read as ROS_DISTRO; set by preload
    max_bytes: int = MAX_FILE_BYTES  # larger files are reported (X002's ``max-bytes``), not read
    # (path, action id, known values) -> an OpaqueFunction evaluated again (``specialize``)
    specialized: dict[Any, Any] = field(default_factory=dict)

    def text(self, path: str) -> str | None:
        if path in self.texts:
            return self.texts[path]
        self.texts[path] = text = self._read(path, self._fail)
        return text

    def peek(self, path: str) -> str | None:
        """The text of a file that may not be checked at all: read and kept like ``text``, but a
        file that cannot be read is neither reported nor remembered (``text`` reports it if the
        file is checked after all, an include of it say)."""
        if path in self.texts:
            return self.texts[path]
        text = self._read(path, lambda *_: None)
        if text is not None:
            self.texts[path] = text
        return text

    def _read(self, path: str, fail: Callable[[str, Span, str], None]) -> str | None:
        span = Span.whole_file(path)
        try:
            size = os.path.getsize(path)
            if size > self.max_bytes:
                fail(path, span, f"file is {_size(size)}, larger than the {_size(self.max_bytes)} limit")
                return None
            with open(path, "rb") as fh:
                data = read_at_most(fh, self.max_bytes)
        except OSError as exc:
            fail(path, span, f"cannot read file: {exc.strerror or exc}")
            return None
        if b"\0" in data[:8192] or b"\0" in data:
            fail(path, span, "file is binary (contains NUL bytes)")
            return None
        try:
            text = data.decode("utf-8")
        except UnicodeDecodeError as exc:
            line = data[: exc.start].count(b"\n") + 1
            col = exc.start - (data.rfind(b"\n", 0, exc.start) + 1) + 1
            fail(path, Span.point(path, line, col),
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
        if text is not None:  # any file: ros2 launch loads what an include names, whatever its name
            job = Job("launch", path, text, self.distro)
            value = self._cached(job)
            if value is None:
                value, ok = run_job(job, reader or self.text)
                self._store(job, value, ok)
            result = self._accept(job, value)
        self.launches[path] = result
        return result

    def specialize(self, path: str, action: Any, known: tuple[tuple[Any, str], ...],
                   reader: Callable[[str], str | None] | None = None) -> Any:
        """The OpaqueFunction ``action`` of Python launch file ``path`` evaluated again with the
        strings ``known`` for what it performs (``frontends.python.specialize``), or None; memoised
        per (file, action, values): an include used twice with the same arguments evaluates once."""
        key = (path, action.id, known)
        try:
            return self.specialized[key]
        except KeyError:
            pass
        except TypeError:  # an unhashable value: not memoised
            key = None
        result = None
        text = self.text(path)
        if text is not None and launch_format(path, text) == "python":
            from physai_lint.frontends.python import specialize

            if reader is None:
                from physai_lint.workspace.index import read_text_file as reader
            try:
                result = specialize(path, text, reader, self.distro or None, known, action)
            except (RecursionError, MemoryError):  # too deep or too large: it stays opaque
                result = None
        if key is not None:
            self.specialized[key] = result
        return result

    def param_file(self, path: str, distro: str) -> Any:
        """The parameter file model (``params.loader.ParamFile``), or None when unreadable."""
        if path in self.params:
            return self.params[path]
        text = self.text(path)
        model = None
        if text is not None:
            job = Job("params", path, text, distro)
            value = self._cached(job)
            if value is None:
                value, ok = run_job(job, None)
                self._store(job, value, ok)
            model = self._accept(job, value)
        self.params[path] = model
        return model

    def preload(self, launches: Iterable[str], params: Iterable[str], distro: str, jobs: int,
                progress: Any = None, side: Any = None) -> None:
        """Parse these files now: cached ones from disk, the others in a pool when worth it
        (``side``: other items for the same helpers, see ``parallel.map_jobs``)."""
        from physai_lint import parallel

        self.distro = distro
        todo = [Job("launch", p, "", distro) for p in sorted(set(launches)) if p not in self.launches]
        todo += [Job("params", p, "", distro) for p in sorted(set(params)) if p not in self.params]
        misses: list[Job] = []
        for job in todo:
            text = self.text(job.path)
            if text is None:
                continue
            full = Job(job.kind, job.path, text, job.distro)
            value = self._cached(full)
            if value is None:
                misses.append(full)
            else:
                self._preloaded(full, value)
        if progress is not None:
            progress.stage("parsing", len(misses))
        import_parsers(misses)  # here, once: forked helpers inherit them instead of importing them
        for job, (value, ok, data) in zip(misses, parallel.map_jobs(misses, jobs, progress, side)):
            self._store(job, value, ok, data)
            self._preloaded(job, value)

    def _preloaded(self, job: Job, value: Any) -> None:
        result = self._accept(job, value)
        if job.kind == "launch":
            self.launches[job.path] = result
        else:
            self.params[job.path] = result

    def _cached(self, job: Job) -> Any:
        if self.cache is None:
            return None
        from physai_lint.cache import loads

        data = self.cache.get_bytes(self.cache.key(job.kind, job.path, job.text, job.distro))
        value = loads(data) if data is not None else None
        return value if _well_formed(value) else None

    def _store(self, job: Job, value: Any, cacheable: bool, data: bytes | None = None) -> None:
        if self.cache is None or not cacheable or not self.cache.enabled:
            return
        from physai_lint.cache import dumps

        data = data if data is not None else dumps(value)
        if data is not None:
            self.cache.put_bytes(self.cache.key(job.kind, job.path, job.text, job.distro), data)

    def _accept(self, job: Job, value: Any) -> Any:
        """Record a job's diagnostics; return its launch IR or parameter model."""
        result, diags = value
        if job.kind == "launch":
            self.diagnostics.extend(diags)
        else:
            self.param_diagnostics.extend(diags)
        return result


@dataclass(frozen=True)
class Job:
    """One file to parse: ``kind`` is "launch" or "params"; ``distro`` is part of the cache key
    (parameter typing and ``ROS_DISTRO`` in Python launch files depend on it)."""

    kind: str
    path: str
    text: str
    distro: str = ""


def import_parsers(jobs: Iterable[Job]) -> None:
    """Import the parsers ``jobs`` need, as ``run_job`` would on its first job of each kind.

    Imported before parsing starts, they are shared with the helpers ``parallel.map_jobs`` forks;
    imported by the first job, each process imported them again (the Python frontend, the markup
    frontends and the parameter loader: ~0.1 s of CPU per helper)."""
    from importlib import import_module

    kinds = {"params" if job.kind == "params" else launch_format(job.path, job.text) for job in jobs}
    for kind, module in (("params", "physai_lint.params.loader"), ("python", "physai_lint.frontends.python"),
                         ("xml", "physai_lint.frontends.xml_launch"), ("yaml", "physai_lint.frontends.yaml_launch")):
        if kind in kinds:
            import_module(module)


def run_job(job: Job, reader: Callable[[str], str | None] | None) -> tuple[Any, bool]:
    """((result, diagnostics), cacheable): a parse that is a pure function of the job.

    Not cacheable: results of a crash (X003: worth retrying with fixed code) and Python launch
    files that read other files (helper modules, YAML loaded at launch time) while evaluated.
    """
    diags: list[Diagnostic] = []
    if job.kind == "params":
        from physai_lint.params.loader import load_param_file

        try:
            return (load_param_file(job.path, job.text, job.distro), diags), True
        except Exception as exc:  # noqa: BLE001 - a crash is a finding, not a traceback
            diags.append(internal_error(job.path, "parameter file parser", exc))
            return (None, diags), False
    reads: list[str] = []

    def recording(path: str) -> str | None:
        reads.append(path)
        return read(path)

    read: Callable[[str], str | None]
    if reader is None:
        from physai_lint.workspace.index import read_text_file

        read = read_text_file
    else:
        read = reader
    result = parse_launch_text(job.path, job.text, recording, diags, job.distro)
    return (result, diags), not reads and not any(d.code == "X003" for d in diags)


def _well_formed(value: Any) -> bool:
    return isinstance(value, tuple) and len(value) == 2 and isinstance(value[1], list)


# The largest launch file in a corpus of public ROS 2 repositories is ~40 kB. A 50 MB one needed
# more than 6 GB (a .py file's AST) or more than 2 GB and 200 s (an XML element tree and positions).
MAX_LAUNCH_CHARS = 2_000_000


def parse_launch_text(path: str, text: str, reader: Callable[[str], str | None],
                      sink: list[Diagnostic], distro: str = "") -> LaunchFile | None:
    """Parse a launch file with the frontend ``ros2 launch`` would load it with (by extension, else
    by its text: ``sniff.launch_format``); its diagnostics go to ``sink``."""
    if len(text) > MAX_LAUNCH_CHARS:
        sink.append(Diagnostic(
            "X002", Span.whole_file(path),
            f"file is {len(text) // 1_000_000} MB, larger than the {MAX_LAUNCH_CHARS // 1_000_000} MB "
            f"limit for launch files",
            help="split the launch file, or exclude it from the check", key="file is too large"))
        return None
    fmt = launch_format(path, text)
    try:
        if fmt == "python":
            from physai_lint.frontends.python import parse_python_launch

            res = parse_python_launch(path, text, reader, distro or None)
        elif fmt == "xml":
            from physai_lint.frontends.xml_launch import parse_xml_launch

            res = parse_xml_launch(path, text)
        else:
            from physai_lint.frontends.yaml_launch import parse_yaml_launch

            res = parse_yaml_launch(path, text)
    except RecursionError:
        sink.append(Diagnostic("X001", Span.whole_file(path),
                               "file is nested too deeply to analyse",
                               help="split deeply nested expressions into smaller pieces"))
        return None
    except Exception as exc:  # a crash is a bug and a finding, never a traceback
        sink.append(internal_error(path, f"{fmt} frontend", exc))
        return None
    if fmt == "python" and res.launch is None and format_by_name(path) is None:  # Python as the last resort
        sink.extend(_no_loader(path, d) if d.code == "X001" else d for d in res.diagnostics)
    else:
        sink.extend(res.diagnostics)
    return res.launch


def _no_loader(path: str, d: Diagnostic) -> Diagnostic:
    """A file of no launch extension that no loader takes: say so, as launch's
    ``InvalidLaunchFileError`` does, rather than only that it is not valid Python."""
    from dataclasses import replace

    return replace(d, message=f'no launch frontend can load "{os.path.basename(path)}": it is neither '
                              f'XML, nor YAML with a "launch" key, nor Python ({d.message})',
                   help="ros2 launch fails to load it (InvalidLaunchFileError); name launch files "
                        "*.launch.py, *.launch.xml or *.launch.yaml")


def internal_error(path: str, where: str, exc: BaseException) -> Diagnostic:
    return Diagnostic(
        "X003", Span.whole_file(path),
        f"internal error in {where}: {type(exc).__name__}: {exc}",
        help="this is a bug in physai-lint; please report it with the file that triggers it",
        key=f"{where}:{type(exc).__name__}",
    )
