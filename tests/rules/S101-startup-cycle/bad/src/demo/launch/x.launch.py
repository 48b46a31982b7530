from launch import LaunchDescription
from launch.actions import RegisterEventHandler
from launch.event_handlers import OnProcessStart
from launch_ros.actions import Node


def generate_launch_description():
    talker = Node(package='demo_nodes_cpp', executable='talker')
    listener = Node(package='demo_nodes_cpp', executable='listener')
    return LaunchDescription([
        RegisterEventHandler(OnProcessStart(target_action=talker, on_start=[listener])),
        RegisterEventHandler(OnProcessStart(target_action=listener, on_start=[talker])),
    ])
