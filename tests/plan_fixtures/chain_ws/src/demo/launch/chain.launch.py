from launch import LaunchDescription
from launch.actions import RegisterEventHandler, TimerAction
from launch.event_handlers import OnProcessExit, OnProcessStart
from launch_ros.actions import ComposableNodeContainer, Node
from launch_ros.descriptions import ComposableNode


def generate_launch_description():
    control = Node(package='controller_manager', executable='ros2_control_node')
    jsb = Node(package='controller_manager', executable='spawner',
               arguments=['joint_state_broadcaster'])
    arm = Node(package='controller_manager', executable='spawner', arguments=['arm_controller'])
    rviz = Node(package='rviz2', executable='rviz2')
    container = ComposableNodeContainer(
        name='container', namespace='', package='rclcpp_components',
        executable='component_container',
        composable_node_descriptions=[
            ComposableNode(package='demo_nodes_cpp', plugin='demo_nodes_cpp::Talker', name='talker'),
        ])
    planner = Node(package='nav2_planner', executable='planner_server', name='planner_server')
    controller = Node(package='nav2_controller', executable='controller_server',
                      name='controller_server')
    manager = Node(package='nav2_lifecycle_manager', executable='lifecycle_manager',
                   name='lifecycle_manager',
                   parameters=[{'node_names': ['controller_server', 'planner_server']}])
    return LaunchDescription([
        control, jsb, container, planner, controller, manager,
        RegisterEventHandler(OnProcessExit(target_action=jsb, on_exit=[arm])),
        RegisterEventHandler(OnProcessStart(
            target_action=control, on_start=[TimerAction(period=3.0, actions=[rviz])])),
    ])
