"""docs/rules.md is generated from rules/: it must be regenerated whenever the catalog changes."""
from __future__ import annotations

import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def test_rules_doc_is_fresh() -> None:
    result = subprocess.run([sys.executable, str(ROOT / "scripts" / "gen_rules_doc.py"), "--check"],
                            capture_output=True, text=True, cwd=ROOT)
    assert result.returncode == 0, result.stderr + "run: python scripts/gen_rules_doc.py"


def test_every_rule_has_an_anchor_and_a_row() -> None:
    sys.path.insert(0, str(ROOT))
    from physai_lint.catalog import load_catalog

    text = (ROOT / "docs" / "rules.md").read_text(encoding="utf-8")
    for code, doc in load_catalog(ROOT / "rules").items():
        assert f'<a id="{code.lower()}"></a>' in text, code
        assert f"| [{code}](#{code.lower()}) | `{doc.name}` | {doc.category} | {doc.severity} |" in text, code
