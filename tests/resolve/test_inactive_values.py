"""A node switched off by an empty argument, or whose start is uncertain, is not judged by an empty
value (N105, P101): with any value that starts it, the remap or the parameter file is another."""
from __future__ import annotations

LAUNCH = """
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, OpaqueFunction
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def setup(context):
    imu_topic = LaunchConfiguration('imu_topic')
    config = LaunchConfiguration('config')
    nodes = []
    if imu_topic.perform(context) != '':
        nodes.append(Node(package='demo_nodes_cpp', executable='listener', name='imu',
                          remappings=[('chatter', imu_topic)]))
    if config.perform(context) != '':
        nodes.append(Node(package='demo_nodes_cpp', executable='talker', name='cfg', parameters=[config]))
    return nodes


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('imu_topic', default_value='IMU'),
        DeclareLaunchArgument('config', default_value='CONFIG'),
        OpaqueFunction(function=setup),
    ])
"""


def _codes(demo_findings, imu: str, config: str) -> list[tuple[str, int]]:
    files = {"launch/a.launch.py": LAUNCH.replace("IMU", imu).replace("CONFIG", config)}
    return [(code, line) for code in ("N105", "P101")
            for line, _ in demo_findings(files, "launch/a.launch.py", code)]


def test_an_empty_argument_that_switches_the_node_off_is_not_its_value(demo_findings):
    assert _codes(demo_findings, "", "") == []


def test_a_value_that_starts_the_node_is_still_checked(demo_findings):
    assert _codes(demo_findings, "9bad", "") == [("N105", 14)]


def test_an_empty_value_of_a_node_whose_start_is_uncertain_is_not_judged(demo_findings):
    # rtabmap's lidar3d: the node's condition mixes the empty argument with other values
    text = LAUNCH.replace("default_value='IMU'", "default_value=''").replace("CONFIG", "")
    text = "import os\n" + text.replace("if imu_topic.perform(context) != '':",
                                        "if os.environ.get('USE_IMU') or imu_topic.perform(context):")
    assert [line for line, _ in demo_findings({"launch/a.launch.py": text}, "launch/a.launch.py", "N105")] == []
