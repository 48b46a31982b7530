"""Regenerate docs/rules.md from the rule catalog (rules/). ``--check``: fail if it is stale."""
from __future__ import annotations

import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from physai_lint.catalog import load_catalog  # noqa: E402
from physai_lint.report.rules_doc import render_markdown  # noqa: E402


def main(argv: list[str]) -> int:
    target = ROOT / "docs" / "rules.md"
    text = render_markdown(load_catalog(ROOT / "rules"))
    if "--check" in argv:
        if not target.is_file() or target.read_text(encoding="utf-8") != text:
            print(f"{target.relative_to(ROOT)} is stale: run python scripts/gen_rules_doc.py", file=sys.stderr)
            return 1
        return 0
    target.write_text(text, encoding="utf-8")
    print(f"wrote {target.relative_to(ROOT)}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main(sys.argv[1:]))
