from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('log_level', default_value='info',
                              choices=['debug', 'info', 'warn', 'error']),
        Node(
            package='robot_localization',
            executable='ekf_node',
            name='ekf_filter_node',
            arguments=['--ros-args', '--log-level', LaunchConfiguration('log_level')],
        ),
    ])
