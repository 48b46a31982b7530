"""Glob patterns as regular expressions: Python ``glob``, CMake ``PATTERN`` and ``.gitignore`` share
one translator so that ``*`` never crosses a ``/`` and ``**`` spans directories."""
from __future__ import annotations

import re
from collections.abc import Collection
from functools import lru_cache


def _translate(pat: str, recursive: bool) -> str:
    out: list[str] = []
    i, n = 0, len(pat)
    while i < n:
        c = pat[i]
        if c == "*":
            if recursive and pat.startswith("**", i):
                # "**/" -> zero or more directories; trailing "**" -> anything
                j = i + 2
                at_seg_start = i == 0 or pat[i - 1] == "/"
                if at_seg_start and j < n and pat[j] == "/":
                    out.append("(?:[^/]*/)*")
                    i = j + 1
                    continue
                if at_seg_start and j == n:
                    out.append(".*")
                    i = j
                    continue
            out.append("[^/]*")
            while i < n and pat[i] == "*":
                i += 1
            continue
        if c == "?":
            out.append("[^/]")
        elif c == "[":
            j = i + 1
            if j < n and pat[j] in "!^":
                j += 1
            if j < n and pat[j] == "]":
                j += 1
            while j < n and pat[j] != "]":
                j += 1
            if j >= n:
                out.append("\\[")
            else:
                body = pat[i + 1 : j].replace("\\", "\\\\")
                if body[:1] in ("!", "^"):
                    body = "^" + body[1:]
                out.append("[" + body + "]")
                i = j
        elif c == "\\" and i + 1 < n:
            i += 1
            out.append(re.escape(pat[i]))
        else:
            out.append(re.escape(c))
        i += 1
    return "".join(out)


@lru_cache(maxsize=2048)
def compile_glob(pat: str, recursive: bool = True) -> re.Pattern[str]:
    """A full-match regex for ``pat`` over ``/``-separated relative paths."""
    return re.compile(r"(?s:" + _translate(pat, recursive) + r")\Z")


def has_magic(pat: str) -> bool:
    return any(ch in pat for ch in "*?[")


def glob_files(pattern: str, files: Collection[str], recursive: bool = False) -> list[str]:
    """Evaluate a Python ``glob.glob(pattern)`` (relative to a package dir) against a snapshot of
    the package's files (relative ``/`` paths). Like ``glob``, ``*`` does not match a leading dot
    unless the pattern segment starts with one. Returns sorted matches (files only)."""
    pattern = pattern.replace("\\", "/")
    while pattern.startswith("./"):
        pattern = pattern[2:]
    if not has_magic(pattern):
        return [pattern] if pattern in files else []
    rx = compile_glob(pattern, recursive)
    segs = pattern.split("/")
    out = []
    for f in files:
        if not rx.match(f):
            continue
        # hidden files are only matched by a segment starting with "."
        parts = f.split("/")
        hidden = False
        for k, part in enumerate(parts):
            if part.startswith("."):
                seg = segs[k] if k < len(segs) else ""
                if not seg.startswith("."):
                    hidden = True
                    break
        if not hidden:
            out.append(f)
    return sorted(out)
