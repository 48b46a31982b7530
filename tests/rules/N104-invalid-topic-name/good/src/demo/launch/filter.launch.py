from launch import LaunchDescription
from launch.actions import IncludeLaunchDescription
from launch.substitutions import PathJoinSubstitution, ThisLaunchFileDir
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='demo', executable='scan_filter', name='scan_filter'),
        IncludeLaunchDescription(PathJoinSubstitution([ThisLaunchFileDir(), 'driver.launch.xml'])),
        IncludeLaunchDescription(PathJoinSubstitution([ThisLaunchFileDir(), 'status.launch.yaml'])),
    ])
