"""A component's namespace when the launch gives none: rclcpp_components loads it with
use_global_arguments(false), so the container's namespace does not reach it unless
extra_arguments asks for forward_global_arguments."""
import json

from physai_lint import api
from physai_lint.engine import CheckOptions

PKG = """<package format="3"><name>demo</name><version>0.0.0</version><description>d</description>
<maintainer email="m@example.com">a</maintainer><license>MIT</license>
<export><build_type>ament_cmake</build_type></export></package>
"""

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


def test_component_namespaces(tmp_path):
    pkg = tmp_path / "src" / "demo"
    (pkg / "launch").mkdir(parents=True)
    (pkg / "package.xml").write_text(PKG)
    (pkg / "CMakeLists.txt").write_text("project(demo)\ninstall(DIRECTORY launch DESTINATION share/${PROJECT_NAME})\n")
    entry = pkg / "launch" / "a.launch.py"
    entry.write_text(LAUNCH)
    doc = json.loads(api.graph(CheckOptions(paths=[str(entry)], workspace=str(tmp_path)), str(entry), "json"))
    fqns = {n["name"]: n["fqn"] for n in doc["nodes"] if n["kind"] == "composable_node"}
    assert fqns == {"plain": "/plain", "forwarded": "/robot/forwarded", "own": "/arm/own", "pushed": "/fleet/pushed"}
