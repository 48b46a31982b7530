from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    robot = LaunchConfiguration('robot')
    return LaunchDescription([
        DeclareLaunchArgument('robot', default_value='scout'),
        Node(
            package='robot_state_publisher',
            executable='robot_state_publisher',
            namespace='/' + robot,
        ),
    ])
