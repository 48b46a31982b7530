from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, ExecuteProcess, GroupAction
from launch_ros.actions import LifecycleNode, Node, PushRosNamespace


def generate_launch_description():
    common = {'package': 'demo_nodes_cpp', 'executable': 'listener'}
    return LaunchDescription([
        Node(
            package='demo_nodes_cpp',
            executable='talker',
            name='talker',
            parameters=[{'rate': 2.0}],
            output='screen', respawn=True, respawn_delay=2.0, emulate_tty=True,
        ),
        GroupAction([
            PushRosNamespace('robot1'),
            ExecuteProcess(cmd=['ros2', 'bag', 'record', '-a'], output='screen', name='bag'),
        ]),
        LifecycleNode(package='nav2_map_server', executable='map_server', name='map_server',
                      namespace=''),
        DeclareLaunchArgument('map', default_value='map.yaml', description='map file'),
        Node(name='listener', **common),
    ])
