from launch import LaunchDescription
from launch_ros.actions import ComposableNodeContainer, Node
from launch_ros.descriptions import ComposableNode


class CameraFragment:

    @staticmethod
    def components(camera_name):
        return [ComposableNode(package='demo', plugin='demo::Camera', name=camera_name)]


def driver(name, frame_id, rate=30.0, *extra, **more):
    return Node(package='demo', executable='driver', name=name,
                parameters=[{'frame_id': frame_id, 'rate': rate}])


def generate_launch_description():
    return LaunchDescription([
        ComposableNodeContainer(
            package='rclcpp_components', executable='component_container', name='cameras',
            namespace='',
            composable_node_descriptions=CameraFragment.components('front_camera')),
        driver('front', 'front_link', 15.0, 'extra'),
        driver('rear', frame_id='rear_link', frame='rear_link'),
    ])
