from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, ExecuteProcess, GroupAction
from launch.conditions import IfCondition, UnlessCondition
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    scoped = LaunchConfiguration('scoped')
    listener = Node(package='demo_nodes_cpp', executable='listener')
    return LaunchDescription([
        DeclareLaunchArgument('respawn', default_value='true'),
        DeclareLaunchArgument('emulate_tty', default_value='false'),
        DeclareLaunchArgument('scoped', default_value='false'),
        Node(package='demo_nodes_cpp', executable='talker', respawn=LaunchConfiguration('respawn'),
             respawn_delay=2.0, emulate_tty=True),
        Node(package='demo_nodes_cpp', executable='talker', name='talker2',
             respawn_delay='2.0'),  # never respawned: the delay is never compared
        Node(package='demo_nodes_cpp', executable='listener', name='listener2',
             emulate_tty='True'),  # a string is always true: on, as it says
        ExecuteProcess(cmd=['ls'], shell=False, output=LaunchConfiguration('emulate_tty')),
        GroupAction([listener], scoped=True, condition=IfCondition(scoped)),
        GroupAction([listener], scoped=False, condition=UnlessCondition(scoped)),
    ])
