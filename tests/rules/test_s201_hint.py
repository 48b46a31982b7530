"""S201's did-you-mean offers only nodes no manager lists yet: map_server, already in node_names,
is no misspelling of the missing map_saver."""
from __future__ import annotations

from typing import Any

LAUNCH = """from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='nav2_map_server', executable='map_server', name='map_server'),
        Node(package='nav2_amcl', executable='amcl', name='amcl'),
        Node(package='nav2_map_server', executable='map_saver_server', name='map_savr'),
        Node(package='nav2_lifecycle_manager', executable='lifecycle_manager', name='lifecycle_manager',
             parameters=[{'autostart': True, 'node_names': [{names}]}]),
    ])
"""


def test_the_hint_skips_nodes_the_manager_lists_already(demo_findings: Any) -> None:
    text = LAUNCH.replace("{names}", "'map_server', 'amcl', 'map_saver'")
    (found,) = demo_findings({"launch/loc.launch.py": text}, "launch/loc.launch.py", "S201")
    assert 'manages "map_saver" (/map_saver) but no such node is launched; did you mean "/map_savr"?' \
        in found[1]


COMPOSED = """from launch import LaunchDescription
from launch_ros.actions import ComposableNodeContainer, PushRosNamespace
from launch.actions import GroupAction
from launch_ros.descriptions import ComposableNode


def generate_launch_description():
    return LaunchDescription([GroupAction([
        PushRosNamespace('rover'),
        ComposableNodeContainer(
            name='nav2_container', namespace='', package='rclcpp_components',
            executable='component_container_isolated',
            composable_node_descriptions=[
                ComposableNode(package='nav2_planner', plugin='nav2_planner::PlannerServer', name='planner'),
                ComposableNode(package='nav2_lifecycle_manager', plugin='nav2_lifecycle_manager::LifecycleManager',
                               name='lifecycle_manager_navigation',
                               parameters=[{'autostart': True, 'node_names': ['planner_server']}]),
            ]),
    ])])
"""


def test_a_composed_manager_is_checked_too(demo_findings: Any) -> None:
    # nav2_bringup's use_composition branch loads the manager as a component
    ((line, message),) = demo_findings({"launch/c.launch.py": COMPOSED}, "launch/c.launch.py", "S201")
    assert line == 17 and 'manages "planner_server" (/rover/planner_server) but no such node is launched' in message


AUTOSTART = """from launch import LaunchDescription
from launch_ros.actions import LifecycleNode, Node


def generate_launch_description():
    return LaunchDescription([
        LifecycleNode(package='demo', executable='sim', name='sim', namespace='', autostart=True),
        LifecycleNode(package='demo', executable='sim', name='sim2', namespace=''),
        LifecycleNode(package='demo', executable='sim', name='sim3', namespace='', autostart=False),
        Node(package='nav2_lifecycle_manager', executable='lifecycle_manager', name='lifecycle_manager',
             parameters=[{'autostart': True, 'node_names': ['other']}]),
    ])
"""


def test_an_autostarted_lifecycle_node_needs_no_manager(demo_findings: Any) -> None:
    found = demo_findings({"launch/a.launch.py": AUTOSTART}, "launch/a.launch.py", "S202", distro="jazzy")
    assert [line for line, _ in found] == [8, 9]  # autostart=False: launch_ros tests its truth
