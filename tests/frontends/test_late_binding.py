"""Functions launch calls later (an OpaqueFunction's, an event handler's) read the variables of the
enclosing function when they run, after ``generate_launch_description`` has returned: Python
closures hold variables, not values (``calls.late_bindings``, L013)."""
import pytest

PY = """
from launch import LaunchDescription
from launch.actions import LogInfo, OpaqueFunction, RegisterEventHandler
from launch.event_handlers import OnProcessExit
from launch_ros.actions import Node

ROBOTS = ['alpha', 'beta']


def robot(context, name):
    return [Node(package='turtlesim', executable='turtlesim_node', name='sim', namespace=name)]


def generate_launch_description():
    ld = LaunchDescription()
@BODY@
    return ld
"""


def _run(demo_findings, body: str, code: str) -> list[tuple[int, str]]:
    text = PY.replace("@BODY@", "\n".join("    " + line for line in body.strip("\n").splitlines()))
    return demo_findings({"launch/fleet.launch.py": text}, "launch/fleet.launch.py", code)


LOOP = """
for name in ROBOTS:
    ld.add_action(OpaqueFunction(function=lambda context: robot(context, name)))
"""


def test_a_lambda_made_in_a_loop_sees_the_last_value(demo_findings):
    late = _run(demo_findings, LOOP, "L013")
    assert len(late) == 1
    assert "reads \"name\" when launch runs the OpaqueFunction" in late[0][1]
    assert "name is 'beta' by then, not 'alpha'" in late[0][1]
    # both functions build /beta/sim: one node name launched twice
    assert [m for _, m in _run(demo_findings, LOOP, "N101") if '"/beta/sim"' in m]


@pytest.mark.parametrize("body", [
    # bound when the function is made
    "for name in ROBOTS:\n    ld.add_action(OpaqueFunction(function=lambda context, name=name: robot(context, name)))",
    "for name in ROBOTS:\n    ld.add_action(OpaqueFunction(function=robot, kwargs={'name': name}))",
    # a factory: each call has its own variable
    "def make(name):\n    return OpaqueFunction(function=lambda context: robot(context, name))\n"
    "for name in ROBOTS:\n    ld.add_action(make(name))",
    # the variable the function reads is not the one the loop moves
    "prefix = 'fleet_'\nfor name in ROBOTS:\n"
    "    ld.add_action(OpaqueFunction(function=lambda context, name=name: robot(context, prefix + name)))",
])
def test_values_bound_when_made_are_quiet(demo_findings, body):
    assert _run(demo_findings, body, "L013") == []
    assert _run(demo_findings, body, "N101") == []


def test_a_nested_def_an_event_handler_calls(demo_findings):
    body = """
for ns in ROBOTS:
    watched = Node(package='turtlesim', executable='turtlesim_node', name='watched', namespace=ns)
    ld.add_action(watched)

    def done(event, context):
        return [LogInfo(msg='turtle of ' + ns + ' exited')]

    ld.add_action(RegisterEventHandler(OnProcessExit(target_action=watched, on_exit=done)))
"""
    late = _run(demo_findings, body, "L013")
    assert len(late) == 1 and "when launch runs the OnProcessExit handler" in late[0][1]


def test_a_variable_assigned_after_the_function_is_read_then(demo_findings):
    # launch runs the function after generate_launch_description has returned: it sees `exe`,
    # which the body could not read when the OpaqueFunction was made. Not a mistake: no L013, but
    # the node is known, and its wrong executable reported.
    body = """
ld.add_action(OpaqueFunction(function=lambda context: [
    Node(package='demo', executable=exe, name='sim')]))
exe = 'talker'
"""
    assert _run(demo_findings, body, "L013") == []
    assert [m for _, m in _run(demo_findings, body, "U102") if '"talker"' in m]
