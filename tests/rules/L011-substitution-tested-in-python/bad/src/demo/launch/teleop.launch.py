from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    use_joy = LaunchConfiguration('use_joy')
    use_rviz = LaunchConfiguration('use_rviz')
    actions = [
        DeclareLaunchArgument('use_joy', default_value='false'),
        DeclareLaunchArgument('use_rviz', default_value='true'),
    ]
    if use_joy:
        actions.append(Node(package='joy', executable='joy_node'))
    if use_rviz == 'true':
        actions.append(Node(package='rviz2', executable='rviz2'))
    return LaunchDescription(actions)
