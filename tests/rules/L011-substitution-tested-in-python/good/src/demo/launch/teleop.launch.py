from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.conditions import IfCondition, LaunchConfigurationEquals
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('use_joy', default_value='false'),
        DeclareLaunchArgument('use_rviz', default_value='true'),
        Node(package='joy', executable='joy_node', condition=IfCondition(LaunchConfiguration('use_joy'))),
        Node(package='rviz2', executable='rviz2', condition=LaunchConfigurationEquals('use_rviz', 'true')),
    ])
