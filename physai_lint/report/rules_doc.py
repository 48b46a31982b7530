"""The rule catalog as a table, JSON or Markdown (``physai-lint rules``, ``docs/rules.md``)."""
from __future__ import annotations

import json
from typing import Any, Mapping

CATEGORIES = {
    "L": "Launch structure and arguments",
    "N": "Names and namespaces",
    "T": "Topics and remappings",
    "P": "Parameters",
    "U": "Unresolved references",
    "S": "Startup order, lifecycle and composition",
    "X": "The tool itself",
}


def render_table(catalog: Mapping[str, Any]) -> str:
    rows = [(d.code, d.name, d.severity, d.summary) for d in catalog.values()]
    if not rows:
        return "no rules in the catalog\n"
    w_name = max(len(r[1]) for r in rows)
    w_sev = max(len("severity"), *(len(r[2]) for r in rows))
    out = [f"{'code':<5} {'name':<{w_name}} {'severity':<{w_sev}} summary"]
    out += [f"{c:<5} {n:<{w_name}} {s:<{w_sev}} {summary}" for c, n, s, summary in rows]
    return "\n".join(out) + "\n"


def render_json(catalog: Mapping[str, Any]) -> str:
    rules = [
        {
            "code": d.code,
            "name": d.name,
            "category": d.category,
            "severity": d.severity,
            "since": d.since,
            "summary": d.summary,
            "options": d.options,
        }
        for d in catalog.values()
    ]
    return json.dumps({"rules": rules}, indent=2, ensure_ascii=False) + "\n"


def _untitled(markdown: str) -> str:
    """The body without its leading ``# title`` line."""
    text = markdown.strip()
    if text.startswith("# "):
        text = text.partition("\n")[2].strip()
    return text


def render_rule(doc: Any) -> str:
    """``physai-lint rule CODE``: the catalog entry as Markdown."""
    since = f", since {doc.since}" if doc.since else ""
    meta = f"Default severity: {doc.severity}{since}. Select it with `{doc.code}` or `{doc.name}`."
    return f"# {doc.name} ({doc.code})\n\n{doc.summary}\n\n{meta}\n\n{_untitled(doc.markdown)}\n"


def _demote(markdown: str) -> str:
    """Headings one level down (``##`` -> ``###``), outside code fences."""
    out, fence = [], False
    for line in markdown.splitlines():
        if line.lstrip().startswith(("```", "~~~")):
            fence = not fence
        out.append("#" + line if not fence and line.startswith("#") else line)
    return "\n".join(out)


def render_markdown(catalog: Mapping[str, Any]) -> str:
    """``docs/rules.md``: an index table, then every rule under an ``#<code>`` anchor."""
    out = [
        "# Rules",
        "",
        "<!-- Generated from rules/ by `python scripts/gen_rules_doc.py`; do not edit. -->",
        "",
        "Select rules by code (`N101`), prefix (`N`, `N1`) or name (`duplicate-node-name`);",
        "severities are defaults and can be changed in the configuration.",
        "",
        "| code | name | severity | summary |",
        "| --- | --- | --- | --- |",
    ]
    for d in catalog.values():
        summary = d.summary.replace("|", "\\|")
        out.append(f"| [{d.code}](#{d.code.lower()}) | `{d.name}` | {d.severity} | {summary} |")
    current = None
    for d in catalog.values():
        letter = d.code[0]
        if letter != current:
            current = letter
            out += ["", f"## {letter}: {CATEGORIES.get(letter, 'Other')}"]
        since = f", since {d.since}" if d.since else ""
        out += [
            "",
            f'<a id="{d.code.lower()}"></a>',
            "",
            f"### {d.code} `{d.name}`",
            "",
            f"*Default severity: {d.severity}{since}.* {d.summary}",
            "",
            _demote(_demote(_untitled(d.markdown))),
        ]
    return "\n".join(out).rstrip() + "\n"
