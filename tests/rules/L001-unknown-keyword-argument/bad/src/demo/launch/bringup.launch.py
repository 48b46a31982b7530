from launch import LaunchDescription
from launch.actions import ExecuteProcess
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(
            package='demo_nodes_cpp',
            node_executable='talker',
            node_name='talker',
            paramters=[{'rate': 2.0}],
        ),
        ExecuteProcess(cmd=['ros2', 'bag', 'record', '-a'], namespace='robot1'),
    ])
