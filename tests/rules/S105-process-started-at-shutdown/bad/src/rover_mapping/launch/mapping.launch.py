from launch import LaunchDescription
from launch.actions import ExecuteProcess, LogInfo, RegisterEventHandler
from launch.event_handlers import OnShutdown
from launch_ros.actions import Node


def generate_launch_description():
    slam = Node(package='slam_toolbox', executable='async_slam_toolbox_node', name='slam_toolbox')
    save_map = Node(package='nav2_map_server', executable='map_saver_cli',
                    arguments=['-f', '/tmp/site_map'])
    return LaunchDescription([
        slam,
        RegisterEventHandler(OnShutdown(on_shutdown=[
            LogInfo(msg='saving the map'),
            save_map,
        ])),
        RegisterEventHandler(OnShutdown(
            on_shutdown=[ExecuteProcess(cmd=['ros2', 'service', 'call', '/recorder/stop', 'std_srvs/srv/Trigger'])])),
    ])
