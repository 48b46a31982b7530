"""Startup plan (graph/plan.py), its renderers (report/plan_render.py) and rules S101-S103.

Snapshots live in tests/plan_fixtures/snapshots; refresh with ``PHYSAI_UPDATE_SNAPSHOTS=1``.
"""
from __future__ import annotations

import json
import os
from pathlib import Path

import pytest

from physai_lint.api_plan import compute_plan, plan
from physai_lint.engine import CheckOptions, run_check
from physai_lint.report.plan_render import FORMATS, render_plan

HERE = Path(__file__).parent
RULES = HERE / "rules"
FIXTURES = HERE / "plan_fixtures"
SNAP = FIXTURES / "snapshots"
CODES = ("S101", "S102", "S103")


def _cases() -> list[Path]:
    return sorted(p for p in RULES.glob("S10[123]-*") if p.is_dir())


def _run(case: Path) -> list[tuple[str, str, int]]:
    files = sorted((case / "src").rglob("*.launch.py"))
    args = {}
    if (case / "args.txt").exists():
        for line in (case / "args.txt").read_text().splitlines():
            if ":=" in line:
                k, v = line.split(":=", 1)
                args[k.strip()] = v.strip()
    interfaces = ["interfaces.yaml"] if (case / "interfaces.yaml").exists() else []
    out = []
    for f in files:
        rep = run_check(CheckOptions(paths=[str(f.relative_to(case))], workspace=str(case),
                                     launch_args=args, interfaces=interfaces), cwd=str(case))
        out += [(x.code, os.path.relpath(x.span.file, case), x.span.line) for x in rep.findings]
    return out


@pytest.mark.parametrize("case", _cases(), ids=lambda p: p.name)
def test_rule_fixture(case: Path) -> None:
    code = case.name.split("-")[0]
    expected = json.loads((case / "bad" / "expected.json").read_text())
    got = _run(case / "bad")
    for e in expected:
        assert (e["code"], e["file"], e["line"]) in got, got
    assert sorted(g for g in got if g[0] == code) == sorted((e["code"], e["file"], e["line"]) for e in expected)
    assert [g for g in _run(case / "good") if g[0] == code] == []


def _plan(ws: Path, entry: str):  # type: ignore[no-untyped-def]
    return compute_plan(CheckOptions(paths=[], workspace=str(ws)), entry, cwd=str(ws))


def test_chain_plan_structure() -> None:
    p, _ = _plan(FIXTURES / "chain_ws", "src/demo/launch/chain.launch.py")
    labels = p.labels
    stage_of = {labels[v]: i for i, s in enumerate(p.stages, 1) for v in s}
    assert stage_of["/controller_manager"] == 1 and stage_of["spawner [joint_state_broadcaster]"] == 1
    assert stage_of["spawner [arm_controller]"] == 2 and stage_of["rviz2"] == 2
    assert stage_of["/talker"] == stage_of["/container"] + 1
    assert stage_of["/planner_server"] == stage_of["/controller_server"] + 1  # lifecycle order
    assert stage_of["/lifecycle_manager"] > stage_of["/planner_server"]
    assert p.cycles == []
    assert [labels[x] for x in p.critical_path] == ["/controller_manager", "rviz2"]
    assert p.critical_delay == 3.0


def test_cycle_plan_is_deadlock() -> None:
    p, _ = _plan(RULES / "S101-startup-cycle" / "bad", "src/demo/launch/x.launch.py")
    assert len(p.cycles) == 1 and p.cycles[0].deadlock
    assert p.cycles[0].text(p.labels) == "listener -> talker -> listener"
    assert p.stages == []  # neither starts: they are listed apart, in no stage
    assert {p.labels[v] for v in p.never_starts} == {"listener", "talker"}
    for fmt, mark in (("text", "Never starts (2)"), ("mermaid", "linkStyle 0,1 stroke:#d00"),
                      ("dot", "cluster_never"), ("json", '"never_starts": true')):
        assert mark in render_plan(p, fmt, str(RULES)), fmt


def test_root_chain_is_not_a_deadlock() -> None:
    p, _ = _plan(RULES / "S101-startup-cycle" / "good", "src/demo/launch/x.launch.py")
    assert p.cycles == [] and p.never_starts == set()


@pytest.mark.parametrize("fmt", FORMATS)
def test_snapshots(fmt: str) -> None:
    ws = FIXTURES / "chain_ws"
    text = plan(CheckOptions(paths=[], workspace=str(ws)), "src/demo/launch/chain.launch.py", fmt,
                cwd=str(ws))
    ext = {"text": "txt", "json": "json", "dot": "dot", "mermaid": "mmd"}[fmt]
    snap = SNAP / f"chain.{ext}"
    if os.environ.get("PHYSAI_UPDATE_SNAPSHOTS") or not snap.exists():
        snap.write_text(text)
    assert text == snap.read_text()
    again = plan(CheckOptions(paths=[], workspace=str(ws)), "src/demo/launch/chain.launch.py", fmt,
                 cwd=str(ws))
    assert again == text  # deterministic


def test_json_keys() -> None:
    p, cwd = _plan(FIXTURES / "chain_ws", "src/demo/launch/chain.launch.py")
    data = json.loads(render_plan(p, "json", cwd))
    assert set(data) >= {"stages", "edges", "cycles", "critical_path", "vertices", "version"}
    assert all(set(e) >= {"before", "after", "reason", "soft", "delay"} for e in data["edges"])


def test_unknown_format() -> None:
    p, cwd = _plan(FIXTURES / "chain_ws", "src/demo/launch/chain.launch.py")
    with pytest.raises(ValueError):
        render_plan(p, "svg", cwd)


def test_parts_that_cannot_be_known_are_listed_not_silently_left_out(tmp_path, demo_package) -> None:
    """An include outside the workspace or a helper the linter cannot follow may start processes
    the plan cannot show: the text and JSON forms say so, with where and why."""
    launch = (
        "from launch import LaunchDescription\n"
        "from launch.actions import IncludeLaunchDescription\n"
        "from launch.launch_description_sources import PythonLaunchDescriptionSource\n"
        "from launch_ros.actions import Node\n"
        "from my_helpers import spawn\n\n\n"
        "def generate_launch_description():\n"
        "    return LaunchDescription([\n"
        "        Node(package='demo', executable='talker'),\n"
        "        spawn('robot'),\n"
        "        IncludeLaunchDescription(PythonLaunchDescriptionSource('/opt/other/launch/x.launch.py')),\n"
        "    ])\n")
    demo_package({"launch/a.launch.py": launch})
    opts = CheckOptions(paths=[], workspace=str(tmp_path))
    text = plan(opts, "src/demo/launch/a.launch.py", "text", cwd=str(tmp_path))
    assert "1 process in 1 stage(s)" in text
    assert "Not shown: 2 part(s) of the launch cannot be known statically and may start more:" in text
    data = json.loads(plan(opts, "src/demo/launch/a.launch.py", "json", cwd=str(tmp_path)))
    assert [(u["line"], u["reason"].split(" ")[0]) for u in data["unknown"]] == [(11, "call"), (12, "include")]


def test_components_loaded_by_a_timer_or_a_handler_wait_for_it(tmp_path, demo_package) -> None:
    """A LoadComposableNodes inside a TimerAction loads its components when the timer fires, one
    inside an event handler when the event comes: the components wait for those as a Node does."""
    launch = (
        "from launch import LaunchDescription\n"
        "from launch.actions import RegisterEventHandler, TimerAction\n"
        "from launch.event_handlers import OnProcessStart\n"
        "from launch_ros.actions import LoadComposableNodes, Node\n"
        "from launch_ros.descriptions import ComposableNode\n\n\n"
        "def generate_launch_description():\n"
        "    driver = Node(package='demo_nodes_cpp', executable='talker', name='driver')\n"
        "    def load(name):\n"
        "        return LoadComposableNodes(target_container='shared', composable_node_descriptions=[\n"
        "            ComposableNode(package='composition', plugin='composition::Listener', name=name)])\n"
        "    return LaunchDescription([\n"
        "        Node(package='rclcpp_components', executable='component_container', name='shared'),\n"
        "        driver,\n"
        "        TimerAction(period=3.0, actions=[load('late')]),\n"
        "        RegisterEventHandler(OnProcessStart(target_action=driver, on_start=[load('after_driver')])),\n"
        "    ])\n")
    demo_package({"launch/a.launch.py": launch})
    p, _ = _plan(tmp_path, "src/demo/launch/a.launch.py")
    vertex = {label: v for v, label in p.labels.items()}
    assert p.vertices[vertex["/late"]].delay == 3.0
    assert p.critical_delay == 3.0
    before = {(p.labels[e.before], e.reason) for e in p.edges if p.labels[e.after] == "/after_driver"}
    assert ("/shared", "container") in before
    assert any(who == "/driver" and "start" in reason.lower() for who, reason in before), before


def test_components_of_a_timed_container_wait_for_its_timer_once(tmp_path, demo_package) -> None:
    """A container started by a TimerAction loads its own components when it starts: their wait is
    the container's, not a second timer on top of it."""
    launch = (
        "from launch import LaunchDescription\n"
        "from launch.actions import TimerAction\n"
        "from launch_ros.actions import ComposableNodeContainer\n"
        "from launch_ros.descriptions import ComposableNode\n\n\n"
        "def generate_launch_description():\n"
        "    return LaunchDescription([TimerAction(period=10.0, actions=[\n"
        "        ComposableNodeContainer(package='rclcpp_components', executable='component_container',\n"
        "                                name='container', namespace='', composable_node_descriptions=[\n"
        "            ComposableNode(package='composition', plugin='composition::Talker', name='talker')]),\n"
        "    ])])\n")
    demo_package({"launch/a.launch.py": launch})
    p, _ = _plan(tmp_path, "src/demo/launch/a.launch.py")
    assert [p.labels[v] for v in p.critical_path] == ["/container", "/talker"]
    assert p.critical_delay == 10.0


def test_a_part_disabled_by_its_condition_is_not_listed_as_unknown(tmp_path, demo_package) -> None:
    """An include outside the workspace whose condition is false starts nothing in this run: it is
    not among the parts that "may start more". The rules judge the file for every run, where it
    may run and read any argument: L106 stays silent on what is passed to its includer."""
    child = (
        "from launch import LaunchDescription\n"
        "from launch.actions import DeclareLaunchArgument, IncludeLaunchDescription\n"
        "from launch.conditions import UnlessCondition\n"
        "from launch.launch_description_sources import PythonLaunchDescriptionSource\n"
        "from launch.substitutions import LaunchConfiguration\n\n\n"
        "def generate_launch_description():\n"
        "    return LaunchDescription([\n"
        "        DeclareLaunchArgument('multi', default_value='false'),\n"
        "        IncludeLaunchDescription(PythonLaunchDescriptionSource('/opt/sim/launch/world.launch.py'),\n"
        "                                 condition=UnlessCondition(LaunchConfiguration('multi'))),\n"
        "    ])\n")
    top = (
        "from launch import LaunchDescription\n"
        "from launch.actions import IncludeLaunchDescription\n"
        "from launch.launch_description_sources import PythonLaunchDescriptionSource\n"
        "from launch.substitutions import PathJoinSubstitution\n"
        "from launch_ros.substitutions import FindPackageShare\n\n\n"
        "def generate_launch_description():\n"
        "    child = PathJoinSubstitution([FindPackageShare('demo'), 'launch', 'child.launch.py'])\n"
        "    return LaunchDescription([IncludeLaunchDescription(PythonLaunchDescriptionSource(child),\n"
        "                              launch_arguments={'multi': 'true', 'bogus': '1'}.items())])\n")
    demo_package({"launch/child.launch.py": child, "launch/top.launch.py": top})
    opts = CheckOptions(paths=[], workspace=str(tmp_path))
    data = json.loads(plan(opts, "src/demo/launch/top.launch.py", "json", cwd=str(tmp_path)))
    assert data["unknown"] == []
    found = run_check(CheckOptions(paths=[str(tmp_path / "src/demo/launch/top.launch.py")],
                                   workspace=str(tmp_path), cache=False)).findings
    assert [f for f in found if f.code == "L106"] == []


def test_what_only_a_handler_of_a_disabled_action_starts_never_starts(tmp_path, demo_package) -> None:
    """The handler's target is off under the analysed arguments, so the handler never fires and
    the spawner it starts never starts: not a process that starts with the launch."""
    text = (
        "from launch import LaunchDescription\n"
        "from launch.actions import DeclareLaunchArgument, RegisterEventHandler\n"
        "from launch.conditions import IfCondition\n"
        "from launch.event_handlers import OnProcessExit\n"
        "from launch.substitutions import LaunchConfiguration\n"
        "from launch_ros.actions import Node\n\n\n"
        "def generate_launch_description():\n"
        "    jsb = Node(package='controller_manager', executable='spawner', arguments=['jsb'],\n"
        "               condition=IfCondition(LaunchConfiguration('use_jsb')))\n"
        "    arm = Node(package='controller_manager', executable='spawner', arguments=['arm'])\n"
        "    return LaunchDescription([\n"
        "        DeclareLaunchArgument('use_jsb', default_value='false'),\n"
        "        Node(package='controller_manager', executable='ros2_control_node'),\n"
        "        jsb,\n"
        "        RegisterEventHandler(OnProcessExit(target_action=jsb, on_exit=[arm])),\n"
        "    ])\n")
    demo_package({"launch/chain.launch.py": text})
    p, _ = _plan(tmp_path, "src/demo/launch/chain.launch.py")
    assert {p.labels[v] for v in p.never_starts} == {"spawner"}
    assert [m for _, m in p.never_started] == [
        "the target action of its OnProcessExit is disabled by its condition"]
    p, _ = compute_plan(CheckOptions(paths=[], workspace=str(tmp_path), launch_args={"use_jsb": "true"}),
                        "src/demo/launch/chain.launch.py", cwd=str(tmp_path))
    assert p.never_starts == set() and len(p.stages) == 2


def test_spawner_labels_name_the_controllers_not_the_options_values() -> None:
    from physai_lint.graph.plan import first_positional

    def label(*args: str | None, exe: str = "spawner") -> str | None:
        return first_positional(args, package="controller_manager", executable=exe)

    assert label("-c", "/controller_manager", "joint_state_broadcaster") == "joint_state_broadcaster"
    assert label("jsb", "arm", "--inactive", "-p", "/cfg/arm.yaml", "--controller-manager-timeout", "30") \
        == "jsb, arm"
    assert label("--controller-manager=/cm", "jsb", "--fallback_controllers", "safe", "-t", "x/Y") == "jsb"
    assert label("-c", None, "jsb") is None  # an option's value unknown: where the names start is too
    # other executables: the first positional argument, as before
    assert first_positional(("-c", "/controller_manager", "jsb")) == "controller_manager"


def test_nodes_behind_a_trigger_cycle_never_start(tmp_path, demo_package) -> None:
    """A node started only from the handler of a lifecycle node's transition, when that node is
    configured only once the node has started, never starts (S101 through the transitions): the
    plan marks it and says why."""
    from tests.resolve.test_trigger_cycles import LIFECYCLE

    demo_package({"launch/a.launch.py": LIFECYCLE.format(first="relay", more="")})
    opts = CheckOptions(paths=[], workspace=str(tmp_path))
    data = json.loads(plan(opts, "src/demo/launch/a.launch.py", "json", cwd=str(tmp_path)))
    assert {v["fqn"]: v["never_starts"] for v in data["vertices"]} == {"/lidar": False, "/relay": True}
    assert [(n["line"], n["message"].split(":")[0]) for n in data["never_started"]] == [
        (20, 'startup cycle "/lidar" -> EmitEvent (line 14) -> "/relay" -> "/lidar"')]
    demo_package({"launch/a.launch.py": LIFECYCLE.format(first="lidar", more="")})
    data = json.loads(plan(opts, "src/demo/launch/a.launch.py", "json", cwd=str(tmp_path)))
    assert not any(v["never_starts"] for v in data["vertices"]) and data["never_started"] == []


def test_never_starting_vertices_render_in_one_order_whatever_the_hash_seed(tmp_path) -> None:
    import subprocess
    import sys

    launch = tmp_path / "src" / "demo" / "launch"
    launch.mkdir(parents=True)
    (launch.parent / "package.xml").write_text(
        '<?xml version="1.0"?>\n<package format="3"><name>demo</name><version>0.0.1</version>'
        '<description>d</description><maintainer email="m@example.com">m</maintainer><license>MIT</license>'
        '<buildtool_depend>ament_cmake</buildtool_depend><export><build_type>ament_cmake</build_type></export>'
        '</package>\n')
    (launch.parent / "CMakeLists.txt").write_text(
        "project(demo)\ninstall(DIRECTORY launch DESTINATION share/${PROJECT_NAME})\n")
    (launch / "a.launch.py").write_text(
        "from launch import LaunchDescription\nfrom launch.actions import ExecuteProcess, RegisterEventHandler\n"
        "from launch.event_handlers import OnProcessExit\nfrom launch_ros.actions import Node\n\n\n"
        "def generate_launch_description():\n"
        "    check = ExecuteProcess(cmd=['true'])\n"
        "    nodes = [Node(package='demo_nodes_cpp', executable='talker', name=f'n{i}') for i in range(4)]\n"
        "    return LaunchDescription([RegisterEventHandler(OnProcessExit(target_action=check, on_exit=nodes))])\n")
    outs = set()
    for seed in ("1", "2", "3"):
        out = subprocess.run([sys.executable, "-m", "physai_lint", "plan", "src/demo/launch/a.launch.py",
                              "--workspace", str(tmp_path), "--format", "mermaid"], cwd=tmp_path, text=True,
                             capture_output=True, env={**os.environ, "PYTHONHASHSEED": seed}, check=False).stdout
        outs.add(out)
    assert len(outs) == 1 and "class n1,n2,n3,n4 never" in outs.pop()
