from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare
from nav2_common.launch import RewrittenYaml


def generate_launch_description():
    params = RewrittenYaml(
        source_file=PathJoinSubstitution([FindPackageShare('demo'), 'config', 'localization.yaml']),
        param_rewrites={'use_sim_time': LaunchConfiguration('use_sim_time'),
                        'yaml_filename': LaunchConfiguration('map'),
                        'amcl.ros__parameters.scan_topic': 'scan_front'},
        convert_types=True)
    return LaunchDescription([
        DeclareLaunchArgument('map', default_value='/maps/depot.yaml'),
        DeclareLaunchArgument('use_sim_time', default_value='false'),
        Node(package='nav2_map_server', executable='map_server', name='map_server',
             parameters=[params]),
        Node(package='nav2_amcl', executable='amcl', name='amcl', parameters=[params]),
    ])
