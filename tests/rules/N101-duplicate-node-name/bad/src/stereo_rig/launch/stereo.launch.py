from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    left = Node(
        package='usb_cam', executable='usb_cam_node_exe', name='stereo_cam',
        parameters=[{'video_device': '/dev/video0', 'frame_id': 'left_optical'}],
    )
    right = Node(
        package='usb_cam', executable='usb_cam_node_exe', name='stereo_cam',
        parameters=[{'video_device': '/dev/video1', 'frame_id': 'right_optical'}],
    )
    return LaunchDescription([left, right])
