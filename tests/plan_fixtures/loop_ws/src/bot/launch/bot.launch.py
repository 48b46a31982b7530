"""A small robot: a driver/controller topic loop, a camera pipeline in a container, a lifecycle
manager, a spawner chain and a delayed RViz. Used by tests/test_plan.py and tests/graph/."""
from launch import LaunchDescription
from launch.actions import RegisterEventHandler, TimerAction
from launch.event_handlers import OnProcessExit, OnProcessStart
from launch_ros.actions import ComposableNodeContainer, Node
from launch_ros.descriptions import ComposableNode


def generate_launch_description():
    base = Node(package='bot', executable='base_driver', name='base')
    follower = Node(package='bot', executable='follower', name='follower', namespace='nav')
    planner = Node(package='bot', executable='planner', name='planner', namespace='nav')
    manager = Node(package='nav2_lifecycle_manager', executable='lifecycle_manager',
                   name='lifecycle_manager', namespace='nav',
                   parameters=[{'node_names': ['planner', 'follower'], 'autostart': True}])
    camera = ComposableNodeContainer(
        name='camera_container', namespace='sensors', package='rclcpp_components',
        executable='component_container',
        composable_node_descriptions=[
            ComposableNode(package='bot', plugin='bot::Camera', name='camera', namespace='sensors'),
            ComposableNode(package='bot', plugin='bot::Detector', name='detector', namespace='sensors'),
        ])
    jsb = Node(package='controller_manager', executable='spawner', arguments=['joint_state_broadcaster'])
    base_ctrl = Node(package='controller_manager', executable='spawner', arguments=['base_controller'])
    rviz = Node(package='rviz2', executable='rviz2', name='rviz')
    return LaunchDescription([
        base, follower, planner, manager, camera, jsb,
        RegisterEventHandler(OnProcessExit(target_action=jsb, on_exit=[base_ctrl])),
        RegisterEventHandler(OnProcessStart(
            target_action=base_ctrl, on_start=[TimerAction(period=2.5, actions=[rviz])])),
    ])
