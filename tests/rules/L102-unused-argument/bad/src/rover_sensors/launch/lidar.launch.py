from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('serial_port', default_value='/dev/ttyUSB0'),
        DeclareLaunchArgument('frame_id', default_value='laser_link'),
        Node(
            package='rplidar_ros',
            executable='rplidar_node',
            parameters=[{'serial_port': LaunchConfiguration('serial_port'), 'frame_id': 'laser_link'}],
        ),
    ])
