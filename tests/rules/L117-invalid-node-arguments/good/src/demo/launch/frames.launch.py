from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, IncludeLaunchDescription
from launch.launch_description_sources import AnyLaunchDescriptionSource
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('lidar_frame', default_value='lidar_link'),
        Node(package='tf2_ros', executable='static_transform_publisher', name='lidar_tf',
             arguments=['--x', '0.12', '--z', '0.31', '--yaw', '3.14159',
                        '--frame-id', 'base_link', '--child-frame-id', LaunchConfiguration('lidar_frame')]),
        # the old positional forms: 8 words (x y z yaw pitch roll), 9 words (a quaternion)
        Node(package='tf2_ros', executable='static_transform_publisher', name='imu_tf',
             arguments=['0', '0', '0.1', '0', '0', '0', 'base_link', 'imu_link']),
        Node(package='tf2_ros', executable='static_transform_publisher', name='gps_tf',
             arguments=['0.5', '0', '0', '0', '0', '0', '1', 'base_link', 'gps_link']),
        # ROS arguments are taken out before the program parses the rest
        Node(package='tf2_ros', executable='static_transform_publisher', name='map_tf',
             arguments=['--frame-id', 'map', '--child-frame-id', 'odom', '--ros-args', '--log-level', 'warn']),
        IncludeLaunchDescription(AnyLaunchDescriptionSource(
            PathJoinSubstitution([FindPackageShare('demo'), 'launch', 'camera.launch.xml']))),
    ])
