"""P103 for a component loaded with no name: launch_ros sends no node name, and
``to_parameters_list`` applies only the "/**" entries of the component's parameter files (warning
"node name not provided to launch; parameter files will not apply")."""
from __future__ import annotations

from typing import Any

LAUNCH = """from launch import LaunchDescription
from launch.substitutions import PathJoinSubstitution
from launch_ros.actions import ComposableNodeContainer
from launch_ros.descriptions import ComposableNode
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    params = PathJoinSubstitution([FindPackageShare('demo'), 'config', 'nav.yaml'])
    return LaunchDescription([
        ComposableNodeContainer(
            name='container', namespace='', package='rclcpp_components',
            executable='component_container',
            composable_node_descriptions=[
                ComposableNode(package='nav2_map_server', plugin='nav2_map_server::MapServer',
                               name='map_server', parameters=[params]),
                ComposableNode(package='nav2_amcl', plugin='nav2_amcl::AmclNode'NAME,
                               parameters=[params]),
            ]),
    ])
"""

NODE_KEYED = """amcl:
  ros__parameters:
    base_frame_id: base_link
map_server:
  ros__parameters:
    yaml_filename: map.yaml
"""


def _found(demo_findings: Any, name: str, params: str) -> list[tuple[int, str]]:
    files = {"launch/a.launch.py": LAUNCH.replace("NAME", name), "config/nav.yaml": params}
    return demo_findings(files, "launch/a.launch.py", "P103")


def test_an_unnamed_component_gets_nothing_from_a_node_keyed_file(demo_findings: Any) -> None:
    (line, message), = _found(demo_findings, "", NODE_KEYED)
    assert line == 18
    assert message.startswith('component "nav2_amcl::AmclNode" is loaded without a name, so launch_ros applies '
                              'only the "/**" entries of its parameter files, and "')
    assert message.endswith('src/demo/config/nav.yaml" has none (its keys: "amcl", "map_server"): the component gets '
                            'none of its parameters from it and runs on its defaults')


def test_a_named_component_or_a_file_with_a_wildcard_entry_is_quiet(demo_findings: Any) -> None:
    assert _found(demo_findings, ", name='amcl'", NODE_KEYED) == []
    assert _found(demo_findings, "", "/**:\n  ros__parameters:\n    use_sim_time: false\n" + NODE_KEYED) == []


CMAKE = """project(demo)
add_library(amcl_component SHARED src/amcl.cpp)
rclcpp_components_register_node(amcl_component PLUGIN "demo::Amcl" EXECUTABLE amcl)
install(TARGETS amcl_component LIBRARY DESTINATION lib RUNTIME DESTINATION bin)
install(DIRECTORY launch config DESTINATION share/${PROJECT_NAME})
"""
AMCL = """namespace demo {
class Amcl : public rclcpp::Node {
 public:
  explicit Amcl(const rclcpp::NodeOptions & o) : Node("amcl", o) {
    declare_parameter("base_frame_id", "base_footprint");
    declare_parameter("use_sim_time", false);
  }
};
}
RCLCPP_COMPONENTS_REGISTER_NODE(demo::Amcl)
"""


def test_an_unnamed_components_parameters_are_the_wildcard_entries(demo_package: Any, tmp_path: Any) -> None:
    # the component's constructor names it "amcl", but launch_ros matches the file before it runs
    import json

    from physai_lint.api import params
    from physai_lint.engine import CheckOptions

    text = "/**:\n  ros__parameters:\n    use_sim_time: true\n" + NODE_KEYED
    launch = LAUNCH.replace("NAME", "").replace("package='nav2_amcl', plugin='nav2_amcl::AmclNode'",
                                                "package='demo', plugin='demo::Amcl'")
    entry = str(demo_package({"launch/a.launch.py": launch, "config/nav.yaml": text, "CMakeLists.txt": CMAKE,
                              "src/amcl.cpp": AMCL}) / "launch/a.launch.py")
    nodes = json.loads(params(CheckOptions(paths=[entry], workspace=str(tmp_path), cache=False), entry, None,
                              "json"))["nodes"]
    got = {n["executable"]: sorted(p["name"] for p in n["parameters"]) for n in nodes}
    assert got["demo::Amcl"] == ["use_sim_time"]
    assert got["nav2_map_server::MapServer"] == ["use_sim_time", "yaml_filename"]
