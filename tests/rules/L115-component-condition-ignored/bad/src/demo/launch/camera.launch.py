from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.conditions import IfCondition
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import LoadComposableNodes
from launch_ros.descriptions import ComposableNode


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('debug', default_value='false'),
        LoadComposableNodes(
            target_container='/camera/container',
            composable_node_descriptions=[
                ComposableNode(package='image_view', plugin='image_view::ImageViewNode',
                               name='viewer', namespace='camera',
                               condition=IfCondition(LaunchConfiguration('debug'))),
            ]),
    ])
