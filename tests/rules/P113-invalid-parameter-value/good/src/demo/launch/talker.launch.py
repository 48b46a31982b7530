from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node
from launch_ros.parameter_descriptions import ParameterValue


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('greeting', default_value='note: hello'),
        Node(package='demo_nodes_cpp', executable='talker',
             parameters=[{'greeting': ParameterValue(LaunchConfiguration('greeting'), value_type=str),
                          'motto': 'a: b'}]),
    ])
