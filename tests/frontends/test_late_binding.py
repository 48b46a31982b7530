"""Functions launch calls later (an OpaqueFunction's, an event handler's) read the variables of the
enclosing function when they run, after ``generate_launch_description`` has returned: Python
closures hold variables, not values (``calls.late_bindings``, L013)."""
import pytest

PY = """
from launch import LaunchDescription
from launch.actions import LogInfo, OpaqueFunction, RegisterEventHandler
from launch.event_handlers import OnProcessExit
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node
from ament_index_python.packages import get_package_share_directory

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
    # the loop makes an equal value each time: what the function reads has not changed
    "for name in ROBOTS:\n    extra = '_x'\n"
    "    ld.add_action(OpaqueFunction(function=lambda context, name=name: robot(context, name + extra)))",
    "for name in ROBOTS:\n    share = get_package_share_directory('turtlesim')\n"
    "    ld.add_action(OpaqueFunction(function=lambda context, name=name: robot(context, share + name)))",
    "for name in ROBOTS:\n    sim = LaunchConfiguration('use_sim_time', default='false')\n"
    "    ld.add_action(OpaqueFunction(function=lambda context, name=name: [LogInfo(msg=sim)]))",
    # names the body binds itself: a nested function's parameter, a lambda's, an exception's
    "for ns in ROBOTS:\n    def setup(context, ns=ns):\n        def fix(ns):\n            return ns\n"
    "        return robot(context, fix(ns))\n    ld.add_action(OpaqueFunction(function=setup))",
    "for name in ROBOTS:\n    ld.add_action(OpaqueFunction(function=lambda context, robot_name=name: "
    "robot(context, sorted([robot_name], key=lambda name: name)[0])))",
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


def test_the_help_of_a_handler_binds_after_the_event_and_the_context(demo_package, tmp_path):
    from physai_lint.engine import CheckOptions, run_check

    body = """
for ns in ROBOTS:
    watched = Node(package='turtlesim', executable='turtlesim_node', name='watched', namespace=ns)
    ld.add_action(watched)
    ld.add_action(RegisterEventHandler(OnProcessExit(
        target_action=watched, on_exit=lambda event, context: [LogInfo(msg=ns)])))
"""
    text = PY.replace("@BODY@", "\n".join("    " + line for line in body.strip("\n").splitlines()))
    root = demo_package({"launch/fleet.launch.py": text})
    opts = CheckOptions(paths=[str(root / "launch/fleet.launch.py")], workspace=str(tmp_path), cache=False)
    (finding,) = [f for f in run_check(opts).findings if f.code == "L013"]
    assert "lambda event, context, ns=ns" in finding.help and "kwargs" not in finding.help


def test_nested_functions_made_in_loops_run_a_bounded_number_of_times(demo_findings):
    # each level's first run is superseded when it is run again: what it made is not run again
    import physai_lint.frontends.python.calls as calls

    body = """
for a in range(3):
    def f0(context):
        out = []
        for b in range(3):
            def f1(context):
                return [LogInfo(msg=str(a) + str(b))]
            out.append(OpaqueFunction(function=f1))
        return out
    ld.add_action(OpaqueFunction(function=f0))
"""
    runs = []
    original = calls.call_user

    def counting(ev, f, *args, **kwargs):
        if getattr(f.node, "name", "") == "f1":
            runs.append(1)
        return original(ev, f, *args, **kwargs)

    calls.call_user = counting
    try:
        _run(demo_findings, body, "L013")
    finally:
        calls.call_user = original
    # 9 runs when made, 3 for each f0 run again, then the f1s those made that read a stale b: 21
    # (27 when the f1s made by a superseded run of f0 were run again too)
    assert len(runs) <= 21


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
