"""A rule is a triple: catalog entry, registered check, fixture folder. This keeps the three in step."""
from __future__ import annotations

import re
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from physai_lint.catalog import SECTION_TITLES, load_catalog  # noqa: E402
from physai_lint.checks.base import load_all  # noqa: E402

CATALOG = load_catalog(ROOT / "rules")
REGISTERED = dict(load_all())
FIXTURES = {p.name: p for p in sorted((ROOT / "tests" / "rules").glob("*")) if p.is_dir()}
NON_CHECK_PRODUCERS = ("frontends", "engine")
# Catalogued but not built yet, with nobody on them: strict xfail, so the line must go when they land.
PENDING = {
}


@pytest.mark.parametrize("code", sorted(REGISTERED))
def test_registered_rule_has_catalog_entry_and_fixture(code: str) -> None:
    impl = REGISTERED[code]
    doc = CATALOG.get(code)
    assert doc is not None, f"{code} ({impl.name}) is registered but has no rules/{code[0]}/{code}-{impl.name}.md"
    assert doc.name == impl.name, f'{code}: @rule name "{impl.name}" != catalog name "{doc.name}"'
    assert doc.producer == "check", f"{code}: catalog producer is {doc.producer!r}, but a check implements it"
    folder = f"{code}-{impl.name}"
    assert folder in FIXTURES, f"{code}: no fixture folder tests/rules/{folder}/"


@pytest.mark.parametrize("code", sorted(CATALOG))
def test_catalog_entry_is_implemented(code: str, request: pytest.FixtureRequest) -> None:
    if code in PENDING:
        request.applymarker(pytest.mark.xfail(reason=PENDING[code], strict=True))
    doc = CATALOG[code]
    if doc.producer == "check":
        assert code in REGISTERED, f"{code} ({doc.name}) says producer: check but no @rule({code!r}, ...) exists"
        return
    assert doc.producer in NON_CHECK_PRODUCERS, f"{code}: unknown producer {doc.producer!r}"
    if f"{code}-{doc.name}" in FIXTURES:
        return
    # Frontend/engine findings are tested where they are produced: some test must name the code.
    pattern = re.compile(rf"\b{code}\b")
    mentions = [p for p in (ROOT / "tests").rglob("*.py") if p.name != Path(__file__).name
                and pattern.search(p.read_text(encoding="utf-8", errors="replace"))]
    assert mentions, f"{code} ({doc.producer}) has neither tests/rules/{code}-{doc.name}/ nor a test mentioning it"


@pytest.mark.parametrize("folder", sorted(FIXTURES))
def test_fixture_folder_names_a_catalog_rule(folder: str) -> None:
    code, _, name = folder.partition("-")
    assert code in CATALOG, f"tests/rules/{folder}: no catalog rule {code}"
    assert CATALOG[code].name == name, f'tests/rules/{folder}: catalog calls {code} "{CATALOG[code].name}"'


@pytest.mark.parametrize("code", sorted(CATALOG))
def test_catalog_entry_has_the_doc_sections(code: str) -> None:
    doc = CATALOG[code]
    missing = [s for s in SECTION_TITLES if not doc.sections.get(s, "").strip()]
    assert not missing, f"{doc.path}: missing or empty sections {missing}"
