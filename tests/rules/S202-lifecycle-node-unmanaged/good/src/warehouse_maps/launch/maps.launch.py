from launch import LaunchDescription
from launch_ros.actions import LifecycleNode, Node


def generate_launch_description():
    return LaunchDescription([
        LifecycleNode(package='nav2_map_server', executable='map_server', name='map_server',
                      namespace='', parameters=[{'yaml_filename': '/maps/warehouse.yaml'}]),
        LifecycleNode(package='nav2_map_server', executable='map_server', name='keepout_filter_mask',
                      namespace='', parameters=[{'yaml_filename': '/maps/keepout.yaml'}]),
        Node(
            package='nav2_lifecycle_manager',
            executable='lifecycle_manager',
            name='lifecycle_manager_maps',
            parameters=[{'autostart': True, 'node_names': ['map_server', 'keepout_filter_mask']}],
        ),
    ])
