"""Bring up several Atlas robots, each in its own namespace, and one shared RViz."""
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, GroupAction, IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution
from launch_ros.actions import PushRosNamespace
from launch_ros.substitutions import FindPackageShare

ROBOTS = [
    'atlas_1',
    'atlas-2',
]


def generate_launch_description():
    use_sim_time = LaunchConfiguration('use_sim_time')
    robot_launch = PathJoinSubstitution(
        [FindPackageShare('atlas_bringup'), 'launch', 'robot.launch.py'])

    ld = LaunchDescription([
        DeclareLaunchArgument('use_sim_time', default_value='true',
                              description='The fleet runs in simulation by default'),
    ])
    for robot in ROBOTS:
        ld.add_action(GroupAction([
            PushRosNamespace(robot),
            IncludeLaunchDescription(
                PythonLaunchDescriptionSource(robot_launch),
                launch_arguments={
                    'use_sim_time': use_sim_time,
                    'robot_name': robot,
                    'use_rviz': 'false',
                }.items(),
            ),
        ]))
    return ld
