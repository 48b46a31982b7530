"""A nav2 RewrittenYaml whose source file is not installed fails the launch when it opens the file
(FileNotFoundError): P102 / P101 on the RewrittenYaml. A missing SetParametersFromFile file fails
it too (launch_ros Node._perform_substitutions asserts the file exists), not only the node."""
from __future__ import annotations

from typing import Any

LAUNCH = """import os
from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node, SetParametersFromFile
from nav2_common.launch import RewrittenYaml


def generate_launch_description():
    share = get_package_share_directory('demo')
    configured = RewrittenYaml(source_file=LaunchConfiguration('params_file'), root_key='',
                               param_rewrites={'use_sim_time': 'false'}, convert_types=True)
    return LaunchDescription([
        DeclareLaunchArgument('params_file', default_value=os.path.join(share, '{folder}', 'nav2.yaml')),
        SetParametersFromFile(os.path.join(share, 'config', 'global_params.yaml')),
        Node(package='nav2_map_server', executable='map_server', name='map_server',
             parameters=[configured]),
    ])
"""
PARAMS = """map_server:
  ros__parameters:
    yaml_filename: map.yaml
"""


def _found(demo_findings: Any, folder: str, code: str) -> list[tuple[int, str]]:
    files = {"launch/a.launch.py": LAUNCH.replace("{folder}", folder), "params/nav2.yaml": PARAMS,
             "config/nav2.yaml": PARAMS}
    return [(line, msg.split("; ", 1)[1]) for line, msg in demo_findings(files, "launch/a.launch.py", code)]


def test_a_rewritten_yaml_source_that_is_not_installed(demo_findings: Any) -> None:
    assert _found(demo_findings, "params", "P102") == [
        (12, "RewrittenYaml opens it while launch runs and the launch fails with FileNotFoundError")]


def test_a_rewritten_yaml_source_that_is_installed(demo_findings: Any) -> None:
    assert _found(demo_findings, "config", "P102") == []


def test_a_missing_global_parameter_file_fails_the_launch(demo_findings: Any) -> None:
    assert _found(demo_findings, "config", "P101") == [
        (16, "SetParametersFromFile hands it to every node after it, and launch fails when it starts "
             "/map_server (AssertionError: Node._perform_substitutions asserts the file exists)")]


ROOT_KEY = """import os
from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node
from nav2_common.launch import RewrittenYaml


def generate_launch_description():
    configured = RewrittenYaml(source_file=os.path.join(get_package_share_directory('demo'), 'config', 'nav2.yaml'),
                               root_key=LaunchConfiguration('namespace'), param_rewrites={}, convert_types=True)
    return LaunchDescription([
        DeclareLaunchArgument('namespace', default_value='robot1'),
        Node(package='nav2_amcl', executable='amcl', name='amcl', namespace=LaunchConfiguration('namespace'),
             parameters=[configured]),
    ])
"""


def test_values_of_a_rewritten_file_are_checked_when_only_the_launch_file_is(demo_findings: Any) -> None:
    """Checking the launch file alone: the RewrittenYaml source is checked with it (its values reach
    /robot1/amcl through the rewritten copy), as a file given directly to the node is."""
    files = {"launch/a.launch.py": ROOT_KEY,
             "config/nav2.yaml": "amcl:\n  ros__parameters:\n    transform_tolerance: 1\n"}
    found = demo_findings(files, "launch/a.launch.py", "P105")
    assert [(line, 'parameter "transform_tolerance" of /robot1/amcl' in msg) for line, msg in found] == [(3, True)]
