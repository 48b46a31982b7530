from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    camera = Node(
        package='usb_cam',
        executable='usb_cam_node_exe',
        name='front_camera',
        parameters=[{'video_device': '/dev/video0', 'framerate': 30.0}],
    )
    return LaunchDescription([camera])
