from launch import LaunchDescription
from launch.actions import (DeclareLaunchArgument, GroupAction, IncludeLaunchDescription, LogInfo,
                            SetEnvironmentVariable)
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare

RATE = 30


def generate_launch_description():
    use_sim_time = LaunchConfiguration('use_sim_time')
    world = PathJoinSubstitution([FindPackageShare('sim_bringup'), 'launch', 'world.launch.py'])
    return LaunchDescription([
        DeclareLaunchArgument('use_sim_time', default_value=True),
        DeclareLaunchArgument('rate', default_value=RATE),
        SetEnvironmentVariable('RCUTILS_COLORIZED_OUTPUT', 1),
        LogInfo(msg=0.5),
        IncludeLaunchDescription(PythonLaunchDescriptionSource(world),
                                 launch_arguments={'use_sim_time': use_sim_time}),
        IncludeLaunchDescription(PythonLaunchDescriptionSource(world),
                                 launch_arguments={'use_sim_time': False}.items()),
        GroupAction([LogInfo(msg='in group')], launch_configurations={'rate': 10}),
        Node(package='demo_nodes_cpp', executable='talker',
             arguments=['--rate', 10],
             remappings=[['chatter', 'chat']]),
        Node(package='demo_nodes_cpp', executable='listener',
             remappings={'chatter': 'chat'}),
    ])
