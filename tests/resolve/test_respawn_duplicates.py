"""N101 duplicate-node-name and the respawn pattern: a node started again by an OnProcessExit
handler of the first one never runs beside it, so the two are not duplicates. A node started when
some *other* process exits may run beside the first one, and still is."""
from physai_lint.engine import CheckOptions, run_check

LAUNCH = """
from launch import LaunchDescription
from launch.actions import ExecuteProcess, RegisterEventHandler
from launch.event_handlers import OnProcessExit
from launch_ros.actions import Node


def make():
    return Node(package="demo_nodes_cpp", executable="talker", name="talker")


def generate_launch_description():
    first = make()
    supervisor = ExecuteProcess(cmd=["sleep", "5"])
    return LaunchDescription([
        first,
        supervisor,
        RegisterEventHandler(OnProcessExit(target_action={target}, on_exit=[make()])),
    ])
"""


def _n101(tmp_path, demo_package, target: str) -> list[str]:
    path = demo_package({"launch/a.launch.py": LAUNCH.format(target=target)}) / "launch/a.launch.py"
    report = run_check(CheckOptions(paths=[str(path)], workspace=str(tmp_path), select=("N101",)),
                       cwd=str(tmp_path))
    return [f.message for f in report.findings]


def test_a_node_respawned_when_it_exits_is_no_duplicate(tmp_path, demo_package):
    assert _n101(tmp_path, demo_package, "first") == []


def test_a_node_started_when_another_process_exits_is_still_a_duplicate(tmp_path, demo_package):
    assert _n101(tmp_path, demo_package, "supervisor") == [(
        'node "/talker" is launched twice (also at line 9); services, parameters and topics of '
        "the two collide")]


def test_a_node_that_launch_respawns_itself_may_run_beside_the_copy(tmp_path, demo_package):
    text = LAUNCH.replace('name="talker")', 'name="talker", respawn=True)')
    path = demo_package({"launch/a.launch.py": text.format(target="first")}) / "launch/a.launch.py"
    report = run_check(CheckOptions(paths=[str(path)], workspace=str(tmp_path), select=("N101",)),
                       cwd=str(tmp_path))
    assert [f.code for f in report.findings] == ["N101"]


def test_a_copy_started_after_the_exit_through_another_action_is_no_duplicate(tmp_path, demo_package):
    text = LAUNCH.replace(
        "RegisterEventHandler(OnProcessExit(target_action={target}, on_exit=[make()])),",
        "RegisterEventHandler(OnProcessExit(target_action=first, on_exit=[supervisor])),\n"
        "        RegisterEventHandler(OnProcessStart(target_action=supervisor, on_start=[make()])),")
    text = text.replace("from launch.event_handlers import OnProcessExit",
                        "from launch.event_handlers import OnProcessExit, OnProcessStart")
    text = text.replace("        supervisor,\n", "")
    path = demo_package({"launch/a.launch.py": text}) / "launch/a.launch.py"
    report = run_check(CheckOptions(paths=[str(path)], workspace=str(tmp_path), select=("N101",)),
                       cwd=str(tmp_path))
    assert report.findings == []
