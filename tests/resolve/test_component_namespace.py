"""A component's namespace when the launch gives none: rclcpp_components loads it with
use_global_arguments(false), so the container's namespace does not reach it unless
extra_arguments asks for forward_global_arguments."""

LAUNCH = """
from launch import LaunchDescription
from launch.actions import GroupAction
from launch_ros.actions import ComposableNodeContainer, LoadComposableNodes, PushRosNamespace
from launch_ros.descriptions import ComposableNode

def generate_launch_description():
    container = ComposableNodeContainer(
        name="box", namespace="robot", package="rclcpp_components", executable="component_container",
        composable_node_descriptions=[
            ComposableNode(package="demo", plugin="demo::A", name="plain"),
            ComposableNode(package="demo", plugin="demo::A", name="forwarded",
                           extra_arguments=[{"forward_global_arguments": True}]),
            ComposableNode(package="demo", plugin="demo::A", name="own", namespace="arm"),
        ])
    pushed = GroupAction([
        PushRosNamespace("fleet"),
        LoadComposableNodes(target_container="/robot/box", composable_node_descriptions=[
            ComposableNode(package="demo", plugin="demo::A", name="pushed")]),
    ])
    return LaunchDescription([container, pushed])
"""


def test_component_namespaces(demo_graph):
    nodes = demo_graph({"launch/a.launch.py": LAUNCH}, "launch/a.launch.py").values()
    fqns = {n["name"]: n["fqn"] for n in nodes if n["kind"] == "composable_node"}
    assert fqns == {"plain": "/plain", "forwarded": "/robot/forwarded", "own": "/arm/own", "pushed": "/fleet/pushed"}
