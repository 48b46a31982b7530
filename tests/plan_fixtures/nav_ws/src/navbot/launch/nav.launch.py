"""nav2_bringup's shape: an unknown params file before the node_names dict, components loaded by
container name into a Node running component_container, ROS arguments on every node."""
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import LoadComposableNodes, Node
from launch_ros.descriptions import ComposableNode


def generate_launch_description():
    params = LaunchConfiguration('params_file')
    ros_args = ['--ros-args', '--log-level', 'info']
    return LaunchDescription([
        DeclareLaunchArgument('params_file'),
        Node(package='rclcpp_components', executable='component_container', name='nav_container',
             arguments=ros_args),
        Node(package='nav2_map_server', executable='map_server', name='map_server',
             parameters=[params], arguments=ros_args),
        LoadComposableNodes(target_container='nav_container', composable_node_descriptions=[
            ComposableNode(package='nav2_amcl', plugin='nav2_amcl::AmclNode', name='amcl', namespace='',
                           parameters=[params]),
            ComposableNode(package='nav2_map_server', plugin='nav2_map_server::MapServer',
                           name='map_server', namespace='', parameters=[params]),
        ]),
        Node(package='nav2_lifecycle_manager', executable='lifecycle_manager',
             name='lifecycle_manager_localization', arguments=ros_args,
             parameters=[params, {'autostart': True}, {'node_names': ['map_server', 'amcl']}]),
    ])
