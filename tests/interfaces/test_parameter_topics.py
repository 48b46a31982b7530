"""A topic held in a variable that ``get_parameter`` overwrites is the parameter's value, not the
literal the variable starts with (mrpt's tps_astar_planner: ``std::string topic_ = "goal";``
then ``get_parameter("topic", topic_)``): unknown statically, so no endpoint is named after the
literal."""
from __future__ import annotations

import pytest

from physai_lint.interfaces.extract_cpp import extract_cpp

NODE = """#include <rclcpp/rclcpp.hpp>
#include <geometry_msgs/msg/pose_stamped.hpp>

class Planner : public rclcpp::Node {
 public:
  Planner() : Node("planner_node") {
    this->declare_parameter<std::string>("topic_goal_sub", topic_goal_sub_);
    READ
    sub_ = this->create_subscription<geometry_msgs::msg::PoseStamped>(
      topic_goal_sub_, 10, [](const geometry_msgs::msg::PoseStamped &) {});
  }
 private:
  std::string topic_goal_sub_ = "planner_goal";
  rclcpp::Subscription<geometry_msgs::msg::PoseStamped>::SharedPtr sub_;
};
"""


@pytest.mark.parametrize("read", [
    'this->get_parameter("topic_goal_sub", topic_goal_sub_);',
    'get_parameter<std::string>("topic_goal_sub", this->topic_goal_sub_);',
    'this->get_parameter_or("topic_goal_sub", topic_goal_sub_, std::string("x"));',
])
def test_a_variable_get_parameter_writes_is_no_constant(read: str) -> None:
    iface = extract_cpp([("/ws/src/demo/src/planner.cpp", NODE.replace("READ", read))])
    assert iface.endpoints("subscribers") == []
    assert iface.unnamed == [("subscribers", "geometry_msgs/msg/PoseStamped")]


def test_a_variable_only_declared_with_keeps_its_literal() -> None:
    iface = extract_cpp([("/ws/src/demo/src/planner.cpp", NODE.replace("READ", ""))])
    assert [e.name for e in iface.endpoints("subscribers")] == ["planner_goal"]
