from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.conditions import IfCondition
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('use_rviz', default_value='yes'),
        Node(package='demo_nodes_cpp', executable='talker',
             condition=IfCondition(LaunchConfiguration('use_rviz'))),
    ])
