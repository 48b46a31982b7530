"""A component container (rclcpp_components) has no topics of its own: its components are the
nodes of the graph. Launched in a container, components are checked for dangling topics as they
are launched as nodes; one component alone in a container is a launch of one node."""
from __future__ import annotations

CMAKE = """project(demo)
add_library(driver_component SHARED src/driver.cpp)
rclcpp_components_register_node(driver_component PLUGIN "demo::Driver" EXECUTABLE driver)
add_library(viewer_component SHARED src/viewer.cpp)
rclcpp_components_register_node(viewer_component PLUGIN "demo::Viewer" EXECUTABLE viewer)
install(TARGETS driver_component viewer_component LIBRARY DESTINATION lib RUNTIME DESTINATION bin)
install(DIRECTORY launch DESTINATION share/${PROJECT_NAME})
"""
DRIVER = """namespace demo {
class Driver : public rclcpp::Node {
 public:
  explicit Driver(const rclcpp::NodeOptions & o) : Node("driver", o) {
    pub_ = create_publisher<sensor_msgs::msg::PointCloud2>("points", 10);
  }
};
}
RCLCPP_COMPONENTS_REGISTER_NODE(demo::Driver)
"""
VIEWER = """namespace demo {
class Viewer : public rclcpp::Node {
 public:
  explicit Viewer(const rclcpp::NodeOptions & o) : Node("viewer", o) {
    sub_ = create_subscription<sensor_msgs::msg::PointCloud2>("cloud", 10, [](Msg) {});
  }
};
}
RCLCPP_COMPONENTS_REGISTER_NODE(demo::Viewer)
"""
CONTAINER = """
from launch import LaunchDescription
from launch_ros.actions import ComposableNodeContainer
from launch_ros.descriptions import ComposableNode


def generate_launch_description():
    return LaunchDescription([ComposableNodeContainer(
        name='lidar_container', namespace='', package='rclcpp_components', executable='EXE',
        composable_node_descriptions=[COMPONENTS])])
"""
DRIVER_C = "ComposableNode(package='demo', plugin='demo::Driver', name='driver')"
VIEWER_C = "ComposableNode(package='demo', plugin='demo::Viewer', name='viewer')"


def _t201(demo_findings, executable: str, components: str) -> list[str]:
    launch = CONTAINER.replace("EXE", executable).replace("COMPONENTS", components)
    files = {"CMakeLists.txt": CMAKE, "src/driver.cpp": DRIVER, "src/viewer.cpp": VIEWER,
             "launch/a.launch.py": launch}
    return [m for _, m in demo_findings(files, "launch/a.launch.py", "T201")]


def test_components_in_a_container_are_checked_like_nodes(demo_findings) -> None:
    for executable in ("component_container", "component_container_mt", "component_container_isolated"):
        assert _t201(demo_findings, executable, f"{DRIVER_C}, {VIEWER_C}") == [
            '/viewer subscribes to "/cloud" but nothing publishes it'], executable


def test_one_component_in_a_container_is_a_launch_of_one_node(demo_findings) -> None:
    assert _t201(demo_findings, "component_container", VIEWER_C) == []
