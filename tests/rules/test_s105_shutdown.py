"""S105: processes an OnShutdown handler starts (ExecuteLocal.execute returns once launch is shutting
down, which it is before the handlers run on Ctrl-C or idle)."""
from __future__ import annotations

from typing import Any

LAUNCH = """from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, GroupAction, LogInfo, OpaqueFunction, RegisterEventHandler
from launch.conditions import IfCondition
from launch.event_handlers import OnShutdown
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    saver = Node(package='nav2_map_server', executable='map_saver_cli', name='saver')
    return LaunchDescription([
        DeclareLaunchArgument('save', default_value='SAVE'),
        Node(package='slam_toolbox', executable='async_slam_toolbox_node', name='slam_toolbox'),
        RegisterEventHandler(OnShutdown(on_shutdown=[
            LogInfo(msg='bye'),
            OpaqueFunction(function=lambda context: None),
            GroupAction([saver], condition=IfCondition(LaunchConfiguration('save'))),
        ])),
    ])
"""


def test_a_node_in_a_group_of_the_handler(demo_findings: Any) -> None:
    found = demo_findings({"launch/a.launch.py": LAUNCH.replace("SAVE", "true")}, "launch/a.launch.py", "S105")
    assert [(line, m.split(" is started")[0]) for line, m in found] == [
        (14, 'the Node action "/saver" (nav2_map_server/map_saver_cli)')]


def test_a_group_disabled_by_its_condition_starts_nothing(demo_findings: Any) -> None:
    assert demo_findings({"launch/a.launch.py": LAUNCH.replace("SAVE", "false")}, "launch/a.launch.py", "S105") == []


def test_a_timer_in_the_handler_starts_nothing_either(demo_findings: Any) -> None:
    text = LAUNCH.replace("GroupAction([saver], condition=IfCondition(LaunchConfiguration('save'))),",
                          "TimerAction(period=0.5, actions=[saver]),").replace(
        "GroupAction, LogInfo", "GroupAction, LogInfo, TimerAction")
    found = demo_findings({"launch/a.launch.py": text.replace("SAVE", "true")}, "launch/a.launch.py", "S105")
    assert [line for line, _ in found] == [14]
