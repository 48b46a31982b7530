"""Pictures of the resolved graph: text tree, Graphviz DOT, Mermaid and one self-contained HTML page.

All renderers read the graph JSON document (``api.graph_document``), so every format shows the same
system. Namespaces become clusters; topics with no publisher or no subscriber are highlighted.
"""
from __future__ import annotations

import html
import json
from typing import Any


def _label(n: dict[str, Any]) -> str:
    """The fqn; for a node without a known name its executable and first positional argument
    (three ``spawner`` processes differ only by the controller they load)."""
    if n["fqn"]:
        return str(n["fqn"])
    from physai_lint.graph.plan import first_positional

    arg = first_positional(tuple(n.get("arguments") or ()), package=n.get("package"),
                           executable=n.get("executable"))
    return f"{n['package'] or '?'}/{n['executable'] or '?'}" + (f" [{arg}]" if arg else "")


def _dangling(doc: dict[str, Any]) -> dict[str, str]:
    out = {}
    for t in doc["topics"]:
        if not t["publishers"]:
            out[t["name"]] = "no publisher"
        elif not t["subscribers"]:
            out[t["name"]] = "no subscriber"
    return out


def _containers(doc: dict[str, Any]) -> dict[str, str]:
    """fqn -> id of the containers: container actions and Nodes running a component container."""
    return {n["fqn"]: n["id"] for n in doc["nodes"] if n["fqn"] and (
        n["kind"] == "container" or (n["executable"] or "").startswith("component_container"))}


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
            what = f"  [{n['package']}/{n['executable']}]" if n["fqn"] else ""
            lines.append(f"{indent}  {n['kind']} {_label(n)}{what}"
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
    containers = _containers(doc)
    for n in doc["nodes"]:
        if n.get("container") in containers:
            out.append(f"  {_q(containers[n['container']])} -> {_q(n['id'])} [style=dotted, label=\"loads\"];")
    out.append("}")
    return "\n".join(out) + "\n"


def _mid(s: str) -> str:
    return "".join(ch if ch.isalnum() else "_" for ch in s)


def _mq(s: str) -> str:
    return '"' + s.replace('"', "#quot;") + '"'


def mermaid(doc: dict[str, Any]) -> str:
    out = ["flowchart LR"]
    clusters: dict[str, list[dict[str, Any]]] = {}
    for n in doc["nodes"]:
        clusters.setdefault(n["namespace"] or "?", []).append(n)
    for i, ns in enumerate(sorted(clusters)):
        out.append(f"  subgraph ns{i}[{_mq(ns)}]")
        for n in clusters[ns]:
            shape = f"[({_mq(_label(n))})]" if n["kind"] == "container" else f"[{_mq(_label(n))}]"
            out.append(f"    {_mid(n['id'])}{shape}")
        out.append("  end")
    dangling = _dangling(doc)
    for t in doc["topics"]:
        tid = "t_" + _mid(t["name"])
        out.append(f"  {tid}([{_mq(t['name'] + (' (' + dangling[t['name']] + ')' if t['name'] in dangling else ''))}])")
        for p in t["publishers"]:
            out.append(f"  {_mid(p)} --> {tid}")
        for s in t["subscribers"]:
            out.append(f"  {tid} --> {_mid(s)}")
    containers = _containers(doc)
    for n in doc["nodes"]:
        if n.get("container") in containers:
            out.append(f"  {_mid(containers[n['container']])} -.->|loads| {_mid(n['id'])}")
    if dangling:
        out.append("  classDef dangling stroke:#d00,stroke-width:2px,color:#d00")
        out.append("  class " + ",".join("t_" + _mid(t) for t in sorted(dangling)) + " dangling")
    inactive = [_mid(n["id"]) for n in doc["nodes"] if n["active"] is False]
    if inactive:
        out.append("  classDef inactive stroke-dasharray:4 3,color:#888")
        out.append("  class " + ",".join(inactive) + " inactive")
    return "\n".join(out) + "\n"


def _vertices(doc: dict[str, Any]) -> tuple[list[Any], list[tuple[str, str, str]]]:
    from physai_lint.graph.layout import LVertex

    dangling = _dangling(doc)
    verts = [LVertex("n:" + n["id"], _label(n), n["namespace"] or "?") for n in doc["nodes"]]
    verts += [LVertex("t:" + t["name"], t["name"], None, dangling.get(t["name"], "")) for t in doc["topics"]]
    edges: list[tuple[str, str, str]] = []
    for t in doc["topics"]:
        edges += [("n:" + p, "t:" + t["name"], "pub") for p in t["publishers"]]
        edges += [("t:" + t["name"], "n:" + s, "sub") for s in t["subscribers"]]
    containers = _containers(doc)
    for n in doc["nodes"]:
        if n.get("container") in containers:
            edges.append(("n:" + containers[n["container"]], "n:" + n["id"], "loads"))
    return verts, edges


def _path(a: Any, b: Any, vertical: bool) -> str:
    """A curve from ``a`` to ``b``; against the flow (a loop) it swings out beside both boxes."""
    if vertical:
        x1, y1, x2, y2 = a.x + a.w / 2, a.y + a.h, b.x + b.w / 2, b.y
        if y2 > y1:
            dy = max(25.0, (y2 - y1) / 2)
            return f"M{x1:g},{y1:g} C{x1:g},{y1 + dy:g} {x2:g},{y2 - dy:g} {x2:g},{y2:g}"
        x1, y1, x2, y2 = a.x + a.w, a.y + a.h / 2, b.x + b.w, b.y + b.h / 2
        side = max(x1, x2) + 60
        return f"M{x1:g},{y1:g} C{side:g},{y1:g} {side:g},{y2:g} {x2:g},{y2:g}"
    x1, y1, x2, y2 = a.x + a.w, a.y + a.h / 2, b.x, b.y + b.h / 2
    if x2 > x1:
        dx = max(30.0, (x2 - x1) / 2)
        return f"M{x1:g},{y1:g} C{x1 + dx:g},{y1:g} {x2 - dx:g},{y2:g} {x2:g},{y2:g}"
    x1, y1, x2, y2 = a.x + a.w / 2, a.y + a.h, b.x + b.w / 2, b.y + b.h
    low = max(y1, y2) + 50
    return f"M{x1:g},{y1:g} C{x1:g},{low:g} {x2:g},{low:g} {x2:g},{y2:g}"


def _node_title(n: dict[str, Any]) -> str:
    state = {True: "", False: " (inactive: its condition is false)",
             "unknown": " (condition unknown)"}.get(n["active"], "")
    where = f"{n['source']['file']}:{n['source']['line']}"
    cont = f"\nin container {n['container']}" if n.get("container") else ""
    return f"{n['kind']} {n['package'] or '?'}/{n['executable'] or '?'}{state}\n{where}{cont}"


def page(doc: dict[str, Any]) -> str:
    """One self-contained HTML file (no network; its Content-Security-Policy forbids fetching
    anything): a layered SVG with namespace boxes; drag to pan, wheel or buttons to zoom."""
    from physai_lint.graph.layout import layout

    dangling = _dangling(doc)
    verts, edges = _vertices(doc)
    lay = layout(verts, [(a, b) for a, b, _ in edges])
    labels = {n["id"]: _label(n) for n in doc["nodes"]}
    e = html.escape
    parts = [('<defs><marker id="arrow" viewBox="0 0 10 10" refX="10" refY="5" markerWidth="7" '
             'markerHeight="7" orient="auto-start-reverse"><path d="M0,0 L10,5 L0,10 z"/></marker></defs>')]
    for c in lay.clusters:
        parts.append(f'<g class="cluster" data-namespace="{e(c.name)}"><rect x="{c.x:g}" y="{c.y:g}" '
                     f'width="{c.w:g}" height="{c.h:g}" rx="8"/><text x="{c.x + 8:g}" y="{c.y + 15:g}">'
                     f'{e(c.name)}</text></g>')
    for a, b, kind in edges:
        parts.append(f'<path class="edge {kind}" data-from="{e(a)}" data-to="{e(b)}" '
                     f'd="{_path(lay.boxes[a], lay.boxes[b], lay.vertical)}" marker-end="url(#arrow)"/>')
    for n in doc["nodes"]:
        bx = lay.boxes["n:" + n["id"]]
        cls = ["v", "node", n["kind"].replace("_", "-")]
        if n["active"] is False:
            cls.append("inactive")
        elif n["active"] != True:
            cls.append("unknown")
        parts.append(f'<g class="{" ".join(cls)}" data-id="n:{e(n["id"])}"><title>{e(_node_title(n))}</title>'
                     f'<rect x="{bx.x:g}" y="{bx.y:g}" width="{bx.w:g}" height="{bx.h:g}" rx="5"/>'
                     f'<text x="{bx.x + 10:g}" y="{bx.y + 20:g}">{e(labels[n["id"]])}</text></g>')
    for t in doc["topics"]:
        bx = lay.boxes["t:" + t["name"]]
        why = dangling.get(t["name"])
        pubs = ", ".join(labels.get(i, i) for i in t["publishers"]) or "none"
        subs = ", ".join(labels.get(i, i) for i in t["subscribers"]) or "none"
        title = f"{t['type'] or 'type unknown'}\npublishers: {pubs}\nsubscribers: {subs}"
        extra = f'<tspan class="why" dx="8">{e(why)}</tspan>' if why else ""
        attr = f' data-dangling="{e(why)}"' if why else ""
        parts.append(f'<g class="v topic{" dangling" if why else ""}" data-id="t:{e(t["name"])}"{attr}>'
                     f'<title>{e(title)}</title><rect x="{bx.x:g}" y="{bx.y:g}" width="{bx.w:g}" '
                     f'height="{bx.h:g}" rx="15"/><text x="{bx.x + 12:g}" y="{bx.y + 20:g}">'
                     f'{e(t["name"])}{extra}</text></g>')
    title = e(doc["entries"][0]["file"])
    args = ", ".join(f"{k}:={'?' if v is None else v}" for k, v in doc["entries"][0]["arguments"].items())
    summary = f"{len(doc['nodes'])} nodes, {len(doc['topics'])} topics, {len(dangling)} dangling"
    details = (f"<div>arguments: {e(args) or 'none'}</div><div>dangling: "
               + (e(", ".join(f"{t} ({why})" for t, why in sorted(dangling.items()))) or "none") + "</div>")
    return _PAGE.format(title=title, details=details, summary=e(summary), w=f"{lay.width:g}",
                        h=f"{lay.height:g}", svg="\n".join(parts))


_PAGE = """<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8">
<meta http-equiv="Content-Security-Policy" content="default-src 'none'; style-src 'unsafe-inline'; script-src 'unsafe-inline'">
<meta name="viewport" content="width=device-width, initial-scale=1">
<title>physai-lint graph: {title}</title>
<style>
html, body {{ margin: 0; height: 100%; font-family: system-ui, sans-serif; }}
body {{ display: flex; flex-direction: column; }}
header {{ padding: 6px 12px; background: #223; color: #fff; font-size: 14px; }}
header .sub {{ color: #bbc; font-size: 12px; }}
header button {{ margin-left: 4px; min-width: 28px; }}
header details {{ max-height: 30vh; overflow: auto; }}
header summary {{ cursor: pointer; }}
.legend span {{ margin-right: 12px; white-space: nowrap; }}
.sw {{ display: inline-block; width: 12px; height: 12px; vertical-align: -2px; margin-right: 3px;
       border: 1px solid #335; }}
#graph {{ flex: 1; width: 100%; cursor: grab; background: #fafafa; touch-action: none; }}
#graph.panning {{ cursor: grabbing; }}
.cluster rect {{ fill: #f0f3f8; stroke: #aab; stroke-dasharray: 5 3; }}
.cluster text {{ fill: #556; font-size: 12px; font-weight: bold; }}
.node rect {{ fill: #dde8ff; stroke: #335; }}
.node.container rect {{ fill: #ffe9c7; stroke: #a60; }}
.node.composable-node rect {{ fill: #fff4e0; stroke: #a60; }}
.node.process rect {{ fill: #eee; stroke: #555; }}
.node.inactive rect {{ fill: #f4f4f4; stroke: #999; stroke-dasharray: 4 3; }}
.node.inactive text {{ fill: #888; }}
.node.unknown rect {{ stroke-dasharray: 2 2; }}
.topic rect {{ fill: #fff; stroke: #585; }}
.topic.dangling rect {{ fill: #fff0f0; stroke: #d00; stroke-width: 2.5; }}
.topic .why {{ fill: #d00; font-style: italic; font-size: 12px; }}
.edge {{ fill: none; stroke: #8890a0; stroke-width: 1.3; }}
.edge.loads {{ stroke: #a60; stroke-dasharray: 3 3; }}
marker path {{ fill: #8890a0; }}
text {{ font-size: 13px; fill: #111; }}
svg.focus .v, svg.focus .edge {{ opacity: 0.25; }}
svg.focus .hl {{ opacity: 1; }}
svg.focus .edge.hl {{ stroke: #247; stroke-width: 2.5; }}
</style></head>
<body><header><div><b>{title}</b>
<span style="float:right"><button id="zin" title="zoom in (+)">+</button><button id="zout" title="zoom out (-)">&minus;</button><button id="zfit" title="fit (0)">fit</button></span></div>
<details class="sub"><summary>{summary}</summary>{details}</details>
<div class="sub legend"><span><i class="sw" style="background:#dde8ff"></i>node</span><span><i class="sw" style="background:#ffe9c7;border-color:#a60"></i>container / component</span><span><i class="sw" style="background:#fff;border-color:#585;border-radius:6px"></i>topic</span><span><i class="sw" style="background:#fff0f0;border:2px solid #d00;border-radius:6px"></i>dangling topic</span><span><i class="sw" style="background:#f0f3f8;border-style:dashed"></i>namespace</span><span>drag to pan, wheel to zoom, hover to follow a node</span></div></header>
<svg id="graph" viewBox="0 0 {w} {h}" data-width="{w}" data-height="{h}" xmlns="http://www.w3.org/2000/svg">
{svg}
</svg>
<script>
(function () {{
  const svg = document.getElementById('graph');
  const W = +svg.dataset.width, H = +svg.dataset.height, vb = svg.viewBox.baseVal;
  function set(x, y, w, h) {{ vb.x = x; vb.y = y; vb.width = w; vb.height = h; }}
  function zoom(k, cx, cy) {{ set(cx - (cx - vb.x) * k, cy - (cy - vb.y) * k, vb.width * k, vb.height * k); }}
  function center() {{ return [vb.x + vb.width / 2, vb.y + vb.height / 2]; }}
  function toSvg(e) {{ const p = svg.createSVGPoint(); p.x = e.clientX; p.y = e.clientY;
    return p.matrixTransform(svg.getScreenCTM().inverse()); }}
  svg.addEventListener('wheel', e => {{ e.preventDefault(); const p = toSvg(e);
    zoom(e.deltaY > 0 ? 1.15 : 1 / 1.15, p.x, p.y); }}, {{ passive: false }});
  let drag = null;
  svg.addEventListener('pointerdown', e => {{ drag = toSvg(e); svg.classList.add('panning');
    if (svg.setPointerCapture) try {{ svg.setPointerCapture(e.pointerId); }} catch (_) {{}} }});
  svg.addEventListener('pointermove', e => {{ if (!drag) return; const p = toSvg(e);
    vb.x -= p.x - drag.x; vb.y -= p.y - drag.y; }});
  function stop() {{ drag = null; svg.classList.remove('panning'); }}
  svg.addEventListener('pointerup', stop); svg.addEventListener('pointercancel', stop);
  document.getElementById('zin').onclick = () => zoom(1 / 1.25, ...center());
  document.getElementById('zout').onclick = () => zoom(1.25, ...center());
  document.getElementById('zfit').onclick = () => set(0, 0, W, H);
  window.addEventListener('keydown', e => {{
    if (e.key === '+' || e.key === '=') zoom(1 / 1.25, ...center());
    else if (e.key === '-') zoom(1.25, ...center());
    else if (e.key === '0') set(0, 0, W, H); }});
  const edges = Array.from(svg.querySelectorAll('.edge'));
  svg.querySelectorAll('.v').forEach(g => {{
    g.addEventListener('mouseenter', () => {{ const id = g.dataset.id; svg.classList.add('focus'); g.classList.add('hl');
      edges.forEach(p => {{ if (p.dataset.from === id || p.dataset.to === id) {{ p.classList.add('hl');
        const o = svg.querySelector('.v[data-id="' + CSS.escape(p.dataset.from === id ? p.dataset.to : p.dataset.from) + '"]');
        if (o) o.classList.add('hl'); }} }}); }});
    g.addEventListener('mouseleave', () => {{ svg.classList.remove('focus');
      svg.querySelectorAll('.hl').forEach(x => x.classList.remove('hl')); }});
  }});
  document.body.dataset.ready = '1';
}})();
</script></body></html>
"""
