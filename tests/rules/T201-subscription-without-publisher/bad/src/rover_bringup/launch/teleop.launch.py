from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='rover_teleop', executable='keyboard_teleop', name='teleop',
             remappings=[('cmd_vel', 'teleop/cmd_vel')]),
        Node(package='rover_base', executable='base_driver', name='base',
             remappings=[('cmd_vel', 'base/cmd_vel')]),
    ])
