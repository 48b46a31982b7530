"""Regenerate docs/rules.md from the rule catalog (rules/). ``--check``: exit 1 if it is stale.

The page is ``physai_lint.report.rules_doc.render_markdown`` (every rule under an ``#<code>``
anchor, which SARIF ``helpUri`` links to) with an index table that also gives each rule's category.
"""
from __future__ import annotations

import sys
from pathlib import Path
from typing import Any, Mapping

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from physai_lint.catalog import load_catalog  # noqa: E402
from physai_lint.report.rules_doc import render_markdown  # noqa: E402

TARGET = ROOT / "docs" / "rules.md"
_OLD_HEADER = "| code | name | severity | summary |"


def index_table(catalog: Mapping[str, Any]) -> list[str]:
    rows = ["| code | name | category | default severity | summary |", "| --- | --- | --- | --- | --- |"]
    for d in catalog.values():
        summary = d.summary.replace("|", "\\|")
        rows.append(f"| [{d.code}](#{d.code.lower()}) | `{d.name}` | {d.category} | {d.severity} | {summary} |")
    return rows


def render(catalog: Mapping[str, Any]) -> str:
    lines = render_markdown(catalog).split("\n")
    start = lines.index(_OLD_HEADER)
    end = start + 2 + len(catalog)  # header, separator, one row per rule
    return "\n".join(lines[:start] + index_table(catalog) + lines[end:])


def main(argv: list[str]) -> int:
    text = render(load_catalog(ROOT / "rules"))
    rel = TARGET.relative_to(ROOT)
    if "--check" in argv:
        if not TARGET.is_file() or TARGET.read_text(encoding="utf-8") != text:
            print(f"{rel} is stale: run python scripts/gen_rules_doc.py", file=sys.stderr)
            return 1
        print(f"{rel} is up to date")
        return 0
    TARGET.write_text(text, encoding="utf-8")
    print(f"wrote {rel}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main(sys.argv[1:]))
