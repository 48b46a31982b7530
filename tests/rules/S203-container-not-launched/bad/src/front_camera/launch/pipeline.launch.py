from launch import LaunchDescription
from launch_ros.actions import ComposableNodeContainer, LoadComposableNodes
from launch_ros.descriptions import ComposableNode


def generate_launch_description():
    container = ComposableNodeContainer(
        name='camera_container',
        namespace='front',
        package='rclcpp_components',
        executable='component_container_mt',
    )
    load = LoadComposableNodes(
        target_container='/front/cam_container',
        composable_node_descriptions=[
            ComposableNode(package='image_proc', plugin='image_proc::RectifyNode', name='rectify',
                           namespace='front'),
        ],
    )
    return LaunchDescription([container, load])
