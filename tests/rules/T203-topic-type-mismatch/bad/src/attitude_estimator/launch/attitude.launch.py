from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='imu_driver', executable='imu_node', name='imu'),
        Node(package='attitude_estimator', executable='estimator', name='attitude',
             remappings=[('imu', 'imu/mag')]),
    ])
