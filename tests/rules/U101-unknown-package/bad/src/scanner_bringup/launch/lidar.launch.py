from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    lidar = Node(
        package='rplidar_ros',
        executable='rplidar_node',
        parameters=[{'serial_port': '/dev/ttyUSB0', 'frame_id': 'laser'}],
    )
    tf = Node(
        package='static_transform_publisher',
        executable='static_transform_publisher',
        arguments=['0.1', '0', '0.2', '0', '0', '0', 'base_link', 'laser'],
    )
    return LaunchDescription([lidar, tf])
