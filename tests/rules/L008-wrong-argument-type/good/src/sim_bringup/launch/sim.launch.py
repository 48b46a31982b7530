from launch import LaunchDescription
from launch.actions import (DeclareLaunchArgument, GroupAction, IncludeLaunchDescription, LogInfo,
                            SetEnvironmentVariable)
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare

RATE = 30
TOPICS = ['chatter', 'status']


def generate_launch_description():
    use_sim_time = LaunchConfiguration('use_sim_time')
    world = PathJoinSubstitution([FindPackageShare('sim_bringup'), 'launch', 'world.launch.py'])
    args = {'use_sim_time': use_sim_time}
    return LaunchDescription([
        DeclareLaunchArgument('use_sim_time', default_value='true'),
        DeclareLaunchArgument('rate', default_value=str(RATE)),
        DeclareLaunchArgument('unset'),
        SetEnvironmentVariable('RCUTILS_COLORIZED_OUTPUT', '1'),
        LogInfo(msg=['rate ', LaunchConfiguration('rate')]),
        IncludeLaunchDescription(PythonLaunchDescriptionSource(world), launch_arguments=args.items()),
        IncludeLaunchDescription(PythonLaunchDescriptionSource(world),
                                 launch_arguments=[('use_sim_time', 'false')]),
        IncludeLaunchDescription(PythonLaunchDescriptionSource(world), launch_arguments={}),
        GroupAction([LogInfo(msg='in group')], launch_configurations={'rate': '10'}),
        Node(package='demo_nodes_cpp', executable='talker',
             arguments=['--rate', str(10)],
             parameters=[{'rate': 10, 'use_sim_time': True}],
             remappings=[('chatter', 'chat')]),
        Node(package='demo_nodes_cpp', executable='listener',
             remappings=list(zip(TOPICS, ['/a/' + t for t in TOPICS])) + [tuple(['x', 'y'])]),
        Node(package='demo_nodes_cpp', executable='listener', name='listener2',
             remappings={'chatter': 'chat'}.items()),
    ])
