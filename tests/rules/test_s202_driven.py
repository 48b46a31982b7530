"""S202: a lifecycle node the launch drives through its states itself (EmitEvent(ChangeState(
lifecycle_node_matcher=matches_action(node)))) needs no manager."""
from __future__ import annotations

from typing import Any

DRIVEN = """from launch import LaunchDescription
from launch.actions import EmitEvent, RegisterEventHandler
from launch.event_handlers import OnProcessStart
from launch.events import matches_action
from launch_ros.actions import LifecycleNode, Node
from launch_ros.event_handlers import OnStateTransition
from launch_ros.events.lifecycle import ChangeState
from lifecycle_msgs.msg import Transition


def generate_launch_description():
    # The launch drives map_server through its states itself; the manager brings up amcl only.
    maps = LifecycleNode(package='nav2_map_server', executable='map_server', name='map_server',
                         namespace='', parameters=[{'yaml_filename': '/srv/maps/floor1.yaml'}])
    return LaunchDescription([
        maps,
        RegisterEventHandler(OnProcessStart(target_action=maps, on_start=[
            EmitEvent(event=ChangeState(lifecycle_node_matcher=matches_action(maps),
                                        transition_id=Transition.TRANSITION_CONFIGURE))])),
        RegisterEventHandler(OnStateTransition(target_lifecycle_node=maps, goal_state='inactive', entities=[
            EmitEvent(event=ChangeState(lifecycle_node_matcher=matches_action(maps),
                                        transition_id=Transition.TRANSITION_ACTIVATE))])),
        LifecycleNode(package='nav2_amcl', executable='amcl', name='amcl', namespace=''),
        Node(package='nav2_lifecycle_manager', executable='lifecycle_manager', name='lifecycle_manager',
             parameters=[{'autostart': True, 'node_names': ['amcl']}]),
    ])
"""

UNDRIVEN = DRIVEN.replace("lifecycle_node_matcher=matches_action(maps)", "lifecycle_node_matcher=matches_action(other)")\
    .replace("    return LaunchDescription([", "    other = LifecycleNode(package='nav2_amcl', executable='amcl', name='amcl2', namespace='')\n"
             "    return LaunchDescription([\n        other,")

ANY_NODE = DRIVEN.replace("matches_action(maps)", "matches_node_name(node_name=node_name)")\
    .replace("def generate_launch_description():", "node_name = '/map_server'\n\n\ndef generate_launch_description():")\
    .replace("from launch.events import matches_action", "from launch_ros.events.lifecycle import matches_node_name")


def test_a_node_the_launch_configures_itself_is_not_unmanaged(demo_findings: Any) -> None:
    assert demo_findings({"launch/a.launch.py": DRIVEN}, "launch/a.launch.py", "S202") == []


def test_events_for_another_node_leave_it_unmanaged(demo_findings: Any) -> None:
    found = demo_findings({"launch/a.launch.py": UNDRIVEN}, "launch/a.launch.py", "S202")
    assert [m.split(" is launched")[0] for _, m in found] == ["lifecycle node /map_server"]


def test_a_transition_of_a_node_not_known_statically_may_be_any(demo_findings: Any) -> None:
    assert demo_findings({"launch/a.launch.py": ANY_NODE}, "launch/a.launch.py", "S202") == []


NAV = """from launch import LaunchDescription
from launch.actions import ExecuteProcess
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='nav2_map_server', executable='map_server', name='map_server', EXTRA),
        Node(package='nav2_amcl', executable='amcl', name='amcl'),
        Node(package='nav2_lifecycle_manager', executable='lifecycle_manager', name='lifecycle_manager',
             parameters=[{'autostart': True, 'node_names': NAMES}]),
        PROCESS
    ])
"""


def _nav(demo_findings: Any, extra: str = "", names: str = "['amcl']", process: str = "") -> list[str]:
    text = NAV.replace("EXTRA", extra or "output='screen'").replace("NAMES", names).replace("PROCESS", process)
    return [m.split(" is launched")[0] for _, m in demo_findings({"launch/a.launch.py": text}, "launch/a.launch.py",
                                                                  "S202")]


def test_a_known_lifecycle_executable_started_with_node(demo_findings: Any) -> None:
    # nav2 starts its servers with Node: map_server makes a lifecycle node nobody brings up
    assert _nav(demo_findings) == ["lifecycle node /map_server"]
    assert _nav(demo_findings, names="['map_server', 'amcl']") == []


def test_other_ways_a_node_is_brought_up(demo_findings: Any) -> None:
    assert _nav(demo_findings, process="ExecuteProcess(cmd=['ros2', 'lifecycle', 'set', '/map_server', 'configure']),") == []
    assert _nav(demo_findings, extra="parameters=[{'autostart': True}]") == []
    # a manager whose node_names are not known may name it
    assert _nav(demo_findings, names="NAMES_FROM_ELSEWHERE") == []


PLAIN_CPP = """#include <rclcpp/rclcpp.hpp>
#include <sensor_msgs/msg/laser_scan.hpp>

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  auto node = rclcpp::Node::make_shared("driver_node");
  auto pub = node->create_publisher<sensor_msgs::msg::LaserScan>("scan", 10);
  rclcpp::spin(node);
  return 0;
}
"""
LIFECYCLE_CPP = PLAIN_CPP.replace("rclcpp::Node::make_shared", "rclcpp_lifecycle::LifecycleNode::make_shared")
DRIVER_CMAKE = """cmake_minimum_required(VERSION 3.8)
project(demo)
find_package(ament_cmake REQUIRED)
add_executable(driver_node src/driver_node.cpp)
install(TARGETS driver_node DESTINATION lib/${PROJECT_NAME})
install(DIRECTORY launch DESTINATION share/${PROJECT_NAME})
ament_package()
"""
DRIVER_LAUNCH = """from launch import LaunchDescription
from launch_ros.actions import LifecycleNode, Node


def generate_launch_description():
    return LaunchDescription([
        LifecycleNode(package='demo', executable='driver_node', name='driver_node', namespace=''),
        Node(package='nav2_map_server', executable='map_server', name='map_server'),
        Node(package='nav2_lifecycle_manager', executable='lifecycle_manager', name='lifecycle_manager',
             parameters=[{'autostart': True, 'node_names': ['map_server']}]),
    ])
"""


def test_a_plain_node_started_with_the_lifecycle_action_needs_no_manager(demo_findings: Any) -> None:
    # ydlidar_ros2_driver: LifecycleNode(...) on an rclcpp::Node; launch_ros only watches its events
    def s202(cpp: str) -> list[str]:
        files = {"CMakeLists.txt": DRIVER_CMAKE, "src/driver_node.cpp": cpp, "launch/a.launch.py": DRIVER_LAUNCH}
        return [m.split(" is launched")[0] for _, m in demo_findings(files, "launch/a.launch.py", "S202")]

    assert s202(PLAIN_CPP) == []
    assert s202(LIFECYCLE_CPP) == ["lifecycle node /driver_node"]
