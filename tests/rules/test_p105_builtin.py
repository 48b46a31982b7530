"""P105 (parameter-type-mismatch) knows the parameter every node declares whatever its sources:
``use_sim_time``, a bool (the client library's TimeSource). A quoted "true" in a parameter file,
or a Python string in a parameters dict (launch_ros dumps it as a YAML string), is a string and
stops the node; a substitution is typed by YAML and gives a bool."""
from __future__ import annotations

from collections.abc import Callable

LAUNCH = """
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    params = PathJoinSubstitution([FindPackageShare('demo'), 'config', 'p.yaml'])
    return LaunchDescription([
        DeclareLaunchArgument('use_sim_time', default_value='true'),
        Node(package='demo', executable='talker', name='from_file', parameters=[params]),
        Node(package='demo', executable='talker', name='from_dict', parameters=[{'use_sim_time': %s}]),
    ])
"""


def _p105(demo_findings: Callable[..., list[tuple[int, str]]], yaml: str, value: str) -> list[tuple[int, str]]:
    return demo_findings({"launch/a.launch.py": LAUNCH % value, "config/p.yaml": yaml}, "launch/a.launch.py", "P105")


def test_string_values_of_use_sim_time_are_reported(demo_findings) -> None:
    found = _p105(demo_findings, 'from_file:\n  ros__parameters:\n    use_sim_time: "true"\n',
                  "'true'")
    assert [line for line, _ in found] == [3, 14]
    for _, message in found:
        assert 'declared bool' in message and 'given "true", a string' in message
    assert "write true without quotes" in found[0][1] and "write True without quotes" in found[1][1]


def test_plain_and_substituted_values_of_use_sim_time_are_silent(demo_findings) -> None:
    assert _p105(demo_findings, "from_file:\n  ros__parameters:\n    use_sim_time: True\n",
                 "LaunchConfiguration('use_sim_time')") == []
