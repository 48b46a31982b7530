from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, GroupAction, IncludeLaunchDescription
from launch.conditions import IfCondition, LaunchConfigurationEquals, UnlessCondition
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution, PythonExpression, ThisLaunchFileDir
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('mode', default_value='mapping',
                              choices=['mapping', 'localization']),
        DeclareLaunchArgument('use_sim', default_value='false'),
        Node(package='demo_nodes_cpp', executable='talker', name='talker',
             condition=LaunchConfigurationEquals('mode', 'mapping')),
        GroupAction(condition=IfCondition(LaunchConfiguration('use_sim')), actions=[
            Node(package='demo_nodes_cpp', executable='listener', name='listener'),
        ]),
        Node(package='demo_nodes_cpp', executable='listener', name='real_listener',
             condition=UnlessCondition(LaunchConfiguration('use_sim'))),
        Node(package='demo_nodes_cpp', executable='talker', name='map_saver',
             condition=IfCondition(PythonExpression(
                 ["'", LaunchConfiguration('mode'), "' == 'mapping'"]))),
        IncludeLaunchDescription(PathJoinSubstitution([ThisLaunchFileDir(), 'viewer.launch.xml'])),
        IncludeLaunchDescription(PathJoinSubstitution([ThisLaunchFileDir(), 'tools.launch.yaml'])),
    ])
