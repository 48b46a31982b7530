"""launch only asks ``hasattr(module, 'generate_launch_description')`` and calls it: an assignment
(``= partial(make, 'front')``) or an import from a shared module defines it as much as a ``def``
(no L006), and a ``functools.partial`` of a function of the file is followed, there and as an
OpaqueFunction's function (its own positional arguments come before the context)."""
from __future__ import annotations

from typing import Any

PARTIAL = """from functools import partial

from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, OpaqueFunction
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def setup(side, context, prefix=''):
    mode = LaunchConfiguration('mode').perform(context)
    return [Node(package='demo_nodes_cpp', executable='talker', name=f'{prefix}{side}_{mode}')]


def make(side):
    return LaunchDescription([
        DeclareLaunchArgument('mode', default_value='fast'),
        Node(package='demo_nodes_cpp', executable='listener', name=f'{side}_listener'),
        OpaqueFunction(function=partial(setup, side, prefix='p_')),
    ])


generate_launch_description = partial(make, 'front')
"""
IMPORTED = """from demo_launch_common.descriptions import generate_launch_description  # noqa: F401
"""


def test_an_assigned_partial_is_the_entry_point(demo_graph: Any, demo_findings: Any) -> None:
    files = {"launch/a.launch.py": PARTIAL}
    assert sorted(demo_graph(files, "launch/a.launch.py")) == ["front_listener", "p_front_fast"]
    assert demo_findings(files, "launch/a.launch.py", "L006") == []


def test_an_imported_entry_point_is_no_l006(demo_findings: Any) -> None:
    assert demo_findings({"launch/b.launch.py": IMPORTED}, "launch/b.launch.py", "L006") == []
