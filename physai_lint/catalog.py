"""The rule catalog: ``rules/<Letter>/<CODE>-<name>.md`` files (YAML front matter + Markdown docs).

Installed, the folder is the package data ``physai_lint._rules``; in a source checkout it is the
top-level ``rules/`` folder. ``PHYSAI_LINT_RULES_DIR`` overrides both (tests, docs previews).
"""
from __future__ import annotations

import os
import re
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Iterable

SECTION_TITLES = (
    "What it does",
    "Why is this bad?",
    "Example",
    "Use instead",
    "Options",
    "References",
)
_FRONT_MATTER = re.compile(r"\A---[ \t]*\r?\n(.*?)\r?\n---[ \t]*\r?\n?", re.DOTALL)
_SECTION = re.compile(r"^## +(.+?)[ \t]*$", re.MULTILINE)
_FENCE = re.compile(r"^(```|~~~)")
_FILE_NAME = re.compile(r"^[A-Z][0-9]{3}-[a-z0-9-]+\.md$")


@dataclass(frozen=True)
class RuleDoc:
    code: str
    name: str
    category: str
    severity: str
    summary: str
    markdown: str  # the body after the front matter
    sections: dict[str, str]
    path: str
    since: str = ""
    producer: str = ""
    options: dict[str, Any] | None = None
    precision: str = "high"
    meta: dict[str, Any] = field(default_factory=dict)


def rules_dir() -> Path:
    """Where the catalog lives: ``$PHYSAI_LINT_RULES_DIR``, the installed package data, or ``<repo>/rules``."""
    override = os.environ.get("PHYSAI_LINT_RULES_DIR")
    if override:
        return Path(override)
    from physai_lint.resources import data_dir

    return data_dir("_rules")


def split_sections(body: str) -> dict[str, str]:
    """``## Title`` sections of a Markdown body (headings inside code fences are ignored)."""
    sections: dict[str, str] = {}
    title: str | None = None
    lines: list[str] = []
    in_fence = False
    for line in body.splitlines():
        if _FENCE.match(line.lstrip()):
            in_fence = not in_fence
        match = None if in_fence else _SECTION.match(line)
        if match:
            if title is not None:
                sections[title] = "\n".join(lines).strip()
            title, lines = match.group(1), []
        elif title is not None:
            lines.append(line)
    if title is not None:
        sections[title] = "\n".join(lines).strip()
    return sections


def parse_rule_doc(path: Path) -> RuleDoc:
    """Read one catalog file; raises ``ValueError`` naming the file when it is malformed."""
    import yaml

    text = path.read_text(encoding="utf-8")
    match = _FRONT_MATTER.match(text)
    if not match:
        raise ValueError(f"{path}: missing YAML front matter")
    # libyaml when present: the pure-Python loader made reading the catalog half of a one-file run.
    meta = yaml.load(match.group(1), Loader=getattr(yaml, "CSafeLoader", yaml.SafeLoader)) or {}
    if not isinstance(meta, dict):
        raise ValueError(f"{path}: front matter is not a mapping")
    for key in ("code", "name", "severity", "summary"):
        if not meta.get(key):
            raise ValueError(f"{path}: front matter lacks {key!r}")
    body = text[match.end():].lstrip("\n")
    code = str(meta["code"])
    return RuleDoc(
        code=code,
        name=str(meta["name"]),
        category=str(meta.get("category") or code[0]),
        severity=str(meta["severity"]),
        summary=" ".join(str(meta["summary"]).split()),
        markdown=body,
        sections=split_sections(body),
        path=str(path),
        since=str(meta.get("since") or ""),
        producer=str(meta.get("producer") or ""),
        options=meta.get("options") or None,
        precision=str(meta.get("precision") or "high"),
        meta=meta,
    )


_CACHE: dict[str, dict[str, RuleDoc]] = {}


def load_catalog(root: str | Path | None = None) -> dict[str, RuleDoc]:
    """Every rule doc by code, sorted by code (cached per catalog folder)."""
    folder = Path(root) if root is not None else rules_dir()
    key = str(folder)
    if key not in _CACHE:
        docs = [parse_rule_doc(p) for p in sorted(folder.glob("*/*.md")) if _FILE_NAME.match(p.name)]
        _CACHE[key] = {d.code: d for d in sorted(docs, key=lambda d: d.code)}
    return _CACHE[key]


def lookup(code_or_name: str, catalog: dict[str, RuleDoc] | None = None) -> RuleDoc | None:
    """A rule by code (any case) or by kebab-case name."""
    docs = load_catalog() if catalog is None else catalog
    wanted = code_or_name.strip()
    if wanted.upper() in docs:
        return docs[wanted.upper()]
    for doc in docs.values():
        if doc.name == wanted.lower():
            return doc
    return None


def suggest(word: str, candidates: Iterable[str]) -> str | None:
    """The closest candidate (a code or a name), for "did you mean" hints."""
    import difflib

    close = difflib.get_close_matches(word, list(candidates), n=1, cutoff=0.6)
    return close[0] if close else None
