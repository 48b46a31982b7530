from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='nav2_map_server', executable='map_server', name='map_server',
             parameters=[{'yaml_filename': '/maps/office.yaml'}]),
        Node(package='nav2_amcl', executable='amcl', name='amcl'),
        Node(
            package='nav2_lifecycle_manager',
            executable='lifecycle_manager',
            name='lifecycle_manager_localization',
            parameters=[{'autostart': True,
                         'node_names': ['map_server',
                                        'amcl_node']}],
        ),
    ])
