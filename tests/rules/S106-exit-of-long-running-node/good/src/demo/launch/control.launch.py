from launch import LaunchDescription
from launch.actions import EmitEvent, LogInfo, RegisterEventHandler
from launch.event_handlers import OnProcessExit, OnProcessStart
from launch.events import Shutdown
from launch_ros.actions import Node


def generate_launch_description():
    rsp = Node(package='robot_state_publisher', executable='robot_state_publisher',
               parameters=[{'robot_description': '<robot name="r"><link name="base"/></robot>'}])
    control = Node(package='controller_manager', executable='ros2_control_node')
    broadcaster = Node(package='controller_manager', executable='spawner', arguments=['joint_state_broadcaster'])
    drive = Node(package='controller_manager', executable='spawner', arguments=['diff_drive_controller'])
    viewer = Node(package='rviz2', executable='rviz2')
    return LaunchDescription([
        rsp, control, viewer,
        # started once robot_state_publisher is up
        RegisterEventHandler(OnProcessStart(target_action=rsp, on_start=[broadcaster])),
        # spawners end by themselves: the chain runs
        RegisterEventHandler(OnProcessExit(target_action=broadcaster, on_exit=[drive])),
        # a long-running node's exit that ends the launch, or is logged, starts no process
        RegisterEventHandler(OnProcessExit(target_action=viewer, on_exit=[EmitEvent(event=Shutdown())])),
        RegisterEventHandler(OnProcessExit(target_action=control, on_exit=[LogInfo(msg='control exited')])),
    ])
