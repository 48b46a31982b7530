"""L011 for launch conditions combined with Python ``and``/``or``: a condition object is always
true, so ``IfCondition(a) and UnlessCondition(b)`` is ``UnlessCondition(b)`` alone (UR's dual-robot
tutorial: launch_dashboard_client:=false did nothing)."""
from __future__ import annotations

from typing import Any

LAUNCH = """from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.conditions import IfCondition, UnlessCondition
from launch.substitutions import AndSubstitution, LaunchConfiguration, NotSubstitution
from launch_ros.actions import Node


def generate_launch_description():
    a = LaunchConfiguration("a")
    b = LaunchConfiguration("b")
    return LaunchDescription([
        DeclareLaunchArgument("a", default_value="false"),
        DeclareLaunchArgument("b", default_value="false"),
        Node(package="demo_nodes_cpp", executable="talker", name="one",
             condition=IfCondition(a) and UnlessCondition(b)),
        Node(package="demo_nodes_cpp", executable="talker", name="two",
             condition=IfCondition(AndSubstitution(a, NotSubstitution(b)))),
    ])
"""


def test_conditions_joined_with_python_and_are_reported(demo_findings: Any) -> None:
    found = demo_findings({"launch/c.launch.py": LAUNCH}, "launch/c.launch.py", "L011")
    assert found == [(15, 'IfCondition(LaunchConfiguration("a")) is tested as a Python bool while the '
                          "launch description is built: a condition object is always true (`if` always runs "
                          "its body, `and` gives the condition on its right, `or` this one), so this "
                          "condition never decides anything")]


IF_EQUALS = """from launch import LaunchDescription
from launch.conditions import LaunchConfigurationEquals
from launch_ros.actions import Node


def generate_launch_description():
    ld = LaunchDescription()
    if LaunchConfigurationEquals('depth_aligned', 'True'):
        ld.add_action(Node(package="demo_nodes_cpp", executable="talker"))
    return ld
"""


def test_a_condition_in_a_python_if_is_reported_with_its_arguments(demo_findings: Any) -> None:
    ((line, message),) = demo_findings({"launch/c.launch.py": IF_EQUALS}, "launch/c.launch.py", "L011")
    assert line == 8 and message.startswith('LaunchConfigurationEquals("depth_aligned", "True") is tested')
