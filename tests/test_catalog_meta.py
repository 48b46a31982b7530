"""The rule catalog (rules/) is well-formed and agrees with the code allocation table."""
from __future__ import annotations

import re
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))  # tests run without an install

from physai_lint.catalog import SECTION_TITLES, load_catalog, parse_rule_doc  # noqa: E402

CATEGORY = {"L": "launch", "N": "names", "T": "topics", "P": "parameters", "U": "unresolved", "S": "startup", "X": "tool"}
FILES = sorted(p for p in (ROOT / "rules").glob("*/*.md") if re.match(r"^[A-Z][0-9]{3}-", p.name))


def _allocation() -> dict[str, tuple[str, str]]:
    text = (ROOT / "docs" / "architecture.md").read_text(encoding="utf-8")
    rows = re.findall(r"^\| ([A-Z][0-9]{3}) \| ([a-z0-9-]+) \| (error|warning|note) \|", text, re.MULTILINE)
    return {code: (name, sev) for code, name, sev in rows}


@pytest.mark.parametrize("path", FILES, ids=[p.stem for p in FILES])
def test_entry_is_well_formed(path: Path) -> None:
    doc = parse_rule_doc(path)
    assert path.name == f"{doc.code}-{doc.name}.md" and path.parent.name == doc.code[0]
    assert doc.severity in ("error", "warning", "note")
    assert doc.category == CATEGORY[doc.code[0]]
    assert "\n" not in doc.summary and doc.summary.endswith(".")
    assert list(doc.sections) == list(SECTION_TITLES), f"sections must be exactly {SECTION_TITLES}"
    assert len(doc.sections["What it does"]) > 0
    for section in ("Example", "Use instead"):
        if "<!-- example: not-run -->" in doc.sections[section]:
            continue
        assert re.search(r'^```\w+ title="[^"]+"', doc.sections[section], re.MULTILINE), f"{section} needs a titled code block"
    if doc.options:
        assert doc.options.get("type") == "object"
        for name, prop in doc.options.get("properties", {}).items():
            assert "default" in prop, f"option {name} has no default"
    allocated = _allocation()
    if doc.code in allocated:
        assert (doc.name, doc.severity) == allocated[doc.code]


def test_catalog_loads_and_codes_are_unique() -> None:
    catalog = load_catalog(ROOT / "rules")
    assert len(catalog) == len(FILES)
    names = [d.name for d in catalog.values()]
    assert len(names) == len(set(names))
