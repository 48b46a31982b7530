from launch import LaunchDescription
from launch.actions import IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import PathJoinSubstitution
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    camera = IncludeLaunchDescription(
        PythonLaunchDescriptionSource(
            PathJoinSubstitution([FindPackageShare('inspection_cam'), 'launch', 'usb_cam.launch.py'])),
        launch_arguments={'video_dev': '/dev/video2'}.items(),
    )
    return LaunchDescription([camera])
