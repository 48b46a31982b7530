from launch import LaunchDescription
from launch.substitutions import Command, PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.parameter_descriptions import ParameterValue
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    rviz_config = PathJoinSubstitution([FindPackageShare('demo'), 'rviz', 'view.rviz'])
    xacro_file = PathJoinSubstitution([FindPackageShare('demo'), 'urdf', 'robot.urdf.xacro'])
    description = ParameterValue(Command(['xacro ', xacro_file]), value_type=str)
    return LaunchDescription([
        Node(package='robot_state_publisher', executable='robot_state_publisher',
             parameters=[{'robot_description': description}]),
        Node(package='rviz2', executable='rviz2', arguments=['-d', rviz_config]),
    ])
