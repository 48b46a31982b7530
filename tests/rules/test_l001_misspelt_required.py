"""L001 for a required argument given under a misspelt keyword (``TimerAction(action=[...])``):
one finding at the keyword, saying what launch raises first (humble launch 1.0.7:
"missing 1 required keyword-only argument: 'actions'"); and what the lost keyword held is not
reported as unused (L102)."""
from __future__ import annotations

from typing import Any

LAUNCH = """from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, ExecuteProcess, GroupAction, TimerAction
from launch.substitutions import LaunchConfiguration


def generate_launch_description():
    record = ExecuteProcess(cmd=['ros2', 'bag', 'record', '-o', LaunchConfiguration('bag_dir'), '/route'])
    return LaunchDescription([
        DeclareLaunchArgument('bag_dir', default_value='/tmp/bag'),
        {action},
    ])
"""


def _found(demo_findings: Any, action: str, code: str) -> list[tuple[int, str]]:
    return demo_findings({"launch/a.launch.py": LAUNCH.format(action=action)}, "launch/a.launch.py", code)


def test_a_misspelt_required_keyword_is_one_finding(demo_findings: Any):
    found = _found(demo_findings, "TimerAction(period=2.0, action=[record])", "L001")
    assert len(found) == 1 and found[0][0] == 10, found
    assert 'no keyword argument "action" (did you mean "actions"?)' in found[0][1]
    assert "missing 1 required keyword-only argument: 'actions'" in found[0][1]


def test_a_positional_parameter_is_named_so(demo_findings: Any):
    found = _found(demo_findings, "GroupAction(action=[record])", "L001")
    assert len(found) == 1 and "missing 1 required positional argument: 'actions'" in found[0][1], found


def test_an_unrelated_unknown_keyword_keeps_both_findings(demo_findings: Any):
    found = _found(demo_findings, "TimerAction(period=2.0, delay=[record])", "L001")
    assert len(found) == 2, found


def test_what_a_lost_keyword_holds_is_not_unused(demo_findings: Any):
    assert _found(demo_findings, "TimerAction(period=2.0, action=[record])", "L102") == []
    assert len(_found(demo_findings, "TimerAction(period=2.0, actions=[])", "L102")) == 1


def test_a_description_without_kwargs_reports_the_unexpected_keyword(demo_findings: Any):
    launch = LAUNCH.replace("from launch.substitutions import LaunchConfiguration",
                            "from launch.substitutions import LaunchConfiguration\n"
                            "from launch_ros.descriptions import ComposableNode")
    text = launch.format(action="ComposableNode(pakage='image_proc', plugin='image_proc::RectifyNode') and record")
    found = demo_findings({"launch/a.launch.py": text}, "launch/a.launch.py", "L001")
    assert any("unexpected keyword argument 'pakage'" in m for _, m in found), found


HANDLERS = LAUNCH.replace("GroupAction, TimerAction", "GroupAction, LogInfo, RegisterEventHandler, TimerAction\n"
                          "from launch.event_handlers import OnProcessExit, OnProcessStart, OnShutdown")


def _handler(demo_findings: Any, handler: str) -> list[tuple[int, str]]:
    text = HANDLERS.format(action=f"record,\n        RegisterEventHandler({handler})")
    return demo_findings({"launch/a.launch.py": text}, "launch/a.launch.py", "L001")


def test_event_handlers_take_their_own_keywords(demo_findings: Any):
    # humble launch 1.0.7: OnProcessExit(*, target_action=None, on_exit, **kwargs), the rest going
    # to EventHandler(matcher, entities=None, handle_once=False)
    found = _handler(demo_findings, "OnProcessExit(target_action=record, on_start=[LogInfo(msg='done')])")
    assert len(found) == 1 and 'no keyword argument "on_start" (did you mean "on_exit"?)' in found[0][1], found
    assert "missing 1 required keyword-only argument: 'on_exit'" in found[0][1]
    found = _handler(demo_findings, "OnProcessStart(target_action=record, on_start=[], once=True)")
    assert len(found) == 1 and "unexpected keyword argument 'once'" in found[0][1], found
    found = _handler(demo_findings, "OnProcessExit(target_action=record)")
    assert len(found) == 1 and 'missing the required argument "on_exit"' in found[0][1], found
    assert _handler(demo_findings, "OnProcessExit(target_action=record, on_exit=[], handle_once=True)") == []
    assert _handler(demo_findings, "OnShutdown(on_shutdown=[LogInfo(msg='bye')])") == []
