"""S102 for an OnExecutionComplete handler registered after its target ran: Action.visit arranges
ExecutionComplete only if a handler for it is registered when the action is visited
(context.would_handle_event), so a handler added later never fires. OnProcessStart/OnProcessExit
events come later (from the process), so their order does not matter."""
import pytest

LAUNCH = """from launch import LaunchDescription
from launch.actions import ExecuteProcess, RegisterEventHandler
from launch.event_handlers import {event}
from launch_ros.actions import Node


def generate_launch_description():
    can_up = ExecuteProcess(cmd=['ip', 'link', 'set', 'can0', 'up'])
    driver = Node(package='demo', executable='driver')
    handler = RegisterEventHandler({event}(target_action=can_up, {kw}=[driver]))
    return LaunchDescription([{order}])
"""


def _s102(demo_findings, event: str, kw: str, order: str) -> list[tuple[int, str]]:
    text = LAUNCH.format(event=event, kw=kw, order=order)
    return demo_findings({"launch/a.launch.py": text}, "launch/a.launch.py", "S102")


def test_a_completion_handler_after_its_target_never_fires(demo_findings):
    assert _s102(demo_findings, "OnExecutionComplete", "on_completion", "can_up, handler") == [(10, (
        "this event handler never fires: its target action was already run when the handler was "
        "registered, and launch only emits ExecutionComplete for an action visited while a handler "
        "for it exists (Action.visit), so its actions never run"))]


def test_a_completion_handler_before_its_target_fires(demo_findings):
    assert _s102(demo_findings, "OnExecutionComplete", "on_completion", "handler, can_up") == []


def test_a_target_run_again_after_the_handler_fires_it(demo_findings):
    assert _s102(demo_findings, "OnExecutionComplete", "on_completion", "can_up, handler, can_up") == []


def test_process_events_do_not_depend_on_the_order(demo_findings):
    assert _s102(demo_findings, "OnProcessExit", "on_exit", "can_up, handler") == []


TIMED = """from launch import LaunchDescription
from launch.actions import ExecuteProcess, RegisterEventHandler, TimerAction
from launch.event_handlers import OnExecutionComplete, OnProcessExit, OnProcessStart
from launch_ros.actions import Node


def generate_launch_description():
    a = ExecuteProcess(cmd=['sleep', '1'])
    proc = ExecuteProcess(cmd=['ip', 'link', 'set', 'can0', 'up'])
    h = RegisterEventHandler(OnExecutionComplete(target_action=proc, on_completion=[
        Node(package='demo', executable='driver')]))
    return LaunchDescription([{order}])
"""


@pytest.mark.parametrize("order", [
    # the walk visits the 5 s timer's actions first; launch fires the 1 s timer first
    "TimerAction(period=5.0, actions=[proc]), TimerAction(period=1.0, actions=[h])",
    # the target runs on a's exit, the handler is registered on a's start
    "a, RegisterEventHandler(OnProcessExit(target_action=a, on_exit=[proc])), "
    "RegisterEventHandler(OnProcessStart(target_action=a, on_start=[h]))",
])
def test_the_order_of_deferred_actions_is_not_judged(demo_findings, order):
    text = TIMED.format(order=order)
    assert demo_findings({"launch/a.launch.py": text}, "launch/a.launch.py", "S102") == []


def test_a_handler_deferred_after_a_first_pass_target_is_late(demo_findings):
    text = TIMED.format(order="proc, TimerAction(period=1.0, actions=[h])")
    assert [line for line, _ in demo_findings({"launch/a.launch.py": text}, "launch/a.launch.py", "S102")] == [10]


def test_the_plan_puts_what_a_dead_handler_starts_apart(demo_package):
    from physai_lint.api_plan import compute_plan
    from physai_lint.engine import CheckOptions

    text = LAUNCH.format(event="OnExecutionComplete", kw="on_completion", order="can_up, handler")
    pkg = demo_package({"launch/a.launch.py": text})
    ws = pkg.parent.parent
    plan, _ = compute_plan(CheckOptions(paths=[], workspace=str(ws)), "src/demo/launch/a.launch.py", cwd=str(ws))
    labels = plan.labels
    assert [[labels[v] for v in stage] for stage in plan.stages] == [["ip"]]
    assert {labels[v] for v in plan.never_starts} == {"driver"}
