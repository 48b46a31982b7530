"""P103 (parameter-file-no-match) in a file that does reach some of the nodes loading it: a key
meant for one of them (its name misspelt, or without the node's namespace) is reported; keys for
nodes of other names are left alone, since a shared file serves nodes that other launch files
start, and so are keys that a node reading the file only under another argument value matches."""
from __future__ import annotations

from collections.abc import Callable

LAUNCH = """
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.conditions import IfCondition
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    params = PathJoinSubstitution([FindPackageShare('demo'), 'config', 'shared.yaml'])
    return LaunchDescription([
        DeclareLaunchArgument('with_mapper', default_value='false'),
        Node(package='demo', executable='talker', name='talker', parameters=[params]),
        Node(package='demo', executable='listener', name='listener', parameters=[params]),
        Node(package='demo', executable='mapper', name='mapper', parameters=[params],
             condition=IfCondition(LaunchConfiguration('with_mapper'))),
        Node(package='demo', executable='mapper', name='mapper2', parameters=[params]),
    ])
"""


def _p103(demo_findings: Callable[..., list[tuple[int, str]]], yaml: str) -> list[tuple[int, str]]:
    return demo_findings({"launch/a.launch.py": LAUNCH, "config/shared.yaml": yaml}, "launch/a.launch.py", "P103")


def test_a_misspelt_key_of_a_node_that_gets_nothing_else_is_reported(demo_findings) -> None:
    found = _p103(demo_findings, (
        "/**:\n  ros__parameters:\n    use_sim_time: true\n"
        "talker:\n  ros__parameters:\n    rate: 10\n"
        "listner:\n  ros__parameters:\n    depth: 5\n"))
    assert [line for line, _ in found] == [7]
    assert 'node key "listner"' in found[0][1] and "/listener" in found[0][1]


def test_keys_for_other_nodes_and_for_nodes_started_under_other_arguments_are_silent(
        demo_findings) -> None:
    # "mapper:" is one typo from "mapper2", which gets only "/**": but "/mapper" reads the file
    # when with_mapper is true
    assert _p103(demo_findings, (
        "/**:\n  ros__parameters:\n    use_sim_time: true\n"
        "talker:\n  ros__parameters:\n    rate: 10\n"
        "listener:\n  ros__parameters:\n    depth: 5\n"
        "mapper:\n  ros__parameters:\n    resolution: 0.05\n"
        "controller_server:\n  ros__parameters:\n    controller_frequency: 20.0\n")) == []


def test_a_key_for_a_node_that_has_its_own_key_is_left_alone(demo_findings) -> None:
    # "/talker" gets "talker:"; "talkerr:" might be for a node of that name started elsewhere
    assert _p103(demo_findings, (
        "talker:\n  ros__parameters:\n    rate: 10\n"
        "listener:\n  ros__parameters:\n    depth: 5\n"
        "talkerr:\n  ros__parameters:\n    rate: 20\n")) == []


NAMESPACED = """
from launch import LaunchDescription
from launch.substitutions import PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    params = PathJoinSubstitution([FindPackageShare('demo'), 'config', 'stack.yaml'])
    return LaunchDescription([
        Node(package='demo', executable='talker', name='domain_expert', namespace='robot1',
             parameters=[params]),
        Node(package='demo', executable='talker', name='planner', namespace='robot1',
             parameters=[params]),
    ])
"""


def test_a_whole_file_finding_explains_the_key_named_like_a_loading_node(demo_findings) -> None:
    # no key matches under /robot1: the message pairs "planner" with /robot1/planner, not the
    # first key ("helper_client", a node of another name) with the first node
    found = demo_findings({"launch/a.launch.py": NAMESPACED, "config/stack.yaml": (
        "helper_client:\n  ros__parameters:\n    timeout: 15.0\n"
        "planner:\n  ros__parameters:\n    timeout: 15.0\n")}, "launch/a.launch.py", "P103")
    assert [line for line, _ in found] == [4]
    assert 'key "planner" matches /planner only; the node is /robot1/planner' in found[0][1]
