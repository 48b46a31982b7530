"""Rectify the camera image and detect obstacles, both as components in one container."""
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution
from launch_ros.actions import ComposableNodeContainer
from launch_ros.descriptions import ComposableNode
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    use_sim_time = LaunchConfiguration('use_sim_time')
    camera_ns = LaunchConfiguration('camera_ns')
    params_file = PathJoinSubstitution(
        [FindPackageShare('atlas_perception'), 'config', 'perception.yaml'])

    container = ComposableNodeContainer(
        name='perception_container',
        namespace='',
        package='rclcpp_components',
        executable='component_container_mt',
        output='screen',
        composable_node_descriptions=[
            ComposableNode(
                package='image_proc',
                plugin='image_proc::RectifyNode',
                name='rectify',
                namespace=camera_ns,
                parameters=[{'use_sim_time': use_sim_time}],
                remappings=[('/image', 'image_raw')],
            ),
            ComposableNode(
                package='atlas_perception',
                plugin='atlas_perception::ObstacleDetector',
                name='obstacle_detector',
                parameters=[params_file, {'use_sim_time': use_sim_time}],
                remappings=[('image', [camera_ns, '/image_rect'])],
            ),
        ],
    )

    return LaunchDescription([
        DeclareLaunchArgument('use_sim_time', default_value='false'),
        DeclareLaunchArgument('camera_ns', default_value='camera',
                              description='Namespace of the camera driver'),
        container,
    ])
