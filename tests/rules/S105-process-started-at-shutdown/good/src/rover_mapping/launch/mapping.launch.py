from launch import LaunchDescription
from launch.actions import LogInfo, RegisterEventHandler
from launch.event_handlers import OnProcessExit, OnShutdown
from launch_ros.actions import Node


def generate_launch_description():
    slam = Node(package='slam_toolbox', executable='async_slam_toolbox_node', name='slam_toolbox')
    save_map = Node(package='nav2_map_server', executable='map_saver_cli',
                    arguments=['-f', '/tmp/site_map'])
    return LaunchDescription([
        slam,
        RegisterEventHandler(OnProcessExit(target_action=slam, on_exit=[save_map])),
        RegisterEventHandler(OnShutdown(on_shutdown=[LogInfo(msg='mapping session over')])),
    ])
