from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import ComposableNodeContainer
from launch_ros.descriptions import ComposableNode


def generate_launch_description():
    # "1" is fine for IfCondition, but YAML types it as the integer 1
    intra = DeclareLaunchArgument('intra_process', default_value='1')
    container = ComposableNodeContainer(
        name='camera_container',
        namespace='front',
        package='rclcpp_components',
        executable='component_container_mt',
        composable_node_descriptions=[
            ComposableNode(package='image_proc', plugin='image_proc::RectifyNode', name='rectify',
                           extra_arguments=[{'use_intra_process_comms': LaunchConfiguration('intra_process')}]),
            ComposableNode(package='image_proc', plugin='image_proc::DebayerNode', name='debayer',
                           extra_arguments=[{'use_intra_process_comms': 'true'}]),
        ],
    )
    return LaunchDescription([intra, container])
