from launch import LaunchDescription
from launch.actions import GroupAction, TimerAction
from launch_ros.actions import Node, PushRosNamespace


def generate_launch_description():
    return LaunchDescription([
        GroupAction([
            PushRosNamespace('robot1'),
            Node(package='demo_nodes_cpp', executable='listener', name='listener'),
        ]),
        TimerAction(period=5.0, actions=[
            GroupAction([
                PushRosNamespace('robot1'),
                Node(package='demo_nodes_cpp', executable='talker', name='talker'),
            ]),
        ]),
    ])
