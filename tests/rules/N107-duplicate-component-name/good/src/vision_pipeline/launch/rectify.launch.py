from launch import LaunchDescription
from launch_ros.actions import ComposableNodeContainer
from launch_ros.descriptions import ComposableNode


def generate_launch_description():
    container = ComposableNodeContainer(
        name='vision_container',
        namespace='',
        package='rclcpp_components',
        executable='component_container',
        composable_node_descriptions=[
            ComposableNode(package='image_proc', plugin='image_proc::RectifyNode',
                           name='rectify_left', remappings=[('image', 'left/image_raw')]),
            ComposableNode(package='image_proc', plugin='image_proc::RectifyNode',
                           name='rectify_right', remappings=[('image', 'right/image_raw')]),
        ],
    )
    return LaunchDescription([container])
