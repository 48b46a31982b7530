"""Bring up one Atlas robot: description, sensors, perception, control, navigation, RViz."""
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, IncludeLaunchDescription
from launch.conditions import IfCondition
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare
from launch_xml.launch_description_sources import XMLLaunchDescriptionSource


def generate_launch_description():
    use_sim_time = LaunchConfiguration('use_sim_time')
    robot_name = LaunchConfiguration('robot_name')
    use_rviz = LaunchConfiguration('use_rviz')

    description = IncludeLaunchDescription(
        PythonLaunchDescriptionSource(PathJoinSubstitution(
            [FindPackageShare('atlas_description'), 'launch', 'description.launch.py'])),
        launch_arguments={'use_sim_time': use_sim_time, 'robot_name': robot_name}.items(),
    )
    sensors = IncludeLaunchDescription(
        XMLLaunchDescriptionSource(PathJoinSubstitution(
            [FindPackageShare('atlas_drivers'), 'launch', 'sensors.launch.xml'])),
        launch_arguments={'use_sim_time': use_sim_time}.items(),
    )
    perception = IncludeLaunchDescription(
        PythonLaunchDescriptionSource(PathJoinSubstitution(
            [FindPackageShare('atlas_perception'), 'launch', 'perception.launch.py'])),
        launch_arguments={'use_sim_time': use_sim_time, 'camera_ns': 'camera'}.items(),
    )
    control = IncludeLaunchDescription(
        PythonLaunchDescriptionSource(PathJoinSubstitution(
            [FindPackageShare('atlas_control'), 'launch', 'control.launch.py'])),
        launch_arguments={'use_sim_time': use_sim_time, 'robot_name': robot_name}.items(),
    )
    navigation = IncludeLaunchDescription(
        PythonLaunchDescriptionSource(PathJoinSubstitution(
            [FindPackageShare('atlas_navigation'), 'launch', 'navigation.launch.py'])),
        launch_arguments={'use_sim_time': use_sim_time}.items(),
    )
    rviz = Node(
        package='rviz2',
        executable='rviz2',
        name='rviz2',
        arguments=['-d', PathJoinSubstitution(
            [FindPackageShare('atlas_description'), 'rviz', 'atlas.rviz'])],
        parameters=[{'use_sim_time': use_sim_time}],
        condition=IfCondition(use_rviz),
    )

    return LaunchDescription([
        DeclareLaunchArgument('use_sim_time', default_value='false',
                              description='Use simulation (Gazebo) clock if true'),
        DeclareLaunchArgument('robot_name', default_value='atlas',
                              description='Robot name, used for the model'),
        DeclareLaunchArgument('use_rviz', default_value='true', choices=['true', 'false'],
                              description='Start RViz'),
        description,
        sensors,
        perception,
        control,
        navigation,
        rviz,
    ])
