from launch import LaunchDescription
from launch.actions import IncludeLaunchDescription
from launch.launch_description_sources import AnyLaunchDescriptionSource
from launch.substitutions import PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    return LaunchDescription([
        Node(package='tf2_ros', executable='static_transform_publisher', name='lidar_tf',
             arguments=['--x', '0.12', '--z', '0.31', '--yaw', '3.14159',
                        '--frame_id', 'base_link', '--child_frame_id', 'lidar_link']),
        Node(package='tf2_ros', executable='static_transform_publisher', name='imu_tf',
             arguments=['0', '0', '0.1', '0', '0', '0', 'base_link']),
        Node(package='tf2_ros', executable='static_transform_publisher', name='gps_tf',
             arguments=['--x', '0.5', '--roll', '0.1', '--qw', '1.0',
                        '--frame-id', 'base_link', '--child-frame-id', 'gps_link']),
        IncludeLaunchDescription(AnyLaunchDescriptionSource(
            PathJoinSubstitution([FindPackageShare('demo'), 'launch', 'camera.launch.xml']))),
    ])
