"""P111: nodes whose output does not depend on their clock are not reported when unset."""
from __future__ import annotations

LAUNCH = """<launch>
  <node pkg="demo_nodes_cpp" exec="talker" name="talker">
    <param name="use_sim_time" value="true"/>
  </node>
  <node pkg="PKG" exec="EXE" name="other" args="/clock@rosgraph_msgs/msg/Clock[gz.msgs.Clock"/>
</launch>
"""


def _p111(demo_findings, pkg: str, exe: str) -> list[str]:
    text = LAUNCH.replace("PKG", pkg).replace("EXE", exe)
    return [msg for _, msg in demo_findings({"launch/a.launch.xml": text}, "launch/a.launch.xml", "P111")]


def test_an_unset_node_on_wall_clock_time_is_reported(demo_findings):
    (msg,) = _p111(demo_findings, "demo_nodes_cpp", "listener")
    assert "never gets use_sim_time" in msg


def test_the_gazebo_bridges_copy_their_stamps(demo_findings):
    assert _p111(demo_findings, "ros_gz_bridge", "parameter_bridge") == []
    assert _p111(demo_findings, "ros_gz_image", "image_bridge") == []


def test_teleop_nodes_publish_unstamped_twists_unless_told_to_stamp(demo_findings):
    assert _p111(demo_findings, "teleop_twist_keyboard", "teleop_twist_keyboard") == []
    assert _p111(demo_findings, "teleop_twist_joy", "teleop_node") == []
    stamped = LAUNCH.replace("PKG", "teleop_twist_keyboard").replace("EXE", "teleop_twist_keyboard") \
        .replace('args="/clock@rosgraph_msgs/msg/Clock[gz.msgs.Clock"/>',
                 '><param name="stamped" value="true"/></node>')
    (msg,) = [m for _, m in demo_findings({"launch/a.launch.xml": stamped}, "launch/a.launch.xml", "P111")]
    assert "never gets use_sim_time" in msg


NAV = """import os

from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch_ros.actions import Node
from nav2_common.launch import RewrittenYaml


def generate_launch_description():
    params = os.path.join(get_package_share_directory('demo'), 'config', 'nav2.yaml')
    configured = RewrittenYaml(source_file=params, root_key='', param_rewrites={}, convert_types=True)
    return LaunchDescription([
        Node(package='nav2_controller', executable='controller_server', name='controller_server',
             parameters=[configured]),
        Node(package='nav2_behaviors', executable='behavior_server', name='behavior_server',
             parameters=[configured]),
    ])
"""
NAV_YAML = """controller_server:
  ros__parameters:
    use_sim_time: true
recoveries_server:
  ros__parameters:
    use_sim_time: true
"""


def test_a_node_a_rewritten_file_has_no_key_for_is_unset(demo_findings):
    # RewrittenYaml writes a temporary file: its model is the node's source, and behavior_server
    # (the file still says recoveries_server, its pre-humble name) gets no use_sim_time from it
    (msg,) = [m for _, m in demo_findings({"launch/nav.launch.py": NAV, "config/nav2.yaml": NAV_YAML},
                                          "launch/nav.launch.py", "P111")]
    assert msg.startswith("/behavior_server never gets use_sim_time")


def test_a_component_container_on_wall_time_is_harmless(demo_findings):
    # its own node only loads components; each component gets its own use_sim_time
    assert _p111(demo_findings, "rclcpp_components", "component_container_isolated") == []
