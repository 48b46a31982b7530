from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, RegisterEventHandler
from launch.conditions import IfCondition
from launch.event_handlers import OnProcessExit
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    talker = Node(package='demo_nodes_cpp', executable='talker',
                  condition=IfCondition(LaunchConfiguration('use_talker')))
    listener = Node(package='demo_nodes_cpp', executable='listener')
    return LaunchDescription([
        DeclareLaunchArgument('use_talker', default_value='false'),
        talker,
        RegisterEventHandler(OnProcessExit(target_action=talker, on_exit=[listener])),
    ])
