from launch import LaunchDescription
from launch.actions import GroupAction
from launch_ros.actions import Node, SetRemap


def generate_launch_description():
    return LaunchDescription([
        Node(package='rover_teleop', executable='keyboard_teleop', name='teleop',
             remappings=[('cmd_vel', 'cmd_vel_safe')]),
        GroupAction([
            SetRemap(src='cmd_vel', dst='cmd_vel_safe'),
            Node(package='rover_base', executable='base_driver', name='base'),
        ]),
    ])
