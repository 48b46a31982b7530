from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, ExecuteProcess
from launch_ros.actions import LifecycleNode, Node


def generate_launch_description():
    return LaunchDescription([
        Node(
            package='demo_nodes_cpp',
            node_executable='talker',
            node_name='talker',
            paramters=[{'rate': 2.0}],
        ),
        ExecuteProcess(cmd=['ros2', 'bag', 'record', '-a'], namespace='robot1'),
        LifecycleNode(package='nav2_map_server', executable='map_server', name='map_server'),
        DeclareLaunchArgument(default_value='map.yaml', description='map file'),
        Node('demo_nodes_cpp', 'listener'),
    ])
