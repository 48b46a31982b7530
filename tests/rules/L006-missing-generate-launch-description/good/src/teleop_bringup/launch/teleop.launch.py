from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='joy', executable='joy_node', name='joystick'),
        Node(package='teleop_twist_joy', executable='teleop_node', name='teleop'),
    ])
