"""P103 for a parameter file that nodes read only through a file nav2_common's RewrittenYaml writes
from it: rcl matches the written keys. With ``root_key`` every key is nested under it
(``data = {root_key: data}``), so nodes outside that namespace get none of the file (the nav2
bringup pattern with ``namespace`` set but ``use_namespace`` false)."""
from __future__ import annotations

import re

PARAMS = """controller_server:
  ros__parameters:
    controller_frequency: 20.0
planner_server:
  ros__parameters:
    expected_planner_frequency: 1.0
"""

LAUNCH = """from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, GroupAction
from launch.conditions import IfCondition
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution
from launch_ros.actions import Node, PushRosNamespace
from launch_ros.substitutions import FindPackageShare
from nav2_common.launch import RewrittenYaml


def generate_launch_description():
    namespace = LaunchConfiguration('namespace')
    configured = RewrittenYaml(
        source_file=PathJoinSubstitution([FindPackageShare('demo'), 'config', '{file}']),
        root_key=namespace, param_rewrites={{}}, convert_types=True)
    return LaunchDescription([
        DeclareLaunchArgument('namespace', default_value='rover1'),
        DeclareLaunchArgument('use_namespace', default_value='false'),
        GroupAction([
            PushRosNamespace(condition=IfCondition(LaunchConfiguration('use_namespace')), namespace=namespace),
            Node(package='nav2_controller', executable='controller_server', name='controller_server',
                 parameters=[configured]),
            Node(package='nav2_planner', executable='planner_server', name='planner_server',
                 parameters=[configured]),
        ]),
    ])
"""


def _p103(demo_findings, file: str = "nav2_params.yaml", params: str = PARAMS, **args: str):
    files = {"launch/nav.launch.py": LAUNCH.format(file=file), f"config/{file}": params}
    text = "\n".join(f"        DeclareLaunchArgument('{k}', default_value='{v}')," for k, v in args.items())
    if args:
        files["launch/nav.launch.py"] = files["launch/nav.launch.py"].replace(
            "        DeclareLaunchArgument('namespace', default_value='rover1'),\n"
            "        DeclareLaunchArgument('use_namespace', default_value='false'),", text)
    # paths are shown relative to the working directory
    return [(line, re.sub(r'"[^"]*src/demo/', '"src/demo/', msg))
            for line, msg in demo_findings(files, "launch/nav.launch.py", "P103")]


def test_root_key_outside_the_nodes_namespace(demo_findings):
    ((line, message),) = _p103(demo_findings)
    assert line == 1  # the source's first key
    assert message == (
        'no node key of the file written from "src/demo/config/nav2_params.yaml" matches the node(s) that '
        'load it ("/controller_server", "/planner_server"): its writer (RewrittenYaml\'s root_key "rover1") '
        'nests every key under "rover1" ("rover1/controller_server" matches /rover1/controller_server only), '
        'and the nodes run in "/"; the whole file is silently ignored')


def test_root_key_of_the_nodes_namespace_or_none(demo_findings):
    assert _p103(demo_findings, namespace="rover1", use_namespace="true") == []
    assert _p103(demo_findings, namespace="", use_namespace="false") == []


def test_written_keys_for_other_nodes(demo_findings):
    other = PARAMS.replace("controller_server:", "controller:").replace("planner_server:", "planner:")
    ((line, message),) = _p103(demo_findings, params=other, namespace="", use_namespace="false")
    assert line == 1
    assert message.startswith('no node key of the file written from "src/demo/config/nav2_params.yaml" '
                              '(as "controller") matches the node(s) that load it')
