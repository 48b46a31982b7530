"""L112 (dirname-after-include) compares the directory an include left behind with the one launch
runs the file from: for a file reached through FindPackageShare that is the installed share
directory, not its source directory, so two includes of files beside it are fine."""
from __future__ import annotations

TOP = """
from launch import LaunchDescription
from launch.actions import IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import PathJoinSubstitution
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    return LaunchDescription([IncludeLaunchDescription(PythonLaunchDescriptionSource(
        PathJoinSubstitution([FindPackageShare('demo'), 'launch', 'mid.launch.py'])))])
"""
MID = """
from launch import LaunchDescription
from launch.actions import IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import ThisLaunchFileDir


def generate_launch_description():
    return LaunchDescription([
        IncludeLaunchDescription(PythonLaunchDescriptionSource([ThisLaunchFileDir(), '/FIRST'])),
        IncludeLaunchDescription(PythonLaunchDescriptionSource([ThisLaunchFileDir(), '/b.launch.py'])),
    ])
"""
LEAF = """
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([Node(package='demo', executable='talker')])
"""


def _l112(demo_findings, first: str) -> list[tuple[int, str]]:
    return demo_findings({"launch/top.launch.py": TOP, "launch/mid.launch.py": MID.replace("FIRST", first),
                          "launch/a.launch.py": LEAF, "launch/b.launch.py": LEAF,
                          "launch/sub/c.launch.py": LEAF}, "launch/top.launch.py", "L112")


def test_includes_beside_an_installed_file_leave_its_own_directory(demo_findings) -> None:
    assert _l112(demo_findings, "a.launch.py") == []


def test_an_include_from_a_subdirectory_still_leaves_the_wrong_one(demo_findings) -> None:
    [(line, message)] = _l112(demo_findings, "sub/c.launch.py")
    assert line == 11
    assert "/install/demo/share/demo/launch/sub\" here, not this file's directory" in message
