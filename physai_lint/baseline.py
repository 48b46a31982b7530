"""Baselines: accept today's findings, report only new ones.

An entry is a finding's fingerprint (rule + relative file + what was flagged, never a line
number), so findings survive edits that move lines. Entries are a multiset: two identical findings
in the baseline hide at most two.
"""
from __future__ import annotations

import json
import os
from collections import Counter
from dataclasses import dataclass, field
from typing import Iterable

from physai_lint.errors import ConfigError
from physai_lint.model.findings import Finding

FORMAT = "physai-lint-baseline"
VERSION = 1


def relpath(path: str, cwd: str) -> str:
    """``path`` relative to ``cwd``, ``/``-separated (absolute if on another drive)."""
    try:
        rel = os.path.relpath(path, cwd)
    except ValueError:
        rel = path
    return rel.replace(os.sep, "/")


@dataclass
class Baseline:
    path: str
    counts: Counter[str] = field(default_factory=Counter)

    def filter(self, findings: Iterable[Finding], cwd: str) -> tuple[list[Finding], int]:
        """Findings not in the baseline, and how many were hidden by it."""
        remaining = Counter(self.counts)
        kept: list[Finding] = []
        suppressed = 0
        for f in findings:
            fp = f.fingerprint(relpath(f.span.file, cwd))
            if remaining[fp] > 0:
                remaining[fp] -= 1
                suppressed += 1
            else:
                kept.append(f)
        return kept, suppressed


def write(path: str, findings: Iterable[Finding], cwd: str) -> int:
    """Write a baseline holding ``findings``; returns the number of entries."""
    entries = []
    for f in findings:
        rel = relpath(f.span.file, cwd)
        entries.append({"code": f.code, "file": rel, "fingerprint": f.fingerprint(rel), "message": f.message})
    entries.sort(key=lambda e: (e["file"], e["code"], e["fingerprint"], e["message"]))
    doc = {"format": FORMAT, "version": VERSION, "entries": entries}
    with open(path, "w", encoding="utf-8", newline="\n") as fh:
        json.dump(doc, fh, indent=2, ensure_ascii=False)
        fh.write("\n")
    return len(entries)


def load(path: str) -> Baseline:
    """Read a baseline file; ``ConfigError`` when it is missing or malformed."""
    try:
        with open(path, encoding="utf-8") as fh:
            doc = json.load(fh)
    except FileNotFoundError:
        raise ConfigError(f'baseline file "{path}" does not exist (create it with --write-baseline)') from None
    except (OSError, ValueError) as exc:
        raise ConfigError(f'baseline file "{path}" cannot be read: {exc}') from None
    if not isinstance(doc, dict) or doc.get("format") != FORMAT or not isinstance(doc.get("entries"), list):
        raise ConfigError(f'baseline file "{path}" is not a physai-lint baseline')
    counts: Counter[str] = Counter()
    for entry in doc["entries"]:
        if not isinstance(entry, dict) or not isinstance(entry.get("fingerprint"), str):
            raise ConfigError(f'baseline file "{path}" has an entry without a fingerprint')
        counts[entry["fingerprint"]] += 1
    return Baseline(path, counts)
