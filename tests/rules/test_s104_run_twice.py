"""S104: one process action object run twice (ExecuteLocal.execute: "executed more than once"),
and the runs that are not: a file included twice, runs under opposite conditions, a handler that
never fires."""
from __future__ import annotations

from typing import Any

import pytest

LAUNCH = """from launch import LaunchDescription
from launch.actions import (DeclareLaunchArgument, ExecuteProcess, IncludeLaunchDescription, OpaqueFunction,
                            RegisterEventHandler, TimerAction)
from launch.conditions import IfCondition, UnlessCondition
from launch.event_handlers import OnProcessExit, OnProcessStart
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare


def spawn(context):
    return [Node(package='controller_manager', executable='spawner', arguments=['arm'])]


def generate_launch_description():
    talker = Node(package='demo_nodes_cpp', executable='talker')
    ghost = Node(package='demo_nodes_cpp', executable='listener', condition=IfCondition('false'))
    arm = Node(package='controller_manager', executable='spawner', arguments=['arm'])
    bag = ExecuteProcess(cmd=['ros2', 'bag', 'record', '-a'], name='bag')
    check = ExecuteProcess(cmd=['true'], name='check')
    inc = PathJoinSubstitution([FindPackageShare('demo'), 'launch', 'b.launch.py'])
    return LaunchDescription([
        DeclareLaunchArgument('sim', default_value='true'),
        {actions},
    ])
"""

INCLUDED = """from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([Node(package='demo_nodes_cpp', executable='listener')])
"""


def _s104(demo_findings: Any, actions: str) -> list[tuple[int, str]]:
    files = {"launch/a.launch.py": LAUNCH.format(actions=actions), "launch/b.launch.py": INCLUDED}
    return demo_findings(files, "launch/a.launch.py", "S104")


def test_an_action_listed_twice(demo_findings: Any):
    found = _s104(demo_findings, "talker, talker")
    assert len(found) == 1 and found[0][0] == 17 and "the launch description runs it twice" in found[0][1], found


def test_an_action_a_handler_runs_again(demo_findings: Any):
    found = _s104(demo_findings, "talker,\n        RegisterEventHandler(OnProcessStart(target_action=talker, "
                                 "on_start=[talker]))")
    assert len(found) == 1 and found[0][0] == 26 and "the event handler at line 26 runs it again" in found[0][1]


@pytest.mark.parametrize("actions", [
    "talker",
    "IncludeLaunchDescription(PythonLaunchDescriptionSource(inc)),\n"
    "        IncludeLaunchDescription(PythonLaunchDescriptionSource(inc))",
    "OpaqueFunction(function=spawn), OpaqueFunction(function=spawn)",
    "talker, RegisterEventHandler(OnProcessStart(target_action=talker, on_start=[arm]), "
    "condition=IfCondition(LaunchConfiguration('sim'))),\n"
    "        RegisterEventHandler(OnProcessStart(target_action=talker, on_start=[arm]), "
    "condition=UnlessCondition(LaunchConfiguration('sim')))",
    "talker, ghost, RegisterEventHandler(OnProcessExit(target_action=ghost, on_exit=[talker]))",
    "talker, Node(package='demo_nodes_cpp', executable='talker', name='talker2')",
])
def test_runs_of_distinct_objects_or_that_do_not_both_happen(demo_findings: Any, actions: str):
    assert _s104(demo_findings, actions) == []


def test_an_execute_process_run_again_by_a_timer(demo_findings: Any):
    # ExecuteProcess is an ExecuteLocal too (execute_local.py: "executed more than once")
    found = _s104(demo_findings, "bag, TimerAction(period=5.0, actions=[bag])")
    assert len(found) == 1 and "a timer runs it again" in found[0][1], found


def test_a_handler_whose_target_never_runs_runs_nothing_again(demo_findings: Any):
    # check is never added: OnProcessExit(target_action=check) never fires (S102), talker runs once
    files = {"launch/a.launch.py": LAUNCH.format(
        actions="talker, RegisterEventHandler(OnProcessExit(target_action=check, on_exit=[talker]))"),
        "launch/b.launch.py": INCLUDED}
    assert demo_findings(files, "launch/a.launch.py", "S104") == []
    assert demo_findings(files, "launch/a.launch.py", "N101") == []


def test_one_object_run_twice_is_not_also_two_nodes_of_one_name(demo_findings: Any):
    files = {"launch/a.launch.py": LAUNCH.format(actions="talker, talker"), "launch/b.launch.py": INCLUDED}
    assert demo_findings(files, "launch/a.launch.py", "N101") == []
