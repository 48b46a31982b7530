"""N105 for the ROS arguments of ``ExecuteProcess(cmd=['ros2', 'run', pkg, exe, ...])``: the
arguments after the executable are its command line, which rcl parses like a Node's (rcl
arguments.c :: _rcl_parse_remap_namespace_replacement wants a fully qualified __ns)."""
from __future__ import annotations

from typing import Any

import pytest

LAUNCH = """from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, ExecuteProcess
from launch.substitutions import LaunchConfiguration


def generate_launch_description():
    robot = LaunchConfiguration('robot')
    return LaunchDescription([
        DeclareLaunchArgument('robot', default_value='tb3_0'),
        ExecuteProcess(cmd=[{cmd}], output='screen'),
    ])
"""


@pytest.mark.parametrize(("cmd", "bad"), [
    ("'ros2', 'run', 'teleop_twist_keyboard', 'teleop_twist_keyboard', '--ros-args', '-r', ['__ns:=', robot]", True),
    ("'ros2', 'run', 'teleop_twist_keyboard', 'teleop_twist_keyboard', '--ros-args', '-r', ['__ns:=/', robot]", False),
    ("'ros2', 'run', 'teleop_twist_keyboard', 'teleop_twist_keyboard', '--ros-args', '-r', 'cmd_vel:=1bad'", True),
    ("'ros2', 'run', 'teleop_twist_keyboard', 'teleop_twist_keyboard', 'cmd_vel:=1bad'", False),  # not a rule to rcl
    ("'ros2', 'launch', 'teleop_twist_keyboard', 'x.launch.py', '--ros-args', '-r', '__ns:=tb3_0'", False),
    ("'echo', 'run', 'a', 'b', '--ros-args', '-r', '__ns:=tb3_0'", False),
])
def test_ros2_run_arguments_are_read_as_the_executable_s_command_line(demo_findings: Any, cmd: str, bad: bool):
    found = demo_findings({"launch/a.launch.py": LAUNCH.format(cmd=cmd)}, "launch/a.launch.py", "N105")
    assert (found != []) is bad, found
