"""ros2_control for the base and the arm, the controller spawners in order, the safety stage."""
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import (Command, FindExecutable, LaunchConfiguration,
                                  PathJoinSubstitution)
from launch_ros.actions import Node
from launch_ros.parameter_descriptions import ParameterValue
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    use_sim_time = LaunchConfiguration('use_sim_time')
    robot_name = LaunchConfiguration('robot_name')

    xacro_file = PathJoinSubstitution(
        [FindPackageShare('atlas_description'), 'urdf', 'atlas.urdf.xacro'])
    robot_description = ParameterValue(
        Command([FindExecutable(name='xacro'), ' ', xacro_file, ' robot_name:=', robot_name]),
        value_type=str)
    controllers = PathJoinSubstitution(
        [FindPackageShare('atlas_control'), 'config', 'controllers.yaml'])
    safety_params = PathJoinSubstitution(
        [FindPackageShare('atlas_control'), 'config', 'safety_controller.yaml'])

    control_node = Node(
        package='controller_manager',
        executable='ros2_control_node',
        name='controller_manager',
        output='screen',
        parameters=[{'robot_description': robot_description}, controllers,
                    {'use_sim_time': use_sim_time}],
    )
    joint_state_broadcaster_spawner = Node(
        package='controller_manager',
        executable='spawner',
        arguments=['joint_state_broadcaster', '--controller-manager', 'controller_manager'],
    )
    diff_drive_spawner = Node(
        package='controller_manager',
        executable='spawner',
        arguments=['diff_drive_controller', '--controller-manager', 'controller_manager'],
    )
    arm_controller_spawner = Node(
        package='controller_manager',
        executable='spawner',
        arguments=['arm_controller', '--controller-manager', 'controller_manager'],
    )
    safety_controller = Node(
        package='atlas_control',
        executable='safety_controller',
        name='safety_controller',
        output='screen',
        parameters=[safety_params, {'use_sim_time': use_sim_time}],
        remappings=[
            ('cmd_vel_in', 'cmd_vel'),
            ('cmd_vel_out', 'diff_drive_controller/cmd_vel_unstamped'),
            ('imu', 'imu/data'),
        ],
    )

    return LaunchDescription([
        DeclareLaunchArgument('use_sim_time', default_value='false'),
        DeclareLaunchArgument('robot_name', default_value='atlas'),
        control_node,
        # Every spawner and the safety controller start directly: event handlers and timers run
        # after the fleet's PushRosNamespace group has been popped, so anything they start would
        # lose the robot's namespace (and talk to /controller_manager). A spawner waits for its
        # controller manager by itself.
        joint_state_broadcaster_spawner,
        diff_drive_spawner,
        arm_controller_spawner,
        safety_controller,
    ])
