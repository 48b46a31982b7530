from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch_ros.actions import Node


def add_launch_arg(name, default_value=None):
    return DeclareLaunchArgument(name, default_value=default_value)


def generate_launch_description():
    return LaunchDescription([
        add_launch_arg('serial_baudrate', '115200'),
        add_launch_arg('scan_mode', 'Standard'),
        Node(package='rplidar_ros', executable='rplidar_node'),
    ])
