from launch import LaunchDescription
from launch.actions import RegisterEventHandler
from launch.event_handlers import OnProcessExit
from launch_ros.actions import ComposableNodeContainer, Node


def generate_launch_description():
    rsp = Node(package='robot_state_publisher', executable='robot_state_publisher',
               parameters=[{'robot_description': '<robot name="r"><link name="base"/></robot>'}])
    control = Node(package='controller_manager', executable='ros2_control_node')
    container = ComposableNodeContainer(name='perception', namespace='', package='rclcpp_components',
                                        executable='component_container', composable_node_descriptions=[])
    broadcaster = Node(package='controller_manager', executable='spawner', arguments=['joint_state_broadcaster'])
    drive = Node(package='controller_manager', executable='spawner', arguments=['diff_drive_controller'])
    viewer = Node(package='rviz2', executable='rviz2')
    return LaunchDescription([
        rsp, control, container,
        # meant: once robot_state_publisher has started
        RegisterEventHandler(OnProcessExit(target_action=rsp, on_exit=[broadcaster])),
        RegisterEventHandler(OnProcessExit(target_action=control, on_exit=[drive])),
        RegisterEventHandler(OnProcessExit(target_action=container, on_exit=[viewer])),
    ])
