"""A lifecycle node's own endpoints (rcl_lifecycle: ``~/transition_event``, ``~/change_state``...)
are in the graph when its code derives from a lifecycle node class, or the launch starts it as a
``LifecycleNode``; callbacks written as lambdas keep their endpoints."""
from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import Any

from physai_lint.engine import CheckOptions, run_check

CMAKE = """project(demo)
add_executable(lc_talker src/talker.cpp)
add_executable(listener src/listener.cpp)
add_executable(plain_talker src/plain_talker.cpp)
install(TARGETS lc_talker listener plain_talker DESTINATION lib/${PROJECT_NAME})
install(DIRECTORY launch DESTINATION share/${PROJECT_NAME})
"""
TALKER = """
class LifecycleTalker : public rclcpp_lifecycle::LifecycleNode {
 public:
  LifecycleTalker() : rclcpp_lifecycle::LifecycleNode("lc_talker") {}
  CallbackReturn on_configure(const rclcpp_lifecycle::State &) {
    pub_ = create_publisher<std_msgs::msg::String>("lifecycle_chatter", 10);
    return CallbackReturn::SUCCESS;
  }
};
"""
# a project's own base class: the code does not show it is a lifecycle node
PLAIN_TALKER = """
class Talker : public my_base::ManagedNode {
  void on_configure() { pub_ = create_publisher<std_msgs::msg::String>("lifecycle_chatter", 10); }
};
"""
LISTENER = """
class Listener : public rclcpp::Node {
  Listener() : Node("listener") {
    data_ = create_subscription<std_msgs::msg::String>(
      "lifecycle_chatter", 10, [this](std_msgs::msg::String::ConstSharedPtr msg) {
        RCLCPP_INFO(get_logger(), "%s", msg->data.c_str());
      });
    events_ = create_subscription<lifecycle_msgs::msg::TransitionEvent>(
      "/lc_talker/transition_event", 10,
      [this](lifecycle_msgs::msg::TransitionEvent::ConstSharedPtr msg) { return on_event(msg); });
  }
};
"""
XML = """<launch>
  <node pkg="demo" exec="{exe}" name="{name}"/>
  <node pkg="demo" exec="listener" name="listener"/>
</launch>
"""
PY = """from launch import LaunchDescription
from launch_ros.actions import LifecycleNode, Node


def generate_launch_description():
    return LaunchDescription([
        LifecycleNode(package='demo', executable='plain_talker', name='lc_talker', namespace=''),
        Node(package='demo', executable='listener', name='listener'),
    ])
"""


def _t201(tmp_path: Path, demo_package: Callable[[dict[str, str]], Path], entry: str,
          files: dict[str, str]) -> list[str]:
    pkg = demo_package({"CMakeLists.txt": CMAKE, "src/talker.cpp": TALKER, "src/listener.cpp": LISTENER,
                        "src/plain_talker.cpp": PLAIN_TALKER, **files})
    opts = CheckOptions(paths=[str(pkg / entry)], workspace=str(tmp_path), cache=False)
    return [f.message for f in run_check(opts).findings if f.code == "T201"]


def test_a_lifecycle_class_publishes_its_transition_events(tmp_path: Path, demo_package: Any) -> None:
    launch = XML.format(exe="lc_talker", name="lc_talker")
    assert _t201(tmp_path, demo_package, "launch/a.launch.xml", {"launch/a.launch.xml": launch}) == []


def test_the_subscriptions_in_lambdas_are_seen(tmp_path: Path, demo_package: Any) -> None:
    # the talker under another name: both of the listener's lambda subscriptions are dangling
    launch = XML.format(exe="lc_talker", name="other_talker")
    found = _t201(tmp_path, demo_package, "launch/a.launch.xml", {"launch/a.launch.xml": launch})
    assert len(found) == 1 and '"/lc_talker/transition_event"' in found[0]
    assert '"/other_talker/transition_event"' in found[0]  # the near miss


def test_a_node_launched_as_lifecycle_node_has_them(tmp_path: Path, demo_package: Any) -> None:
    assert _t201(tmp_path, demo_package, "launch/a.launch.py", {"launch/a.launch.py": PY}) == []
    # the same executable as a plain Node: nothing says it is a lifecycle node
    plain = PY.replace("LifecycleNode(package", "Node(package")
    found = _t201(tmp_path, demo_package, "launch/a.launch.py", {"launch/a.launch.py": plain})
    assert len(found) == 1 and '"/lc_talker/transition_event"' in found[0]


def test_a_lifecycle_node_of_unknown_name_hides_no_other_topic(tmp_path: Path, demo_package: Any) -> None:
    # no name in the launch: its ~/transition_event cannot be named, but the listener's
    # lifecycle_chatter is still matched, and nothing else is reported
    launch = '<launch>\n  <node pkg="demo" exec="lc_talker"/>\n  <node pkg="demo" exec="listener" name="listener"/>\n</launch>\n'
    assert _t201(tmp_path, demo_package, "launch/a.launch.xml", {"launch/a.launch.xml": launch}) == []
    lone = launch.replace('exec="lc_talker"/>', 'exec="lc_talker"><remap from="lifecycle_chatter" to="x"/></node>')
    found = _t201(tmp_path, demo_package, "launch/a.launch.xml", {"launch/a.launch.xml": lone})
    assert len(found) == 1 and '"/lifecycle_chatter"' in found[0]
