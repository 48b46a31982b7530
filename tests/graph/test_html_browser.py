"""The HTML graph rendered in a real browser (headless Chromium from the machine's packages).

A probe script appended to a copy of the page measures what Chromium laid out: every node and
topic drawn inside the window with its label fitting its box, namespace boxes around their nodes,
dangling topics drawn red, pan and zoom moving the view, and no resource fetched. Skips when no
Chromium binary is installed, except under CI (``CI`` set), where ``.ci/run`` installs it.
"""
from __future__ import annotations

import html
import json
import os
import re
import shutil
import subprocess
from pathlib import Path
from typing import Any

import pytest

from physai_lint.api import graph
from physai_lint.engine import CheckOptions

ROOT = Path(__file__).resolve().parents[2]
BUGGY = ROOT / "examples" / "buggy_ws"
ENTRY = BUGGY / "src" / "atlas_bringup" / "launch" / "robot.launch.py"
BROWSERS = ("chromium", "chromium-browser", "google-chrome", "google-chrome-stable")
FLAGS = ("--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
         "--disable-background-networking", "--disable-component-update", "--disable-sync",
         "--disable-extensions", "--window-size=1400,1000")

# Runs first in <head>: records Content-Security-Policy violations (a blocked fetch) before the page's
# own script runs.
WATCH = """<script>window.__blocked = [];
document.addEventListener('securitypolicyviolation', e => window.__blocked.push(e.blockedURI));</script>"""

PROBE = """<script>
(function () {
  const svg = document.getElementById('graph'), vb = svg.viewBox.baseVal;
  const r = svg.getBoundingClientRect();
  const box = el => { const b = el.getBoundingClientRect(); return [b.left, b.top, b.right, b.bottom]; };
  const view = () => [vb.x, vb.y, vb.width, vb.height];
  const out = {ready: document.body.dataset.ready || null, svg: box(svg), vertices: {}, clusters: [],
               edges: svg.querySelectorAll('.edge').length};
  svg.querySelectorAll('.v').forEach(g => {
    const t = g.querySelector('text'), rect = g.querySelector('rect');
    out.vertices[g.dataset.id] = {text: t.textContent, box: box(rect), textWidth: t.getBBox().width,
      rectWidth: rect.getBBox().width, dangling: g.dataset.dangling || null,
      stroke: getComputedStyle(rect).stroke, display: getComputedStyle(g).display};
  });
  svg.querySelectorAll('.cluster').forEach(g => out.clusters.push(
    {namespace: g.dataset.namespace, box: box(g.querySelector('rect')), text: g.querySelector('text').textContent}));
  out.view0 = view();
  const cx = (r.left + r.right) / 2, cy = (r.top + r.bottom) / 2;
  svg.dispatchEvent(new WheelEvent('wheel', {deltaY: -120, clientX: cx, clientY: cy, bubbles: true, cancelable: true}));
  out.zoomed = view();
  const ptr = (type, x, y) => svg.dispatchEvent(new PointerEvent(type, {clientX: x, clientY: y, pointerId: 1, bubbles: true}));
  ptr('pointerdown', cx, cy); ptr('pointermove', cx + 200, cy + 100); ptr('pointerup', cx + 200, cy + 100);
  out.panned = view();
  document.getElementById('zfit').click();
  out.fit = view();
  out.resources = performance.getEntriesByType('resource').map(e => e.name);
  out.blocked = window.__blocked;
  const pre = document.createElement('pre'); pre.id = 'probe'; pre.textContent = JSON.stringify(out);
  document.body.appendChild(pre);
})();
</script>"""


def _browser() -> str:
    for name in BROWSERS:
        found = shutil.which(name)
        if found:
            return found
    msg = f"no Chromium binary on PATH (looked for {', '.join(BROWSERS)}); install it: apt-get install -y chromium"
    if os.environ.get("CI"):
        pytest.fail(msg + " (CI is set: .ci/run installs it, so the browser test must run)")
    pytest.skip(msg)


def _run(tmp: Path, *args: str) -> subprocess.CompletedProcess[str]:
    cmd = [_browser(), *FLAGS, f"--user-data-dir={tmp / 'profile'}", *args]
    return subprocess.run(cmd, check=False, capture_output=True, text=True, timeout=120, stdin=subprocess.DEVNULL)


def _page() -> tuple[str, dict[str, Any]]:
    opts = CheckOptions(paths=[str(ENTRY)], workspace=str(BUGGY), interfaces=[str(BUGGY / "interfaces.yaml")])
    return graph(opts, str(ENTRY), "html"), json.loads(graph(opts, str(ENTRY), "json"))


@pytest.fixture(scope="module")
def rendered(tmp_path_factory: pytest.TempPathFactory) -> tuple[dict[str, Any], dict[str, Any], Path]:
    tmp = tmp_path_factory.mktemp("browser")
    page, doc = _page()
    probed = page.replace("<head>", "<head>" + WATCH, 1).replace("</body>", PROBE + "</body>", 1)
    (tmp / "probe.html").write_text(probed, encoding="utf-8")
    (tmp / "graph.html").write_text(page, encoding="utf-8")
    proc = _run(tmp, "--virtual-time-budget=2000", "--dump-dom", (tmp / "probe.html").as_uri())
    m = re.search(r'<pre id="probe">(.*?)</pre>', proc.stdout, re.DOTALL)
    assert m, f"probe did not run (exit {proc.returncode}): {proc.stderr[-2000:]}"
    return json.loads(html.unescape(m.group(1))), doc, tmp


def _inside(inner: list[float], outer: list[float]) -> bool:
    return (inner[0] >= outer[0] - 0.5 and inner[1] >= outer[1] - 0.5
            and inner[2] <= outer[2] + 0.5 and inner[3] <= outer[3] + 0.5)


def test_every_node_and_topic_is_drawn_in_the_window(rendered: Any) -> None:
    probe, doc, _ = rendered
    assert probe["ready"] == "1"  # the page's own script ran to the end
    want = {"n:" + n["id"] for n in doc["nodes"]} | {"t:" + t["name"] for t in doc["topics"]}
    assert set(probe["vertices"]) == want
    names = {v["text"] for v in probe["vertices"].values()}
    assert {n["fqn"] for n in doc["nodes"] if n["fqn"]} <= names
    for vid, v in probe["vertices"].items():
        assert v["display"] != "none", vid
        assert _inside(v["box"], probe["svg"]), f"{vid} drawn outside the window: {v['box']}"
        assert 0 < v["textWidth"] <= v["rectWidth"], f"label of {vid} overflows its box"
    boxes = sorted((v["box"], k) for k, v in probe["vertices"].items())
    for i, (a, ka) in enumerate(boxes):
        for b, kb in boxes[i + 1:]:
            overlap = a[0] < b[2] and b[0] < a[2] and a[1] < b[3] and b[1] < a[3]
            assert not overlap, f"{ka} and {kb} overlap"
    n_edges = sum(len(t["publishers"]) + len(t["subscribers"]) for t in doc["topics"])
    assert probe["edges"] >= n_edges


def test_namespaces_are_boxes_around_their_nodes(rendered: Any) -> None:
    probe, doc, _ = rendered
    assert {c["namespace"] for c in probe["clusters"]} == {n["namespace"] or "?" for n in doc["nodes"]}
    for n in doc["nodes"]:
        v = probe["vertices"]["n:" + n["id"]]
        assert any(c["namespace"] == (n["namespace"] or "?") and _inside(v["box"], c["box"])
                   for c in probe["clusters"]), f"{n['fqn']} not inside a {n['namespace']} box"


def test_dangling_topics_are_red(rendered: Any) -> None:
    probe, doc, _ = rendered
    dangling = {k[2:]: v["dangling"] for k, v in probe["vertices"].items() if v["dangling"]}
    expected = {t["name"]: "no publisher" if not t["publishers"] else "no subscriber"
                for t in doc["topics"] if not t["publishers"] or not t["subscribers"]}
    assert dangling == expected and {"/scan", "/plan"} <= set(expected)
    for name, why in expected.items():
        v = probe["vertices"]["t:" + name]
        assert v["stroke"] == "rgb(221, 0, 0)" and v["text"].endswith(why)
    assert all(v["stroke"] != "rgb(221, 0, 0)" for k, v in probe["vertices"].items() if not v["dangling"])


def test_pan_and_zoom_move_the_view(rendered: Any) -> None:
    probe, _, _ = rendered
    x0, y0, w0, h0 = probe["view0"]
    assert probe["zoomed"][2] < w0 and probe["zoomed"][3] < h0  # wheel up zooms in
    zx, zy, zw, zh = probe["zoomed"]
    px, py, pw, ph = probe["panned"]
    assert (pw, ph) == (zw, zh) and px < zx and py < zy  # dragging right/down shows what is left/up
    assert probe["fit"] == [x0, y0, w0, h0]


def test_page_fetches_nothing(rendered: Any) -> None:
    probe, _, tmp = rendered
    assert probe["resources"] == [] and probe["blocked"] == []
    page = (tmp / "graph.html").read_text(encoding="utf-8")
    urls = set(re.findall(r"https?://[^\s\"'<>)]+", page)) - {"http://www.w3.org/2000/svg"}
    assert urls == set()
    assert "default-src 'none'" in page  # the page itself forbids any fetch


def test_screenshot_is_a_picture(rendered: Any) -> None:
    _, _, tmp = rendered
    shot = tmp / "graph.png"
    proc = _run(tmp, "--virtual-time-budget=2000", f"--screenshot={shot}", (tmp / "graph.html").as_uri())
    assert shot.exists(), proc.stderr[-2000:]
    data = shot.read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    width, height = int.from_bytes(data[16:20], "big"), int.from_bytes(data[20:24], "big")
    assert (width, height) == (1400, 1000)
    assert len(data) > 30_000  # a drawing, not a blank page (a blank 1400x1000 PNG is a few KB)
