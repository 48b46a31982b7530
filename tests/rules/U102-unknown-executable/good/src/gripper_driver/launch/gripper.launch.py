from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(
            package='gripper_driver',
            executable='gripper_node',
            name='gripper',
            parameters=[{'device': '/dev/ttyACM0'}],
        ),
    ])
