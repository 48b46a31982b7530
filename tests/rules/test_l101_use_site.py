"""L101 where a LaunchConfiguration held in a Python variable is read by a condition: at the
condition (the read launch makes there fails), with the LaunchConfiguration related; other reads,
inline ones and those an OpaqueFunction's body performs stay where they are written."""
from __future__ import annotations

from typing import Any

from physai_lint.engine import CheckOptions, run_check

LAUNCH = """from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, LogInfo, OpaqueFunction
from launch.conditions import IfCondition
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def setup(context):
    return [LogInfo(msg=LaunchConfiguration('late').perform(context))]


def generate_launch_description():
    use_rviz = LaunchConfiguration('use_rviz')
    rate = LaunchConfiguration('rate')
    rviz = Node(package='rviz2', executable='rviz2',
                condition=IfCondition(use_rviz))
    ld = LaunchDescription()
    ld.add_action(rviz)
    ld.add_action(LogInfo(msg=['rate ', rate]))
    ld.add_action(LogInfo(msg=LaunchConfiguration('inline')))
    ld.add_action(OpaqueFunction(function=setup))
    ld.add_action(DeclareLaunchArgument('use_rviz', default_value='true'))
    ld.add_action(DeclareLaunchArgument('rate', default_value='10'))
    ld.add_action(DeclareLaunchArgument('inline', default_value='x'))
    ld.add_action(DeclareLaunchArgument('late', default_value='x'))
    return ld
"""


def test_reported_where_the_variable_is_used(demo_package: Any, tmp_path: Any) -> None:
    root = demo_package({"launch/a.launch.py": LAUNCH})
    opts = CheckOptions(paths=[str(root / "launch/a.launch.py")], workspace=str(tmp_path), cache=False)
    found = sorted((f.span.line, f.message.split('"')[1], [r.span.line for r in f.related])
                   for f in run_check(opts).findings if f.code == "L101")
    assert found == [
        (9, "late", []),  # performed in the function's body: there
        (14, "rate", []),  # read by an action: where it is written
        (16, "use_rviz", [13]),  # the condition that reads it; the LaunchConfiguration related
        (20, "inline", []),  # written in the action
    ]
