"""L102: launch itself reads 'emulate_tty' (ExecuteLocal) and 'launch-prefix' (Executable) for
every process it starts: declaring them is how a user turns those on for the whole launch."""
from __future__ import annotations

LAUNCH = """from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('emulate_tty', default_value='true'),
        DeclareLaunchArgument('launch-prefix', default_value=''),
        DeclareLaunchArgument('unused', default_value='x'),
        Node(package='demo_nodes_cpp', executable='talker'),
    ])
"""


def test_read_by_every_process(demo_findings):
    found = demo_findings({"launch/a.launch.py": LAUNCH}, "launch/a.launch.py", "L102")
    assert [line for line, _ in found] == [10]
    no_process = LAUNCH.replace("        Node(package='demo_nodes_cpp', executable='talker'),\n", "")
    assert [line for line, _ in demo_findings({"launch/a.launch.py": no_process}, "launch/a.launch.py", "L102")] == [
        8, 9, 10]
