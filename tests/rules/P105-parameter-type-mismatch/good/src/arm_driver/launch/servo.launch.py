from launch import LaunchDescription
from launch.substitutions import PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    params = PathJoinSubstitution([FindPackageShare('arm_driver'), 'config', 'servo.yaml'])
    return LaunchDescription([
        Node(
            package='arm_driver',
            executable='servo_node',
            name='servo',
            parameters=[params],
        ),
    ])
