"""L103 for a value an include passes is reported where the include gives it (the rule's page:
"on the value's origin"), with the declaration as the related location."""
from __future__ import annotations

from typing import Any

CHILD = """from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('mode', default_value='slam', choices=['slam', 'localization']),
    ])
"""
PARENT = """from launch import LaunchDescription
from launch.actions import IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import PathJoinSubstitution
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    return LaunchDescription([
        IncludeLaunchDescription(
            PythonLaunchDescriptionSource(PathJoinSubstitution([FindPackageShare('demo'), 'launch', 'child.launch.py'])),
            launch_arguments={'mode': 'mapping'}.items()),
    ])
"""


def test_the_finding_is_at_the_include_argument(demo_findings: Any):
    found = demo_findings({"launch/child.launch.py": CHILD, "launch/parent.launch.py": PARENT},
                          "launch/parent.launch.py", "L103")
    assert [line for line, _ in found] == [12], found
    assert '"mapping" (from the include)' in found[0][1]
