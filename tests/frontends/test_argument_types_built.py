"""L008 for values the launch API refuses when the description is built (humble launch 1.0.7 /
launch_ros 0.19.8): an int TimerAction period (ensure_argument_type), an EmitEvent given no event,
a remap rule given without its list."""
from __future__ import annotations

from typing import Any

import pytest

LAUNCH = """from launch import LaunchDescription
from launch.actions import EmitEvent, LogInfo, Shutdown, TimerAction
from launch.events import Shutdown as ShutdownEvent
from launch_ros.actions import Node, RosTimer


def generate_launch_description():
    return LaunchDescription([
        {action},
    ])
"""


def _l008(demo_findings: Any, action: str) -> list[tuple[int, str]]:
    return demo_findings({"launch/a.launch.py": LAUNCH.format(action=action)}, "launch/a.launch.py", "L008")


@pytest.mark.parametrize(("action", "says"), [
    ("TimerAction(period=5, actions=[LogInfo(msg='x')])",
     "'TimerAction' expected 'period' to be one of [<class 'str'>, <class 'launch.substitution.Substitution'>, "
     "<class 'collections.abc.Iterable'>, <class 'float'>], but got '5' of type '<class 'int'>'"),
    ("TimerAction(period=True, actions=[LogInfo(msg='x')])", "got 'True' of type '<class 'bool'>'"),
    # RosTimer calls TimerAction.__init__, whose name the error carries (humble launch_ros 0.19.8)
    ("RosTimer(period=2, actions=[LogInfo(msg='x')])", "TypeError: 'TimerAction' expected 'period'"),
    ("EmitEvent(event=Shutdown(reason='done'))", "is given launch.actions.Shutdown(...), which is no event"),
    ("EmitEvent(event='shutdown')", "EmitEvent() expected an event instance"),
    ("Node(package='demo_nodes_cpp', executable='talker', remappings=('chatter', 'talk'))",
     "is given ('chatter', 'talk'), one rule without its list"),
])
def test_values_the_api_refuses(demo_findings: Any, action: str, says: str):
    found = _l008(demo_findings, action)
    assert len(found) == 1 and found[0][0] == 9 and says in found[0][1], found


@pytest.mark.parametrize("action", [
    "TimerAction(period=5.0, actions=[LogInfo(msg='x')])",
    "TimerAction(period='5', actions=[LogInfo(msg='x')])",
    "EmitEvent(event=ShutdownEvent(reason='done'))",
    "Shutdown(reason='done')",
    "Node(package='demo_nodes_cpp', executable='talker', remappings=[('chatter', 'talk')])",
    "Node(package='demo_nodes_cpp', executable='talker', remappings=(('chatter', 'talk'),))",
])
def test_values_it_takes(demo_findings: Any, action: str):
    assert _l008(demo_findings, action) == []
