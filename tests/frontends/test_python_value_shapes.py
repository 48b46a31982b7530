"""Shapes of Python launch values that launch accepts and the frontend used to give up on: a set of
remap rules, a TextSubstitution of a path computed in Python."""
from __future__ import annotations

from typing import Any

SET_REMAP = """from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='demo_nodes_cpp', executable='listener', name='listener',
             remappings={('chatter', 'chatter')}),
    ])
"""

TEXT_PATH = """import os
from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.substitutions import TextSubstitution
from launch_ros.actions import Node


def generate_launch_description():
    params = TextSubstitution(text=os.path.join(get_package_share_directory('demo'), 'config', 'gone.yaml'))
    return LaunchDescription([
        Node(package='demo_nodes_cpp', executable='talker', name='talker', parameters=[params]),
    ])
"""


def test_remappings_given_as_a_set_are_rules(demo_findings: Any) -> None:
    # launch_ros only iterates the rules: a set of one rule is that rule
    found = demo_findings({"launch/a.launch.py": SET_REMAP}, "launch/a.launch.py", "T101")
    assert [m for _, m in found] == ['remap "chatter" -> "chatter" maps a name to itself']


def test_a_text_substitution_of_a_python_path_is_that_path(demo_findings: Any) -> None:
    found = demo_findings({"launch/a.launch.py": TEXT_PATH}, "launch/a.launch.py", "P101")
    assert len(found) == 1 and "share/demo/config/gone.yaml" in found[0][1]
