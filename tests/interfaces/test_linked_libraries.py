"""An executable that links a library of several node classes has the endpoints and parameters of
the classes its own code runs (names, directly, through an alias or through a class that runs),
not of every class in the library; a component has its plugin class's."""
from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest

from physai_lint.interfaces import build_interface_store
from physai_lint.interfaces.model import NodeInterface
from physai_lint.workspace.index import build_package_index

CMAKE = """project(demo)
add_library(demo_lib src/filter.cpp src/gps.cpp src/helpers.cpp)
add_executable(filter_node src/filter_node.cpp)
target_link_libraries(filter_node demo_lib)
add_executable(gps_node src/gps_node.cpp)
target_link_libraries(gps_node demo_lib)
add_executable(tool src/tool.cpp)
target_link_libraries(tool demo_lib)
install(TARGETS filter_node gps_node tool DESTINATION lib/${PROJECT_NAME})
install(DIRECTORY launch DESTINATION share/${PROJECT_NAME})
"""
FILTER = """#include "demo/nodes.hpp"
namespace demo {
Filter::Filter(const rclcpp::NodeOptions & options) : rclcpp::Node("filter", options) {
  declare_parameter("gain", 1.0);
  pub_ = create_publisher<std_msgs::msg::String>("filtered", 10);
  sub_ = create_subscription<std_msgs::msg::String>("fix", 10, [this](Msg m) { on_fix(m); });
  srv_ = create_service<std_srvs::srv::Empty>("reset", [](auto, auto) {});
}
}  // namespace demo
"""
GPS = """#include "demo/nodes.hpp"
namespace demo {
template<typename T>
Gps<T>::Gps() : rclcpp::Node("gps") {
  declare_parameter("gain", std::string("high"));  // another class's parameter of the same name
  pub_ = create_publisher<std_msgs::msg::String>("fix", 10);
  srv_ = create_service<std_srvs::srv::Empty>("datum", [](auto, auto) {});
}
template class Gps<Serial>;
}  // namespace demo
"""
HELPERS = """#include "demo/nodes.hpp"
// code outside any class: it may or may not run in an executable linking the library
void advertise_status(rclcpp::Node & node) {
  static auto pub = node.create_publisher<diagnostic_msgs::msg::DiagnosticArray>("status", 1);
}
"""
FILTER_MAIN = """#include "demo/nodes.hpp"
int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<demo::Filter>(rclcpp::NodeOptions()));  // not Gps
}
"""
# the Gps class only through an alias in a header the main includes
GPS_MAIN = """#include "demo/types.hpp"
int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<demo::SerialGps>());
}
"""
TYPES = """#include "demo/nodes.hpp"
namespace demo { using SerialGps = Gps<Serial>; }
"""
TOOL_MAIN = """int main() { return run_tool(); }  // names no class of the library
"""
LAUNCH = """from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='demo', executable='filter_node', name='filter'),
        Node(package='demo', executable='gps_node', name='gps'),
    ])
"""
FILES = {"CMakeLists.txt": CMAKE, "src/filter.cpp": FILTER, "src/gps.cpp": GPS,
         "src/helpers.cpp": HELPERS, "src/filter_node.cpp": FILTER_MAIN, "src/gps_node.cpp": GPS_MAIN,
         "src/tool.cpp": TOOL_MAIN, "include/demo/types.hpp": TYPES, "launch/two.launch.py": LAUNCH}


def _interfaces(tmp_path: Path, demo_package: Callable[[dict[str, str]], Path],
                files: dict[str, str], *executables: str) -> list[NodeInterface]:
    demo_package(files)
    store, _ = build_interface_store([], build_package_index(str(tmp_path)), "humble")
    found = [store.get("demo", exe) for exe in executables]
    assert all(i is not None for i in found)
    return found  # type: ignore[return-value]


def _names(iface: NodeInterface) -> dict[str, list[str]]:
    kinds = ("publishers", "subscribers", "services")
    return {k: sorted(e.name for e in iface.endpoints(k)) for k in kinds if iface.endpoints(k)}


def test_each_executable_has_the_classes_its_main_names(tmp_path: Path, demo_package: Any) -> None:
    filter_node, gps_node = _interfaces(tmp_path, demo_package, FILES, "filter_node", "gps_node")
    assert _names(filter_node) == {"publishers": ["filtered"], "subscribers": ["fix"], "services": ["reset"]}
    assert _names(gps_node) == {"publishers": ["fix"], "services": ["datum"]}  # (through the alias)
    # the free function's publisher may run in either: its kind and type, not its name
    assert filter_node.unnamed == gps_node.unnamed == [
        ("publishers", "diagnostic_msgs/msg/DiagnosticArray")]


def test_parameters_follow_the_classes(tmp_path: Path, demo_package: Any) -> None:
    filter_node, gps_node = _interfaces(tmp_path, demo_package, FILES, "filter_node", "gps_node")
    assert filter_node.parameters is not None and gps_node.parameters is not None
    assert filter_node.parameters["gain"].type == "double"
    assert gps_node.parameters["gain"].type == "string"
    assert not filter_node.parameters_complete and not gps_node.parameters_complete


def test_an_executable_naming_no_library_class_keeps_its_endpoints_unnamed(
        tmp_path: Path, demo_package: Any) -> None:
    (tool,) = _interfaces(tmp_path, demo_package, FILES, "tool")
    assert _names(tool) == {}
    assert sorted(tool.unnamed) == [
        ("publishers", "diagnostic_msgs/msg/DiagnosticArray"), ("publishers", "std_msgs/msg/String"),
        ("publishers", "std_msgs/msg/String"), ("services", "std_srvs/srv/Empty"),
        ("services", "std_srvs/srv/Empty"), ("subscribers", "std_msgs/msg/String")]
    assert tool.parameters is not None and "gain" in tool.parameters  # (may be declared)


def test_no_duplicate_server_between_classes_of_one_library(demo_findings: Any) -> None:
    assert demo_findings(FILES, "launch/two.launch.py", "T204") == []


# The running class builds another class of the library, in a file without any call word.
DRIVE_CMAKE = """project(demo)
add_library(robot src/robot.cpp src/controller.cpp src/odometry.cpp src/teleop.cpp)
add_executable(robot_node src/main.cpp)
target_link_libraries(robot_node robot)
install(TARGETS robot_node DESTINATION lib/${PROJECT_NAME})
"""
ROBOT = """Robot::Robot() : Node("robot") {
  declare_parameter("port", std::string("/dev/ttyACM0"));
}
"""
CONTROLLER = """Controller::Controller(double separation) : Node("controller") {
  odometry_ = std::make_unique<Odometry>(this, separation);  // no call word in this file
}
"""
ODOMETRY = """Odometry::Odometry(rclcpp::Node * node, double separation) {
  pub_ = node->create_publisher<nav_msgs::msg::Odometry>("odom", 10);
}
"""
TELEOP = """Teleop::Teleop() : Node("teleop") {
  pub_ = create_publisher<geometry_msgs::msg::Twist>("cmd_vel", 10);
}
"""
DRIVE_MAIN = """int main() {
  auto robot = std::make_shared<Robot>();
  auto controller = std::make_shared<Controller>(0.16);
}
"""


def test_a_class_the_running_code_builds_runs_too(tmp_path: Path, demo_package: Any) -> None:
    files = {"CMakeLists.txt": DRIVE_CMAKE, "src/robot.cpp": ROBOT, "src/controller.cpp": CONTROLLER,
             "src/odometry.cpp": ODOMETRY, "src/teleop.cpp": TELEOP, "src/main.cpp": DRIVE_MAIN}
    (robot,) = _interfaces(tmp_path, demo_package, files, "robot_node")
    assert _names(robot) == {"publishers": ["odom"]}  # not Teleop's cmd_vel
    assert robot.parameters is not None and list(robot.parameters) == ["port"]


# One library of components: each plugin (and the executable made for it) runs its own class.
COMPONENTS_CMAKE = """project(demo)
add_library(procs SHARED src/rectify.cpp src/resize.cpp)
rclcpp_components_register_node(procs PLUGIN "demo::RectifyNode" EXECUTABLE rectify_node)
rclcpp_components_register_nodes(procs "demo::ResizeNode")
"""
RECTIFY = """namespace demo {
RectifyNode::RectifyNode(const rclcpp::NodeOptions & options) : Node("rectify", options) {
  pub_ = image_transport::create_publisher(this, "image_rect");
}
}  // namespace demo
RCLCPP_COMPONENTS_REGISTER_NODE(demo::RectifyNode)
"""
RESIZE = """namespace demo {
class ResizeNode : public rclcpp::Node {
 public:
  explicit ResizeNode(const rclcpp::NodeOptions & options) : Node("resize", options) {
    pub_ = image_transport::create_publisher(this, "resize");
  }
};
}  // namespace demo
RCLCPP_COMPONENTS_REGISTER_NODE(demo::ResizeNode)
"""


def test_a_component_runs_its_plugin_class(tmp_path: Path, demo_package: Any) -> None:
    files = {"CMakeLists.txt": COMPONENTS_CMAKE, "src/rectify.cpp": RECTIFY, "src/resize.cpp": RESIZE}
    rectify_node, rectify, resize = _interfaces(tmp_path, demo_package, files, "rectify_node",
                                                "demo::RectifyNode", "demo::ResizeNode")
    assert _names(rectify_node) == _names(rectify) == {"publishers": ["image_rect"]}
    assert _names(resize) == {"publishers": ["resize"]}


@pytest.mark.parametrize("main", [
    "int main() { auto n = std::make_shared<demo::Filter>(rclcpp::NodeOptions()); }",
    "// demo::Gps is not used here\nint main() { auto n = std::make_shared<demo::Filter>(rclcpp::NodeOptions()); }",
    'int main() { auto n = std::make_shared<demo::Filter>(rclcpp::NodeOptions()); puts("Gps"); }',
], ids=["code", "comment", "string"])
def test_a_class_named_in_a_comment_or_string_does_not_run(tmp_path: Path, demo_package: Any,
                                                           main: str) -> None:
    (filter_node,) = _interfaces(tmp_path, demo_package, {**FILES, "src/filter_node.cpp": main},
                                 "filter_node")
    assert _names(filter_node)["publishers"] == ["filtered"]


def test_a_component_declaring_nothing_seen_runs_no_other_class(tmp_path: Path,
                                                                demo_package: Any) -> None:
    # its endpoints come through a helper extraction does not read (Autoware's API adaptors)
    fail_safe = """namespace demo {
FailSafeNode::FailSafeNode(const rclcpp::NodeOptions & options) : Node("fail_safe", options) {
  adaptor.init_pub(pub_mrm_state_);
}
}  // namespace demo
"""
    cmake = COMPONENTS_CMAKE.replace("src/resize.cpp", "src/resize.cpp src/fail_safe.cpp").replace(
        '"demo::ResizeNode"', '"demo::ResizeNode" "demo::FailSafeNode"')
    files = {"CMakeLists.txt": cmake, "src/rectify.cpp": RECTIFY, "src/resize.cpp": RESIZE,
             "src/fail_safe.cpp": fail_safe}
    (node,) = _interfaces(tmp_path, demo_package, files, "demo::FailSafeNode")
    assert _names(node) == {} and node.unnamed == []
