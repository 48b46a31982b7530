"""L008 for on_exit= given something that is no action: a launch argument cannot choose the
actions a process runs when it exits (go2_ros2_sdk: on_exit=LaunchConfiguration('on_exit'))."""
from __future__ import annotations

from typing import Any

LAUNCH = """from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, ExecuteProcess, Shutdown
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('on_exit', default_value='shutdown'),
        Node(package='demo_nodes_cpp', executable='talker', on_exit=LaunchConfiguration('on_exit')),
        ExecuteProcess(cmd=['sleep', '1'], on_exit='shutdown'),
        Node(package='demo_nodes_cpp', executable='listener', on_exit=Shutdown()),
        ExecuteProcess(cmd=['sleep', '2'], on_exit=[Shutdown()]),
    ])
"""


def test_on_exit_given_no_action_is_reported(demo_findings: Any) -> None:
    found = demo_findings({"launch/a.launch.py": LAUNCH}, "launch/a.launch.py", "L008")
    assert [(line, m.split(":")[0]) for line, m in found] == [
        (10, "Node(on_exit=...) is given LaunchConfiguration('on_exit'), a substitution, where launch wants "
             "actions to run"),
        (11, "ExecuteProcess(on_exit=...) is given 'shutdown', a string, where launch wants actions to run")]
    assert "RuntimeError" in found[0][1] and "TypeError" in found[1][1]
