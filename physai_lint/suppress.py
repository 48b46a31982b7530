"""Inline suppressions.

- ``# physai-lint: ignore[N101,unknown-package]`` (Python, YAML) or
  ``<!-- physai-lint: ignore[N101] -->`` (XML) on the offending line; on a line of its own it
  applies to the next line holding something else than comments;
- ``ignore N101, P103`` (without brackets) is accepted too;
- ``ignore-file[...]`` anywhere suppresses those rules in the whole file;
- ``# noqa: N101`` in Python. Other linters share that comment, so codes we do not know are left
  alone and an unused ``noqa`` is never reported.

``apply`` reports suppressions that matched nothing (X004) and malformed ones (X005).
"""
from __future__ import annotations

import re
from dataclasses import dataclass
from typing import Any, Callable, Literal, Mapping

from physai_lint.model.findings import Diagnostic, Finding
from physai_lint.model.pickling import fast_pickle_module
from physai_lint.model.span import Span

Format = Literal["python", "xml", "yaml"]
_TOKEN = r"[A-Za-z][A-Za-z0-9]*(?:-[A-Za-z0-9]+)*"
_BODY = (
    r"physai-lint\s*:\s*(?P<kind>ignore-file|ignore)\b"
    rf"(?:\s*\[(?P<br>[^\]]*)\]|\s+(?P<sp>{_TOKEN}(?:\s*,\s*{_TOKEN})*))?"
)
_HASH = re.compile(r"#\s*" + _BODY)
_XML = re.compile(r"<!--\s*" + _BODY + r"[^>]*?-->")
_NOQA = re.compile(r"#\s*noqa\s*:\s*(?P<sp>[A-Z][0-9]+(?:[\s,]+[A-Z][0-9]+)*)", re.IGNORECASE)
_CODE = re.compile(r"^[A-Z][0-9]{3}$")


@dataclass(frozen=True, slots=True)
class Directive:
    span: Span  # where the comment is
    scope: Literal["line", "file"]
    target_line: int  # the line it applies to (0 for file scope)
    tokens: tuple[str, ...]  # codes or names, as written
    style: Literal["physai-lint", "noqa"] = "physai-lint"


@dataclass(frozen=True, slots=True)
class Directives:
    path: str
    items: tuple[Directive, ...] = ()


def _comment_only(line: str, fmt: Format) -> bool:
    s = line.strip()
    if fmt == "xml":
        return s.startswith("<!--") and s.endswith("-->")
    return s.startswith("#")


def parse_directives(path: str, text: str, fmt: Format) -> Directives:
    """Every suppression comment of one file."""
    if "physai-lint" not in text and (fmt != "python" or "noqa" not in text.lower()):
        return Directives(path)
    lines = text.splitlines()
    items: list[Directive] = []
    pattern = _XML if fmt == "xml" else _HASH
    for idx, line in enumerate(lines):
        lineno = idx + 1
        found = [(m, "physai-lint") for m in pattern.finditer(line)]
        if fmt == "python":
            found += [(m, "noqa") for m in _NOQA.finditer(line)]
        for match, style in found:
            span = Span(path, lineno, match.start() + 1, lineno, match.end() + 1)
            raw = match.group("br") if style == "physai-lint" and match.group("br") is not None else match.group("sp")
            tokens = tuple(t for t in re.split(r"[\s,]+", raw or "") if t)
            if style == "physai-lint" and match.group("kind") == "ignore-file":
                items.append(Directive(span, "file", 0, tokens))
                continue
            target = lineno
            if _comment_only(line, fmt):
                target = _next_code_line(lines, idx + 1, fmt)
            items.append(Directive(span, "line", target, tokens, style))  # type: ignore[arg-type]
    return Directives(path, tuple(items))


def _next_code_line(lines: list[str], start: int, fmt: Format) -> int:
    for idx in range(start, len(lines)):
        if lines[idx].strip() and not _comment_only(lines[idx], fmt):
            return idx + 1
    return start + 1


def apply(
    findings: list[Finding],
    directives: Mapping[str, Directives],
    catalog: Mapping[str, Any],
    *,
    enabled: Callable[[str], bool] | None = None,
) -> tuple[list[Finding], list[Diagnostic]]:
    """Drop suppressed findings; report unused (X004) and invalid (X005) suppressions.

    ``enabled`` (optional) tells which rules ran: a suppression of a rule that did not run is not
    reported as unused.
    """
    names = {str(getattr(doc, "name", "")): code for code, doc in catalog.items()}
    new: list[Diagnostic] = []
    # (path, directive index, code) -> used?
    used: dict[tuple[str, int, str], bool] = {}
    line_index: dict[tuple[str, int, str], list[tuple[str, int, str]]] = {}
    file_index: dict[tuple[str, str], list[tuple[str, int, str]]] = {}
    for path, dirs in sorted(directives.items()):
        for i, d in enumerate(dirs.items):
            if not d.tokens and d.style == "physai-lint":
                new.append(_invalid(d, "suppression comment names no rule", "name the rules: \"physai-lint: ignore[N101]\""))
                continue
            for token in d.tokens:
                code = _resolve(token, catalog, names)
                if code is None:
                    if d.style == "physai-lint":
                        new.append(_unknown(d, token, catalog, names))
                    continue
                slot = (path, i, code)
                used.setdefault(slot, False)
                if d.scope == "file":
                    file_index.setdefault((path, code), []).append(slot)
                else:
                    line_index.setdefault((path, d.target_line, code), []).append(slot)
    kept: list[Finding] = []
    for f in findings:
        slots = line_index.get((f.span.file, f.span.line, f.code)) or file_index.get((f.span.file, f.code))
        if slots:
            used[slots[0]] = True
        else:
            kept.append(f)
    for (path, i, code), was_used in sorted(used.items()):
        d = directives[path].items[i]
        if was_used or d.style == "noqa" or (enabled is not None and not enabled(code)):
            continue
        name = str(getattr(catalog.get(code), "name", "") or "")
        label = f'"{code}"' + (f" ({name})" if name else "")
        new.append(
            Diagnostic(
                code="X004",
                span=d.span,
                message=f"unused suppression for {label}: no such finding "
                + ("in this file" if d.scope == "file" else f"on line {d.target_line}"),
                help="remove the rule from the suppression comment",
                key=f"unused:{d.scope}:{code}",
            )
        )
    new.sort(key=lambda dg: (dg.span.file, dg.span.line, dg.span.col, dg.code, dg.message))
    return kept, new


def _resolve(token: str, catalog: Mapping[str, Any], names: Mapping[str, str]) -> str | None:
    if token.upper() in catalog:
        return token.upper()
    if token.lower() in names:
        return names[token.lower()]
    if not catalog and _CODE.match(token.upper()):
        return token.upper()
    return None


def _invalid(d: Directive, message: str, help: str, key: str = "bare") -> Diagnostic:
    return Diagnostic(code="X005", span=d.span, message=message, help=help, key=f"invalid:{key}")


def _unknown(d: Directive, token: str, catalog: Mapping[str, Any], names: Mapping[str, str]) -> Diagnostic:
    from physai_lint.catalog import suggest

    hint = suggest(token, [*catalog, *names])
    help = f'did you mean "{hint}"?' if hint else "use a rule code such as \"N101\" or a rule name"
    return _invalid(d, f'unknown rule "{token}" in suppression comment', help, key=token)


fast_pickle_module(globals())  # tuples instead of dataclasses.fields() per object (model/pickling.py)
