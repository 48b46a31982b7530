from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, ExecuteProcess, GroupAction
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('respawn_delay', default_value='2.0'),
        DeclareLaunchArgument('tty', default_value='false'),
        DeclareLaunchArgument('scoped', default_value='false'),
        Node(package='demo_nodes_cpp', executable='talker', respawn=True,
             respawn_delay=LaunchConfiguration('respawn_delay'),
             emulate_tty=LaunchConfiguration('tty')),
        ExecuteProcess(cmd=['ls'], shell='false'),
        GroupAction([Node(package='demo_nodes_cpp', executable='listener')],
                    scoped=LaunchConfiguration('scoped')),
    ])
