from launch import LaunchDescription
from launch.actions import RegisterEventHandler
from launch.event_handlers import OnProcessExit
from launch_ros.actions import Node


def generate_launch_description():
    jsb = Node(package='controller_manager', executable='spawner',
               arguments=['joint_state_broadcaster'])
    arm = Node(package='controller_manager', executable='spawner', arguments=['arm_controller'])
    return LaunchDescription([
        jsb,
        RegisterEventHandler(OnProcessExit(target_action=jsb, on_exit=[arm])),
    ])
