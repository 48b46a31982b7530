from launch import LaunchDescription
from launch.actions import GroupAction
from launch_ros.actions import Node, PushRosNamespace


def generate_launch_description():
    return LaunchDescription([
        GroupAction([
            PushRosNamespace('lidar_3d'),
            Node(package='velodyne_driver', executable='velodyne_driver_node', name='driver'),
        ]),
    ])
