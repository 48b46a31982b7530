"""Pictures of the resolved graph: text tree, Graphviz DOT, Mermaid and one self-contained HTML page.

All renderers read the graph JSON document (``api.graph_document``), so every format shows the same
system. Namespaces become clusters; topics with no publisher or no subscriber are highlighted.
"""
from __future__ import annotations

import html
import json
from typing import Any


def _label(n: dict[str, Any]) -> str:
    return n["fqn"] or f"{n['package'] or '?'}/{n['executable'] or '?'}"


def _dangling(doc: dict[str, Any]) -> dict[str, str]:
    out = {}
    for t in doc["topics"]:
        if not t["publishers"]:
            out[t["name"]] = "no publisher"
        elif not t["subscribers"]:
            out[t["name"]] = "no subscriber"
    return out


def render(doc: dict[str, Any], fmt: str) -> str:
    return {"text": text, "dot": dot, "mermaid": mermaid, "html": page}[fmt](doc)


def text(doc: dict[str, Any]) -> str:
    entry = doc["entries"][0]
    lines = [f"{entry['file']}"]
    args = entry["arguments"]
    if args:
        lines.append("  arguments: " + ", ".join(f"{k}:={'?' if v is None else v}" for k, v in args.items()))
    by_chain: dict[tuple[str, ...], list[dict[str, Any]]] = {}
    for n in doc["nodes"]:
        by_chain.setdefault(tuple(n["include_chain"]), []).append(n)
    for chain in sorted(by_chain, key=lambda c: (len(c), c)):
        indent = "  " * len(chain)
        if chain:
            lines.append(f"{indent}include {chain[-1]} -> {by_chain[chain][0]['source']['file']}")
        for n in by_chain[chain]:
            state = "" if n["active"] is True else (" (inactive)" if n["active"] is False else " (condition unknown)")
            lines.append(f"{indent}  {n['kind']} {_label(n)}  [{n['package']}/{n['executable']}]"
                         f"  {n['source']['file']}:{n['source']['line']}{state}")
            for src, dst in n["remappings"]:
                lines.append(f"{indent}      remap {src} -> {dst}")
            for name, value in n["parameters"].items():
                lines.append(f"{indent}      param {name} = {json.dumps(value)}")
            if n.get("container"):
                lines.append(f"{indent}      in container {n['container']}")
    dangling = _dangling(doc)
    if doc["topics"]:
        lines.append("topics:")
        ids = {n["id"]: _label(n) for n in doc["nodes"]}
        for t in doc["topics"]:
            note = f"  <- {dangling[t['name']]}" if t["name"] in dangling else ""
            pubs = ", ".join(ids.get(i, i) for i in t["publishers"]) or "-"
            subs = ", ".join(ids.get(i, i) for i in t["subscribers"]) or "-"
            lines.append(f"  {t['name']} [{t['type'] or '?'}]: {pubs} -> {subs}{note}")
    return "\n".join(lines) + "\n"


def _q(s: str) -> str:
    return '"' + s.replace("\\", "\\\\").replace('"', '\\"') + '"'


def dot(doc: dict[str, Any]) -> str:
    out = ["digraph physai_lint {", "  rankdir=LR;", '  node [fontname="Helvetica"];']
    clusters: dict[str, list[dict[str, Any]]] = {}
    for n in doc["nodes"]:
        clusters.setdefault(n["namespace"] or "?", []).append(n)
    for i, ns in enumerate(sorted(clusters)):
        out.append(f"  subgraph cluster_{i} {{ label={_q(ns)}; style=rounded;")
        for n in clusters[ns]:
            style = ", style=dashed" if n["active"] is not True else ""
            shape = "component" if n["kind"] == "container" else "box"
            out.append(f"    {_q(n['id'])} [label={_q(_label(n))}, shape={shape}{style}];")
        out.append("  }")
    dangling = _dangling(doc)
    for t in doc["topics"]:
        color = ', color="red", fontcolor="red"' if t["name"] in dangling else ""
        out.append(f"  {_q('t:' + t['name'])} [label={_q(t['name'])}, shape=ellipse{color}];")
        for p in t["publishers"]:
            out.append(f"  {_q(p)} -> {_q('t:' + t['name'])};")
        for s in t["subscribers"]:
            out.append(f"  {_q('t:' + t['name'])} -> {_q(s)};")
    for n in doc["nodes"]:
        if n.get("container"):
            for c in doc["nodes"]:
                if c["fqn"] == n["container"] and c["kind"] == "container":
                    out.append(f"  {_q(c['id'])} -> {_q(n['id'])} [style=dotted, label=\"loads\"];")
    out.append("}")
    return "\n".join(out) + "\n"


def _mid(s: str) -> str:
    return "".join(ch if ch.isalnum() else "_" for ch in s)


def mermaid(doc: dict[str, Any]) -> str:
    out = ["flowchart LR"]
    clusters: dict[str, list[dict[str, Any]]] = {}
    for n in doc["nodes"]:
        clusters.setdefault(n["namespace"] or "?", []).append(n)
    for i, ns in enumerate(sorted(clusters)):
        out.append(f'  subgraph ns{i}["{ns}"]')
        for n in clusters[ns]:
            out.append(f'    {_mid(n["id"])}["{_label(n)}"]')
        out.append("  end")
    dangling = _dangling(doc)
    for t in doc["topics"]:
        tid = "t_" + _mid(t["name"])
        out.append(f'  {tid}(["{t["name"]}"])')
        if t["name"] in dangling:
            out.append(f"  style {tid} stroke:#d00,stroke-width:2px")
        for p in t["publishers"]:
            out.append(f"  {_mid(p)} --> {tid}")
        for s in t["subscribers"]:
            out.append(f"  {tid} --> {_mid(s)}")
    return "\n".join(out) + "\n"


def page(doc: dict[str, Any]) -> str:
    """One self-contained HTML file (no network): an SVG laid out in columns, pan with the mouse,
    zoom with the wheel."""
    nodes = doc["nodes"]
    topics = doc["topics"]
    dangling = _dangling(doc)
    pos: dict[str, tuple[int, int]] = {}
    col_w, row_h = 320, 56
    pubs = {p for t in topics for p in t["publishers"]}
    left = [n for n in nodes if n["id"] in pubs] or nodes
    right = [n for n in nodes if n not in left]
    for i, n in enumerate(left):
        pos[n["id"]] = (40, 40 + i * row_h)
    for i, t in enumerate(topics):
        pos["t:" + t["name"]] = (40 + col_w, 40 + i * row_h)
    for i, n in enumerate(right):
        pos[n["id"]] = (40 + 2 * col_w, 40 + i * row_h)
    height = 80 + row_h * max(len(left), len(topics), len(right), 1)
    parts = []
    for t in topics:
        tx, ty = pos["t:" + t["name"]]
        for p in t["publishers"]:
            if p in pos:
                x, y = pos[p]
                parts.append(f'<line x1="{x + 250}" y1="{y + 16}" x2="{tx}" y2="{ty + 16}" class="edge"/>')
        for s in t["subscribers"]:
            if s in pos:
                x, y = pos[s]
                parts.append(f'<line x1="{tx + 250}" y1="{ty + 16}" x2="{x}" y2="{y + 16}" class="edge"/>')
    for n in nodes:
        x, y = pos[n["id"]]
        cls = "node" if n["active"] is True else "node inactive"
        parts.append(f'<g class="{cls}" data-id="{html.escape(n["id"])}"><rect x="{x}" y="{y}" width="250" '
                     f'height="32" rx="6"/><text x="{x + 8}" y="{y + 21}">{html.escape(_label(n))}</text></g>')
    for t in topics:
        x, y = pos["t:" + t["name"]]
        cls = "topic dangling" if t["name"] in dangling else "topic"
        title = html.escape(dangling.get(t["name"], t["type"] or ""))
        parts.append(f'<g class="{cls}"><title>{title}</title><rect x="{x}" y="{y}" width="250" height="32" '
                     f'rx="16"/><text x="{x + 12}" y="{y + 21}">{html.escape(t["name"])}</text></g>')
    title = html.escape(doc["entries"][0]["file"])
    return f"""<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>physai-lint graph: {title}</title>
<style>
body {{ margin: 0; font-family: sans-serif; }}
header {{ padding: 8px 12px; background: #223; color: #fff; }}
svg {{ width: 100vw; height: calc(100vh - 40px); cursor: grab; background: #fafafa; }}
.node rect {{ fill: #dde8ff; stroke: #335; }}
.node.inactive rect {{ fill: #eee; stroke: #999; stroke-dasharray: 4 3; }}
.topic rect {{ fill: #fff; stroke: #585; }}
.topic.dangling rect {{ stroke: #d00; stroke-width: 2; }}
.edge {{ stroke: #777; stroke-width: 1.2; }}
text {{ font-size: 13px; }}
</style></head>
<body><header>{title}: {len(nodes)} nodes, {len(topics)} topics, {len(dangling)} dangling</header>
<svg id="graph" viewBox="0 0 {3 * col_w + 80} {height}" xmlns="http://www.w3.org/2000/svg">{''.join(parts)}</svg>
<script>
const svg = document.getElementById('graph');
let vb = svg.viewBox.baseVal, drag = null;
svg.addEventListener('wheel', e => {{ e.preventDefault(); const k = e.deltaY > 0 ? 1.1 : 0.9;
  vb.x += vb.width * (1 - k) / 2; vb.y += vb.height * (1 - k) / 2; vb.width *= k; vb.height *= k; }});
svg.addEventListener('mousedown', e => {{ drag = [e.clientX, e.clientY]; }});
window.addEventListener('mouseup', () => {{ drag = null; }});
svg.addEventListener('mousemove', e => {{ if (!drag) return; const s = vb.width / svg.clientWidth;
  vb.x -= (e.clientX - drag[0]) * s; vb.y -= (e.clientY - drag[1]) * s; drag = [e.clientX, e.clientY]; }});
</script></body></html>
"""
