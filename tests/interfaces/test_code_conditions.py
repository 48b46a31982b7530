"""An endpoint the code makes only under a condition it tests at run time (``if (use_scan_)``,
``else``, ``?:``, ``#ifdef WITH_X``) may not exist: T201/T202 do not report it, and it still
counts as the other end of a topic (``Endpoint.when`` is ``CODE_CONDITION``)."""
from __future__ import annotations

from physai_lint.interfaces.extract_cpp import extract_cpp
from physai_lint.interfaces.extract_py import extract_py
from physai_lint.interfaces.model import CODE_CONDITION

CPP = """#ifndef DEMO__FOO_HPP_
#define DEMO__FOO_HPP_
Foo::Foo(const rclcpp::NodeOptions & o) : Node("foo", o) {
  pub_ = create_publisher<std_msgs::msg::String>("always", 10);
  if (use_scan_) {
    scan_sub_ = create_subscription<sensor_msgs::msg::LaserScan>("scan", 10, cb);
  } else {
    odom_sub_ = create_subscription<nav_msgs::msg::Odometry>("odom", 10, cb);
  }
  if (use_imu_) imu_sub_ = create_subscription<sensor_msgs::msg::Imu>("imu", 10, cb);
  auto maybe = debug_ ? create_publisher<std_msgs::msg::String>("debug", 10) : nullptr;
  for (int i = 0; i < 2; ++i) { loop_ = create_publisher<std_msgs::msg::String>("loop", 10); }
  // if (commented) {
  image_sub_ = create_subscription<sensor_msgs::msg::Image>("image", 10, cb);
#ifdef WITH_APRILTAG_MSGS
  tags_sub_ = create_subscription<apriltag_msgs::msg::AprilTagDetectionArray>("tag_detections", 5, cb);
#endif
}
#endif  // DEMO__FOO_HPP_
"""


def _conditional(iface) -> dict[str, bool]:
    return {e.name: e.when == CODE_CONDITION for e in [*iface.publishers, *iface.subscribers]}


def test_cpp():
    assert _conditional(extract_cpp([("/ws/src/foo.hpp", CPP)])) == {
        "always": False, "scan": True, "odom": True, "imu": True, "debug": True, "loop": False,
        "image": False, "tag_detections": True}


PY = """import rclpy
from rclpy.node import Node
from std_msgs.msg import String


class T(Node):
    def __init__(self):
        super().__init__('t')
        self.a = self.create_publisher(String, 'always', 10)
        if self.get_parameter('use_b').value:
            self.b = self.create_subscription(String, 'b', self.cb, 10)
        else:
            self.c = self.create_subscription(String, 'c', self.cb, 10)
        self.d = self.create_publisher(String, 'd', 10) if self.debug else None


if __name__ == '__main__':
    rclpy.init()
    node = rclpy.create_node('script')
    script_pub = node.create_publisher(String, 'script', 10)
"""


def test_python():
    assert _conditional(extract_py([("/ws/src/t.py", PY)])) == {
        "always": False, "b": True, "c": True, "d": True, "script": False}


CMAKE = """project(demo)
add_executable(filter src/filter.cpp)
add_executable(driver src/driver.cpp)
install(TARGETS filter driver DESTINATION lib/${PROJECT_NAME})
install(DIRECTORY launch DESTINATION share/${PROJECT_NAME})
"""
FILTER = """class Filter : public rclcpp::Node {
 public:
  Filter() : Node("filter") {
    cloud_sub_ = create_subscription<sensor_msgs::msg::PointCloud2>("cloud", 10, cb);
    if (use_imu_) {
      imu_sub_ = create_subscription<sensor_msgs::msg::Imu>("imu", 10, cb);
    }
  }
};
"""
DRIVER = """class Driver : public rclcpp::Node {
 public:
  Driver() : Node("driver") { pub_ = create_publisher<sensor_msgs::msg::PointCloud2>("points", 10); }
};
"""
LAUNCH = """from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='demo', executable='driver'),
        Node(package='demo', executable='filter'),
    ])
"""


def test_t201_reports_the_unconditional_subscription_only(demo_findings):
    found = demo_findings({"CMakeLists.txt": CMAKE, "src/filter.cpp": FILTER, "src/driver.cpp": DRIVER,
                           "launch/a.launch.py": LAUNCH}, "launch/a.launch.py", "T201")
    assert [message.split(" but")[0] for _, message in found] == ['/filter subscribes to "/cloud"']
