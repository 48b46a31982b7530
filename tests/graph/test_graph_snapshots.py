"""``physai-lint graph`` and ``plan`` on a small robot with a topic loop, a container, a lifecycle
manager, a spawner chain and a delayed RViz (tests/plan_fixtures/loop_ws): what users see is
snapshotted in tests/graph/snapshots; refresh with ``PHYSAI_UPDATE_SNAPSHOTS=1`` and review the diff.
"""
from __future__ import annotations

import json
import os
from pathlib import Path

import pytest

from physai_lint.api import GRAPH_FORMATS, graph
from physai_lint.api_plan import compute_plan, plan
from physai_lint.engine import CheckOptions
from physai_lint.report.plan_render import FORMATS as PLAN_FORMATS

HERE = Path(__file__).parent
WS = HERE.parent / "plan_fixtures" / "loop_ws"
ENTRY = "src/bot/launch/bot.launch.py"
SNAP = HERE / "snapshots"
EXT = {"text": "txt", "json": "json", "dot": "dot", "mermaid": "mmd", "html": "html"}


def _opts() -> CheckOptions:
    return CheckOptions(paths=[], workspace=str(WS), interfaces=[str(WS / "interfaces.yaml")])


def _check(name: str, text: str) -> None:
    snap = SNAP / name
    if os.environ.get("PHYSAI_UPDATE_SNAPSHOTS") or not snap.exists():
        snap.parent.mkdir(exist_ok=True)
        snap.write_text(text)
    assert text == snap.read_text()


@pytest.mark.parametrize("fmt", GRAPH_FORMATS)
def test_graph_snapshot(fmt: str, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(WS)  # graph paths are relative to the working directory
    text = graph(_opts(), ENTRY, fmt)
    _check(f"graph.{EXT[fmt]}", text)
    assert graph(_opts(), ENTRY, fmt) == text  # deterministic


@pytest.mark.parametrize("fmt", PLAN_FORMATS)
def test_plan_snapshot(fmt: str) -> None:
    text = plan(_opts(), ENTRY, fmt, cwd=str(WS))
    _check(f"plan.{EXT[fmt]}", text)


def test_topic_loop_does_not_stretch_the_stages() -> None:
    p, _ = compute_plan(_opts(), ENTRY, cwd=str(WS))
    stage = {p.vertices[v].label: i for i, s in enumerate(p.stages, 1) for v in s}
    # /base and /nav/follower feed each other (/odom, /cmd_vel): neither waits for the other
    assert stage["/base"] == 1 and stage["/nav/planner"] == 1
    assert stage["/nav/follower"] == 2  # lifecycle order after /nav/planner, not topics
    assert stage["/sensors/detector"] == 2  # container first; its topic need on /sensors/camera is soft
    assert stage["/nav/lifecycle_manager"] == 3 and stage["/rviz"] == 3
    soft = {(p.vertices[e.before].label, p.vertices[e.after].label) for e in p.edges if e.soft}
    assert ("/nav/follower", "/base") in soft and ("/base", "/nav/follower") in soft
    assert ("/sensors/camera", "/sensors/detector") in soft
    assert [p.vertices[v].label for v in p.critical_path] == [
        "spawner [joint_state_broadcaster]", "spawner [base_controller]", "/rviz"]
    assert p.critical_delay == 2.5


def test_soft_edge_against_the_plan_is_marked() -> None:
    p, cwd = compute_plan(_opts(), ENTRY, cwd=str(WS))
    from physai_lint.report.plan_render import render_plan

    data = json.loads(render_plan(p, "json", cwd))
    label = {v["id"]: v["label"] for v in data["vertices"]}
    against = {(label[e["before"]], label[e["after"]]) for e in data["edges"] if e["against"]}
    assert against == {("/nav/follower", "/base")}  # follower starts in stage 2, /base in 1
    assert "/nav/follower (/cmd_vel, stage 2: starts later)" in render_plan(p, "text", cwd)


def test_graph_html_structure(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(WS)
    page = graph(_opts(), ENTRY, "html")
    doc = json.loads(graph(_opts(), ENTRY, "json"))
    for n in doc["nodes"]:
        assert f'data-id="n:{n["id"]}"' in page
    for ns in ("/", "/nav", "/sensors"):
        assert f'data-namespace="{ns}"' in page
    assert 'data-id="t:/nav/goal" data-dangling="no publisher"' in page
    assert 'data-id="t:/sensors/debug_image" data-dangling="no subscriber"' in page
    assert page.count('class="edge loads"') == 2  # the container loads two components


def test_nav2_shaped_launch_gets_its_ordering_edges() -> None:
    ws = HERE.parent / "plan_fixtures" / "nav_ws"
    p, _ = compute_plan(CheckOptions(paths=[], workspace=str(ws)), "src/navbot/launch/nav.launch.py",
                        cwd=str(ws))
    lbl = p.labels
    assert sorted(lbl.values()) == ["/amcl", "/lifecycle_manager_localization", "/map_server",
                                    "/map_server (component)", "/nav_container"]  # no "[info]"
    edges = {(lbl[e.before], lbl[e.after], e.reason) for e in p.edges if not e.soft}
    assert ("/nav_container", "/amcl", "container") in edges  # loaded by container name
    assert ("/map_server", "/amcl", "lifecycle order") in edges
    # node_names comes after an unknown params file: the later dict wins, so it is known
    assert ("/amcl", "/lifecycle_manager_localization", "lifecycle manager") in edges
    stage = {lbl[v]: i for i, s in enumerate(p.stages, 1) for v in s}
    assert stage["/lifecycle_manager_localization"] == 4
