"""Findings: what a rule or a frontend reports.

Producers (frontends, resolver, rules) create ``Diagnostic``s that name a rule ``code``; the engine
turns them into ``Finding``s by adding the rule's kebab-case name and its configured severity.
"""
from __future__ import annotations

import hashlib
from dataclasses import dataclass
from typing import Literal

from physai_lint.model.pickling import fast_pickle_module

from .span import Span

Severity = Literal["error", "warning", "note"]
SEVERITY_RANK: dict[str, int] = {"note": 0, "warning": 1, "error": 2}


@dataclass(frozen=True, slots=True)
class Related:
    span: Span
    message: str


@dataclass(frozen=True, slots=True)
class Fix:
    """A machine-applicable edit: replace ``span`` with ``replacement``."""

    span: Span
    replacement: str
    description: str


@dataclass(frozen=True, slots=True)
class Diagnostic:
    """What a producer reports. ``key`` identifies *what* was flagged (not where), for fingerprints:
    e.g. the package name for unknown-package. ``message`` is a lower-case fragment quoting the
    actual values in double quotes; ``help`` says how to fix it."""

    code: str
    span: Span
    message: str
    help: str | None = None
    related: tuple[Related, ...] = ()
    key: str = ""
    fix: Fix | None = None


@dataclass(frozen=True, slots=True)
class Finding:
    code: str
    name: str
    severity: Severity
    span: Span
    message: str
    help: str | None
    related: tuple[Related, ...]
    key: str
    fix: Fix | None = None

    def sort_key(self) -> tuple[str, int, int, str, str]:
        return (self.span.file, self.span.line, self.span.col, self.code, self.message)

    def fingerprint(self, relpath: str) -> str:
        """Stable across line moves: rule + file + what was flagged (or the message without digits)."""
        what = self.key or "".join(ch for ch in self.message if not ch.isdigit())
        raw = f"{self.code}\0{relpath}\0{what}"
        return hashlib.sha256(raw.encode("utf-8")).hexdigest()[:20]


fast_pickle_module(globals())  # tuples instead of dataclasses.fields() per object (model/pickling.py)
