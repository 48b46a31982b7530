"""N101 duplicate-node-name and the respawn pattern: a node started again by an OnProcessExit
handler of the first one never runs beside it, so the two are not duplicates. A node started when
some *other* process exits may run beside the first one, and still is."""
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


def _n101(demo_findings, text: str) -> list[str]:
    return [message for _, message in demo_findings({"launch/a.launch.py": text}, "launch/a.launch.py", "N101")]


def test_a_node_respawned_when_it_exits_is_no_duplicate(demo_findings):
    assert _n101(demo_findings, LAUNCH.format(target="first")) == []


def test_a_node_started_when_another_process_exits_is_still_a_duplicate(demo_findings):
    assert _n101(demo_findings, LAUNCH.format(target="supervisor")) == [(
        'node "/talker" is launched twice by this one action (in a loop or a function called again); '
        "services, parameters and topics of the copies collide")]


def test_a_node_that_launch_respawns_itself_may_run_beside_the_copy(demo_findings):
    text = LAUNCH.replace('name="talker")', 'name="talker", respawn=True)')
    assert ["N101" for _ in _n101(demo_findings, text.format(target="first"))] == ["N101"]


def test_a_copy_started_after_the_exit_through_another_action_is_no_duplicate(demo_findings):
    text = LAUNCH.replace(
        "RegisterEventHandler(OnProcessExit(target_action={target}, on_exit=[make()])),",
        "RegisterEventHandler(OnProcessExit(target_action=first, on_exit=[supervisor])),\n"
        "        RegisterEventHandler(OnProcessStart(target_action=supervisor, on_start=[make()])),")
    text = text.replace("from launch.event_handlers import OnProcessExit",
                        "from launch.event_handlers import OnProcessExit, OnProcessStart")
    text = text.replace("        supervisor,\n", "")
    assert _n101(demo_findings, text) == []
