from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='rover_teleop', executable='keyboard_teleop', name='teleop'),
        Node(package='rover_base', executable='base_driver', name='base',
             remappings=[('odom', 'wheel_odom')]),
        Node(package='rover_base', executable='odom_logger', name='logger'),
    ])
