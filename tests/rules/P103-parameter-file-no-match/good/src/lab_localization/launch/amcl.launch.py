from launch import LaunchDescription
from launch.substitutions import PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    params = PathJoinSubstitution([FindPackageShare('lab_localization'), 'config', 'amcl.yaml'])
    robot = PathJoinSubstitution([FindPackageShare('lab_localization'), 'config', 'robot.yaml'])
    return LaunchDescription([
        Node(
            package='nav2_amcl',
            executable='amcl',
            name='amcl',
            parameters=[params],
        ),
        # robot.yaml is shared: its "/**" key reaches this node, its own key must name it fully
        Node(package='nav2_map_server', executable='map_server', name='map_server',
             namespace='robot1', parameters=[robot]),
    ])
