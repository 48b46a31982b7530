import os

from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, ExecuteProcess, OpaqueFunction
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import ComposableNodeContainer, Node
from launch_ros.descriptions import ComposableNode


def setup(context, *args, **kwargs):
    calibration = LaunchConfiguration('calibration_file').perform(context)
    return [Node(package='rplidar_ros', executable='rplidar_node', name='calibrated', namespace='calib',
                 arguments=['--calibration', os.path.basename(calibration)])]


def add_launch_arg(name, default_value=None):
    return DeclareLaunchArgument(name, default_value=default_value)


def generate_launch_description():
    return LaunchDescription([
        add_launch_arg('output', 'screen'),
        add_launch_arg('respawn', 'true'),
        add_launch_arg('prefix', ''),
        add_launch_arg('log_dir', '/tmp'),
        add_launch_arg('calibration_file', '/tmp/calibration.yaml'),
        add_launch_arg('use_intra_process', 'false'),
        Node(package='rplidar_ros', executable='rplidar_node',
             output=LaunchConfiguration('output'), respawn=LaunchConfiguration('respawn'),
             prefix=LaunchConfiguration('prefix'),
             additional_env={'ROS_LOG_DIR': LaunchConfiguration('log_dir')}),
        ComposableNodeContainer(
            package='rclcpp_components', executable='component_container', name='container',
            namespace='',
            composable_node_descriptions=[ComposableNode(
                package='rplidar_ros', plugin='rplidar_ros::RPlidarNode', name='lidar',
                extra_arguments=[{'use_intra_process_comms': LaunchConfiguration('use_intra_process')}])]),
        ExecuteProcess(cmd=['ls'], output=LaunchConfiguration('output')),
        OpaqueFunction(function=setup),
    ])
