"""S201 stays on beside nodes whose name is unknown when they cannot be lifecycle nodes (an unnamed
rviz2, a ros2_control spawner), and points at the list item of a parameter file's node_names."""
from __future__ import annotations

from typing import Any

LAUNCH = """import os
from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch_ros.actions import {kind}


def generate_launch_description():
    params = os.path.join(get_package_share_directory('demo'), 'config', 'nav.yaml')
    return LaunchDescription([
        Node(package='nav2_controller', executable='controller_server', name='controller_server'),
        Node(package='nav2_lifecycle_manager', executable='lifecycle_manager',
             name='lifecycle_manager_navigation', parameters=[params]),
        {kind}(package='rviz2', executable='rviz2', output='screen'),
        Node(package='controller_manager', executable='spawner', arguments=['diff_drive_controller']),
    ])
"""
PARAMS = """lifecycle_manager_navigation:
  ros__parameters:
    autostart: true
    node_names:
      - controller_server
      - smoother_server
      - bt_navigator
"""


def _s201(demo_findings: Any, kind: str) -> list[tuple[int, str]]:
    files = {"launch/nav.launch.py": LAUNCH.replace("{kind}", kind if kind == "Node" else "Node, " + kind),
             "config/nav.yaml": PARAMS}
    return [(line, msg.split(" (")[0]) for line, msg in
            demo_findings(files, "launch/nav.launch.py", "S201")]


def test_plain_unnamed_nodes_leave_s201_on_and_items_are_located(demo_findings: Any) -> None:
    assert _s201(demo_findings, "Node") == [
        (6, 'lifecycle manager /lifecycle_manager_navigation manages "smoother_server"'),
        (7, 'lifecycle manager /lifecycle_manager_navigation manages "bt_navigator"'),
    ]


def test_an_unnamed_lifecycle_node_may_be_the_missing_one(demo_findings: Any) -> None:
    assert _s201(demo_findings, "LifecycleNode") == []


ROS2_RUN = """from launch import LaunchDescription
from launch.actions import ExecuteProcess
from launch.substitutions import FindExecutable
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        ExecuteProcess(cmd=[{program}, 'run', 'nav2_amcl', 'amcl'], prefix='taskset -c 3'),
        Node(package='nav2_lifecycle_manager', executable='lifecycle_manager', name='lifecycle_manager',
             parameters=[{{'autostart': True, 'node_names': ['amcl']}}]),
    ])
"""


def test_a_ros2_run_process_may_start_the_managed_node(demo_findings: Any) -> None:
    # ros2 run starts amcl under the name its code gives it: not one launch names
    for program in ("'ros2'", "FindExecutable(name='ros2')"):
        text = ROS2_RUN.format(program=program)
        assert demo_findings({"launch/a.launch.py": text}, "launch/a.launch.py", "S201") == []
    text = ROS2_RUN.format(program="'taskset'")
    assert [line for line, _ in demo_findings({"launch/a.launch.py": text}, "launch/a.launch.py", "S201")] == [11]
