"""U104 for paths into a workspace package's share directory given as parameter values: the
node is given a path that is not there (a ros_gz bridge's config_file, a behavior tree)."""
from __future__ import annotations

from typing import Any

LAUNCH = """from launch import LaunchDescription
from launch.substitutions import PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    share = FindPackageShare('demo')
    return LaunchDescription([
        Node(package='ros_gz_bridge', executable='parameter_bridge', parameters=[{
            'config_file': PathJoinSubstitution([share, '@DIR@', 'bridge.yaml']),
            'output_log_file': PathJoinSubstitution([share, 'config', 'log.csv']),
            'recordFile': PathJoinSubstitution([share, 'config', 'run.bag']),
            'map_file_name': PathJoinSubstitution([share, 'config', 'office']),  # office.data, ...
            'plugins': PathJoinSubstitution([share, 'config', '*.so']),
            # a list of lists: each item a string (a flat list of substitutions is one string)
            'trees': [[PathJoinSubstitution([share, 'config', 'nav.xml'])],
                      [PathJoinSubstitution([share, 'config', 'dock.xml'])]],
        }]),
    ])
"""


def _found(demo_findings: Any, folder: str) -> list[tuple[int, str]]:
    files = {"launch/a.launch.py": LAUNCH.replace("@DIR@", folder), "config/bridge.yaml": "[]\n",
             "config/nav.xml": "<root/>\n", "bridges/bridge.yaml": "[]\n", "config/office.data": "",
             "config/office.posegraph": ""}
    return demo_findings(files, "launch/a.launch.py", "U104")


def test_a_parameter_path_that_is_not_installed_or_missing(demo_findings: Any) -> None:
    # the demo package installs launch/ and config/ only
    found = _found(demo_findings, "bridges")
    assert [(line, message.split(" (")[0].split(" but")[0]) for line, message in found] == [
        (11, 'file "bridges/bridge.yaml" given as parameter "config_file" of /ros_gz_bridge exists in the '
             'sources of package "demo"'),
        (17, 'file "config/dock.xml" given as parameter "trees" of /ros_gz_bridge does not exist in package '
             '"demo"'),
    ]


def test_installed_files_and_files_the_node_writes_are_not_reported(demo_findings: Any) -> None:
    assert [line for line, _ in _found(demo_findings, "config")] == [17]  # dock.xml alone
