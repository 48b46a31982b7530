"""N101's message names the line its related note points at: the first node's name= (or the file
and line when the first one is in another file), not the line its Node( call starts on."""
LAUNCH = """from launch import LaunchDescription
from launch.actions import IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import ThisLaunchFileDir
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(
            package='demo_nodes_cpp',
            executable='talker',
            name='talker'),
        Node(package='demo_nodes_cpp', executable='talker', name='talker'),
        IncludeLaunchDescription(PythonLaunchDescriptionSource([ThisLaunchFileDir(), '/b.launch.py'])),
    ])
"""
OTHER = """from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([Node(package='demo_nodes_cpp', executable='listener', name='talker')])
"""


def test_the_message_and_the_note_agree(demo_findings):
    found = demo_findings({"launch/a.launch.py": LAUNCH, "launch/b.launch.py": OTHER}, "launch/a.launch.py", "N101")
    also = [(line, msg.split(";")[0].split(" (also at ")[1].rstrip(")")) for line, msg in found]
    assert [line for line, _ in also] == [6, 14]
    assert also[0][1].endswith("src/demo/launch/a.launch.py:13")  # b.launch.py:6, the first in a.launch.py
    assert also[1][1] == "line 13"
