from launch import LaunchDescription
from launch_ros.actions import Node, SetUseSimTime


def generate_launch_description():
    return LaunchDescription([
        SetUseSimTime(True),
        Node(package='demo_nodes_cpp', executable='talker'),
    ])
