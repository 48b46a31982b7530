from launch import LaunchDescription
from launch.substitutions import PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    calibration = PathJoinSubstitution([FindPackageShare('demo'), 'config', 'front.yaml'])
    return LaunchDescription([
        Node(package='usb_cam', executable='usb_cam_node_exe', name='front',
             parameters=[{'camera_name': 'front',
                          'camera_info_url': ['file://', calibration]}]),
        Node(package='gscam', executable='gscam_node', name='rear',
             parameters=[PathJoinSubstitution([FindPackageShare('demo'), 'config', 'rear.yaml'])]),
    ])
