from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, IncludeLaunchDescription
from launch.conditions import IfCondition
from launch.launch_description_sources import AnyLaunchDescriptionSource
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution, PythonExpression
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    slam = LaunchConfiguration('slam')
    return LaunchDescription([
        DeclareLaunchArgument('slam', default_value='False'),
        Node(package='nav2_amcl', executable='amcl', name='amcl',
             condition=IfCondition(PythonExpression(['not ', slam]))),
        Node(package='nav2_amcl', executable='amcl', name='amcl_sqrt',
             condition=IfCondition(PythonExpression(['sqrt(4) == 2.0 and ', slam, ' in (True, False)']))),
        IncludeLaunchDescription(AnyLaunchDescriptionSource(
            PathJoinSubstitution([FindPackageShare('demo_nav'), 'launch', 'slam.launch.xml']))),
    ])
