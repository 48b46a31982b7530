from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('greeting', default_value='note: hello'),
        Node(package='demo_nodes_cpp', executable='talker',
             parameters=[{'greeting': LaunchConfiguration('greeting')}]),
    ])
