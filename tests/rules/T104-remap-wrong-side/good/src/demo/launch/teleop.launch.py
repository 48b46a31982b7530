from launch import LaunchDescription
from launch.actions import IncludeLaunchDescription
from launch.substitutions import PathJoinSubstitution, ThisLaunchFileDir
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='teleop_twist_joy', executable='teleop_node', name='teleop',
             remappings=[('cmd_vel', '/base/cmd_vel')]),
        IncludeLaunchDescription(PathJoinSubstitution([ThisLaunchFileDir(), 'lidar.launch.xml'])),
        IncludeLaunchDescription(PathJoinSubstitution([ThisLaunchFileDir(), 'odom.launch.yaml'])),
    ])
