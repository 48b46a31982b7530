"""T202 (publication-without-subscriber) reports a publication nobody reads only for a near miss:
a similar topic that has subscribers and no publisher. A topic somebody publishes already is no
near miss, whether that publisher names it literally or computes the name at run time."""
from __future__ import annotations

CMAKE = """project(demo)
add_executable(camera src/camera.cpp)
add_executable(viewer src/viewer.cpp)
install(TARGETS camera viewer DESTINATION lib/${PROJECT_NAME})
install(DIRECTORY launch DESTINATION share/${PROJECT_NAME})
"""
CAMERA = """
class Camera : public rclcpp::Node {
 public:
  Camera() : Node("camera") {
    color_ = create_publisher<sensor_msgs::msg::Image>(COLOR, 10);
    overlay_ = create_publisher<sensor_msgs::msg::Image>("depth_to_color/image_raw", 10);
  }
};
int main() { rclcpp::spin(std::make_shared<Camera>()); }
"""
VIEWER = """
class Viewer : public rclcpp::Node {
 public:
  Viewer() : Node("viewer") {
    sub_ = create_subscription<sensor_msgs::msg::Image>("/cam2/color/image_raw", 10, [](Msg) {});
  }
};
int main() { rclcpp::spin(std::make_shared<Viewer>()); }
"""
LAUNCH = """
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='demo', executable='camera', name='camera', namespace='cam1'),
        Node(package='demo', executable='camera', name='camera', namespace='cam2'),
        Node(package='demo', executable='viewer', name='viewer'),
    ])
"""


def _t202(demo_findings, color: str) -> list[tuple[int, str]]:
    camera = CAMERA.replace("COLOR", color)
    return demo_findings({"CMakeLists.txt": CMAKE, "src/camera.cpp": camera, "src/viewer.cpp": VIEWER,
                          "launch/a.launch.py": LAUNCH}, "launch/a.launch.py", "T202")


def test_a_topic_published_under_its_name_is_no_near_miss(demo_findings) -> None:
    assert _t202(demo_findings, '"color/image_raw"') == []


def test_a_topic_a_computed_name_may_publish_is_no_near_miss(demo_findings) -> None:
    assert _t202(demo_findings, 'get_name() + std::string("/image_raw")') == []
