"""A parameter file with no ros__parameters key, loaded by a composable node: launch_ros reads it
with PyYAML and, with nothing to normalise, gives the node every key (to_parameters_list)."""
from __future__ import annotations

FLAT = "# read by launch_ros, not rcl\nrate: 10.0\ncamera:\n  frame_id: base_link\n  size: [640, 480]\n"
LAUNCH = """
from launch import LaunchDescription
from launch.substitutions import PathJoinSubstitution
from launch_ros.actions import ComposableNodeContainer, Node
from launch_ros.descriptions import ComposableNode
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    params = PathJoinSubstitution([FindPackageShare('demo'), 'config', 'flat.yaml'])
    return LaunchDescription([
        ComposableNodeContainer(
            name='container', namespace='', package='rclcpp_components', executable='component_container',
            composable_node_descriptions=[
                ComposableNode(package='composition', plugin='composition::Talker', name='talker',
                               parameters=[params])]),
        PLAIN
    ])
"""
PLAIN_NODE = "Node(package='demo_nodes_cpp', executable='listener', name='listener', parameters=[params]),"


def _files(plain: bool) -> dict[str, str]:
    return {"config/flat.yaml": FLAT,
            "launch/a.launch.py": LAUNCH.replace("PLAIN", PLAIN_NODE if plain else "")}


def test_a_component_gets_every_key_of_a_flat_file(demo_graph) -> None:
    nodes = demo_graph(_files(plain=False), "launch/a.launch.py")
    assert nodes["talker"]["parameters"] == {"rate": 10.0, "camera.frame_id": "base_link",
                                             "camera.size": [640, 480]}


def test_rcl_structure_errors_are_reported_only_when_rcl_reads_the_file(demo_findings) -> None:
    assert demo_findings(_files(plain=False), "launch/a.launch.py", "P104") == []
    (line, message) = demo_findings(_files(plain=True), "launch/a.launch.py", "P104")[0]
    assert line == 2 and "comes before any 'ros__parameters' key" in message
