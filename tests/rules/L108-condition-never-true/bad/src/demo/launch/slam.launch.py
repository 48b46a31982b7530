from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, GroupAction
from launch.conditions import IfCondition, LaunchConfigurationEquals, UnlessCondition
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('mode', default_value='mapping',
                              choices=['mapping', 'localization']),
        DeclareLaunchArgument('use_sim', default_value='false'),
        Node(package='demo_nodes_cpp', executable='talker', name='talker',
             condition=LaunchConfigurationEquals('mode', 'maping')),
        GroupAction(condition=IfCondition(LaunchConfiguration('use_sim')), actions=[
            Node(package='demo_nodes_cpp', executable='listener', name='listener',
                 condition=UnlessCondition(LaunchConfiguration('use_sim'))),
        ]),
    ])
