from launch import LaunchDescription
from launch.actions import ExecuteProcess, GroupAction
from launch_ros.actions import Node, PushRosNamespace


def generate_launch_description():
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
    ])
