"""P115: a RewrittenYaml param_rewrites key that rewrites nothing (nav2_common
``substitute_params`` replaces only keys the file has, ``add_params`` adds only paths through
ros__parameters; navigation2#3111)."""
from __future__ import annotations

from typing import Any

import pytest

LAUNCH = """from launch import LaunchDescription
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare
from nav2_common.launch import RewrittenYaml


def generate_launch_description():
    params = RewrittenYaml(
        source_file=PathJoinSubstitution([FindPackageShare('demo'), 'config', 'nav.yaml']),
        param_rewrites={REWRITES},
        convert_types=True)
    return LaunchDescription([
        Node(package='nav2_map_server', executable='map_server', name='map_server', parameters=[params]),
        Node(package='nav2_lifecycle_manager', executable='lifecycle_manager', name='lifecycle_manager',
             parameters=[{'autostart': True, 'node_names': ['map_server']}]),
    ])
"""

FILE = """map_server:
  ros__parameters:
    frame_id: map
    topics:
      map: map
"""


def _found(demo_findings: Any, rewrites: str) -> list[tuple[int, str]]:
    files = {"launch/a.launch.py": LAUNCH.replace("REWRITES", rewrites), "config/nav.yaml": FILE}
    return demo_findings(files, "launch/a.launch.py", "P115")


def test_a_key_the_file_does_not_have(demo_findings: Any) -> None:
    (line, message), = _found(demo_findings, "'yaml_filename': LaunchConfiguration('map', default='m.yaml')")
    assert line == 11
    assert message.startswith('param_rewrites key "yaml_filename" matches no key of "')
    assert message.endswith('config/nav.yaml": RewrittenYaml replaces only keys the file has (and adds dotted '
                            "paths through ros__parameters), so it writes this value nowhere and no node gets it")


@pytest.mark.parametrize("rewrite", [
    "'frame_id': 'odom'",  # a key of that name, at any depth
    "'map': 'map2'",  # a key of a nested mapping
    "'map_server.ros__parameters.topics.map': 'm'",  # an existing dotted path
    "'map_server.ros__parameters.yaml_filename': 'm.yaml'",  # added: the path runs through ros__parameters
    "'autostart': 'true'",  # given to a node directly as well: the rewrite only repeats it
])
def test_rewrites_that_write_or_repeat_a_value(demo_findings: Any, rewrite: str) -> None:
    assert _found(demo_findings, rewrite) == []


GROUPS = """from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, GroupAction
from launch.conditions import IfCondition, UnlessCondition
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare
from nav2_common.launch import RewrittenYaml


def generate_launch_description():
    params = RewrittenYaml(
        source_file=PathJoinSubstitution([FindPackageShare('demo'), 'config', 'nav.yaml']),
        param_rewrites={'yaml_filename': 'map.yaml'}, convert_types=True)
    composition = LaunchConfiguration('use_composition')
    return LaunchDescription([
        DeclareLaunchArgument('use_composition', default_value='True'),
        GroupAction(condition=UnlessCondition(composition), actions=[
            Node(package='nav2_map_server', executable='map_server', name='map_server', parameters=[params])]),
        GroupAction(condition=IfCondition(composition), actions=[
            Node(package='nav2_map_server', executable='map_server', name='map_server2', parameters=[params])]),
    ])
"""


def test_reported_when_the_first_use_is_in_an_inactive_group(demo_findings: Any) -> None:
    # nav2's bringup: the same rewritten file in an UnlessCondition group first, then the active one
    files = {"launch/a.launch.py": GROUPS, "config/nav.yaml": FILE}
    assert [line for line, _ in demo_findings(files, "launch/a.launch.py", "P115")] == [13]
