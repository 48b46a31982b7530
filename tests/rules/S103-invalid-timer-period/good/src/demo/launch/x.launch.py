from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, TimerAction
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('delay', default_value='5.0'),
        TimerAction(period=LaunchConfiguration('delay'), actions=[
            Node(package='demo_nodes_cpp', executable='talker'),
        ]),
        TimerAction(period=2.0, actions=[
            Node(package='demo_nodes_cpp', executable='listener'),
        ]),
    ])
