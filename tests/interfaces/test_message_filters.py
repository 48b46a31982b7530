"""message_filters subscribers subscribe when constructed with a node and a topic, or told to
(``sub_.subscribe(node, "topic", qos)``); image_transport's ``it.subscribe("topic", ...)`` is
still an image subscription."""
from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest

from physai_lint.interfaces import build_interface_store
from physai_lint.interfaces.extract_cpp import extract_cpp
from physai_lint.workspace.index import build_package_index


def _subscribers(text: str) -> tuple[list[tuple[str, str | None]], list[tuple[str, str | None]]]:
    """(named subscriptions as (topic, type), unnamed ones as (kind, type)) of a source."""
    iface = extract_cpp([("/ws/src/demo/src/a.cpp", text)])
    return [(e.name, e.type) for e in iface.endpoints("subscribers")], iface.unnamed


@pytest.mark.parametrize("text, named", [
    ("""class Listener : public rclcpp::Node {
  Listener() : rclcpp::Node("listener"), odom_sub_(this, "acceleration/filtered"), other_(3) {}
  message_filters::Subscriber<nav_msgs::msg::Odometry> odom_sub_;
};""", [("acceleration/filtered", "nav_msgs/msg/Odometry")]),
    ("""class Listener2 : public rclcpp::Node {
  Listener2() : rclcpp::Node("listener2") { sub_.subscribe(this, "scan_in"); }
  message_filters::Subscriber<sensor_msgs::msg::LaserScan> sub_;
};""", [("scan_in", "sensor_msgs/msg/LaserScan")]),
    ("""Odometry::Odometry(rclcpp::Node::SharedPtr nh) {
  joint_sub_ = std::make_shared<message_filters::Subscriber<sensor_msgs::msg::JointState>>(
    nh, "joint_states");
  imu_sub_ = new message_filters::Subscriber<sensor_msgs::msg::Imu,
    rclcpp_lifecycle::LifecycleNode>(nh, "imu", qos);
}""", [("joint_states", "sensor_msgs/msg/JointState"), ("imu", "sensor_msgs/msg/Imu")]),
    ("""struct Merger : rclcpp::Node {
  message_filters::Subscriber<DetectedObjects> a_{this, "input/a"}, b_{this, "input/b"};
};""", [("input/a", None), ("input/b", None)]),
    # declared elsewhere (a header): the topic, not the type
    ('Pc2Scan::Pc2Scan() : Node("p") { sub_.subscribe(this, "cloud_in", qos.get_rmw_qos_profile()); }',
     [("cloud_in", None)]),
    (('Stereo::Stereo() : Node("s") { image_transport::SubscriberFilter left_;\n'
      '  left_.subscribe(this, "left/image_rect", "raw"); }'), [("left/image_rect", "sensor_msgs/msg/Image")]),
    # image_transport's own subscribe: the topic first
    ('void f() { image_sub_ = it.subscribe("camera/image", 1, &C::cb, this); }',
     [("camera/image", "sensor_msgs/msg/Image")]),
], ids=["initialiser", "subscribe", "make_shared-new", "braced", "undeclared", "image-filter",
        "image_transport"])
def test_subscriptions_are_named(text: str, named: list[tuple[str, str | None]]) -> None:
    assert _subscribers(text) == (named, [])


@pytest.mark.parametrize("text, unnamed", [
    ('void C::f() { sub_.subscribe(this, topic_name_, qos); }', [("subscribers", None)]),
    ('void C::f() { sub_ = it.subscribe(topic, 1, &C::cb, this); }',
     [("subscribers", "sensor_msgs/msg/Image")]),
], ids=["filter", "image_transport"])
def test_a_topic_known_at_run_time_is_unnamed(text: str, unnamed: list[tuple[str, str | None]]) -> None:
    assert _subscribers(text) == ([], unnamed)


CMAKE = """project(demo)
add_library(listener_lib src/listener.cpp)
add_executable(listener_node src/listener_node.cpp)
target_link_libraries(listener_node listener_lib)
install(TARGETS listener_node DESTINATION lib/${PROJECT_NAME})
"""
HEADER = """#include "message_filters/subscriber.h"
class Listener {
  Listener(rclcpp::Node::SharedPtr node);
  message_filters::Subscriber<nav_msgs::msg::Odometry> odom_sub_;
  message_filters::Subscriber<geometry_msgs::msg::AccelWithCovarianceStamped>
    accel_sub_;
  message_filters::TimeSynchronizer<nav_msgs::msg::Odometry,
    geometry_msgs::msg::AccelWithCovarianceStamped> sync_;
};
"""
SOURCE = """#include "demo/listener.hpp"
Listener::Listener(rclcpp::Node::SharedPtr node)
: odom_sub_(node, "odom/filtered", qos),
  accel_sub_(node, "acceleration/filtered", qos),
  sync_(odom_sub_, accel_sub_, 10u)
{
  int size = node->declare_parameter<int>("buffer_size", 10);
  sync_.registerCallback(std::bind(&Listener::cb, this, _1, _2));
}
"""
MAIN = """#include "demo/listener.hpp"
int main() { auto node = rclcpp::Node::make_shared("n"); Listener listener(node); }
"""


def test_members_the_header_declares_subscribe_in_the_initialisers(
        tmp_path: Path, demo_package: Callable[[dict[str, str]], Path]) -> None:
    demo_package({"CMakeLists.txt": CMAKE, "include/demo/listener.hpp": HEADER,
                  "src/listener.cpp": SOURCE, "src/listener_node.cpp": MAIN})
    store, _ = build_interface_store([], build_package_index(str(tmp_path)), "humble")
    iface = store.get("demo", "listener_node")
    assert iface is not None
    assert [(e.name, e.type) for e in iface.endpoints("subscribers")] == [
        ("acceleration/filtered", "geometry_msgs/msg/AccelWithCovarianceStamped"),
        ("odom/filtered", "nav_msgs/msg/Odometry")]


PAIR_CMAKE = """project(demo)
add_executable(listener src/listener.cpp)
add_executable(talker src/talker.cpp)
install(TARGETS listener talker DESTINATION lib/${PROJECT_NAME})
install(DIRECTORY launch DESTINATION share/${PROJECT_NAME})
"""
LISTENER = """#include <message_filters/subscriber.h>
class Listener : public rclcpp::Node {
public:
  Listener() : rclcpp::Node("listener"), odom_sub_(this, "acceleration/filtered") {}
  message_filters::Subscriber<nav_msgs::msg::Odometry> odom_sub_;
};
"""
TALKER = """int main() {
  auto node = rclcpp::Node::make_shared("talker");
  auto pub = node->create_publisher<nav_msgs::msg::Odometry>("acceleration/filtred", 10);
}
"""
PAIR = """<launch>
  <node pkg="demo" exec="listener" name="listener"/>
  <node pkg="demo" exec="talker" name="talker"/>
</launch>
"""


def test_a_message_filters_subscription_is_a_subscriber(demo_findings: Any) -> None:
    files = {"CMakeLists.txt": PAIR_CMAKE, "src/listener.cpp": LISTENER, "src/talker.cpp": TALKER,
             "launch/pair.launch.xml": PAIR}
    # the misspelt one dangles, and the filter's subscription is the near miss that says so (a
    # near miss has subscribers and no publisher)
    assert [m for _, m in demo_findings(files, "launch/pair.launch.xml", "T202")] == [
        ('/talker publishes "/acceleration/filtred" but nothing subscribes to it '
         '(did you mean "/acceleration/filtered"?)')]


PY_NODE = """import message_filters
import message_filters as mf
from message_filters import Subscriber
from rclpy.node import Node
from sensor_msgs.msg import CameraInfo, Image
from vision_msgs.msg import Detection2DArray


class Overlay(Node):
    def __init__(self):
        super().__init__('overlay')
        self.image = message_filters.Subscriber(self, Image, 'image_rect')
        self.info = mf.Subscriber(self, CameraInfo, 'camera_info', qos_profile=10)
        self.dets = Subscriber(self, Detection2DArray, topic=self.get_parameter('t').value)
        self.other = SomethingElse.Subscriber(self, Image, 'not_a_topic')
"""


def test_python_message_filters_subscribers_are_subscriptions() -> None:
    from physai_lint.interfaces.extract_py import extract_py

    iface = extract_py([("/ws/src/demo/demo/overlay.py", PY_NODE)])
    assert [(e.name, e.type) for e in iface.endpoints("subscribers")] == [
        ("image_rect", "sensor_msgs/msg/Image"), ("camera_info", "sensor_msgs/msg/CameraInfo")]
    assert iface.unnamed == [("subscribers", "vision_msgs/msg/Detection2DArray")]
