"""A node class deriving from a class of another workspace package runs its base's constructor:
what the base makes (a status publisher) may be the other end of a topic, so the dangling-topic
rules back off for its types; what it declares as parameters counts. Its generic wrappers
(``create_publisher<MessageT>(topic)``) add nothing, and a base that is not in the workspace
(``rclcpp::Node``) is not looked for."""
from __future__ import annotations

from pathlib import Path
from typing import Any

from physai_lint.interfaces import build_interface_store
from physai_lint.workspace.index import build_package_index

PACKAGE_XML = """<package format="3"><name>{name}</name><version>0.0.0</version><description>d</description>
<maintainer email="m@example.com">a</maintainer><license>MIT</license>
<exec_depend>base_pkg</exec_depend><exec_depend>listener_pkg</exec_depend>
<export><build_type>ament_cmake</build_type></export></package>
"""
BASE_HPP = """#pragma once
#include "rclcpp/rclcpp.hpp"
namespace base_pkg {
// class Decoy : public Elsewhere {  (a comment names no base)
class BaseClient : public rclcpp::Node {
public:
  explicit BaseClient(const std::string & name);
  template<typename MessageT>
  void advertise(const std::string & topic) { create_publisher<MessageT>(topic, 10); }
protected:
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr status_pub_;
};
}
"""
BASE_CPP = """#include "base_pkg/base_client.hpp"
namespace base_pkg {
BaseClient::BaseClient(const std::string & name) : rclcpp::Node(name) {
  declare_parameter("period", 1.0);
  status_pub_ = create_publisher<std_msgs::msg::String>("status", 10);
}
}
"""
BASE_CMAKE = """project(base_pkg)
add_library(base_client src/base_client.cpp)
install(TARGETS base_client LIBRARY DESTINATION lib)
"""
WORKER_HPP = """#pragma once
#include "base_pkg/base_client.hpp"
namespace derived_pkg {
class Worker : public base_pkg::BaseClient {
public:
  Worker();
};
}
"""
WORKER_CPP = """#include "derived_pkg/worker.hpp"
namespace derived_pkg {
Worker::Worker() : base_pkg::BaseClient("worker") { declare_parameter<double>("rate", 1.0); }
}
"""
MAIN = """#include "derived_pkg/worker.hpp"
int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<derived_pkg::Worker>());
}
"""
DERIVED_CMAKE = """project(derived_pkg)
add_library(worker_lib src/worker.cpp)
add_executable(worker_node src/worker_node.cpp)
target_link_libraries(worker_node worker_lib)
install(TARGETS worker_node DESTINATION lib/${PROJECT_NAME})
install(DIRECTORY launch DESTINATION share/${PROJECT_NAME})
"""
LISTENER_CPP = """#include "rclcpp/rclcpp.hpp"
class Listener : public rclcpp::Node {
public:
  Listener() : Node("listener") {
    sub_ = create_subscription<std_msgs::msg::String>("status", 10, [](std_msgs::msg::String::SharedPtr) {});
  }
  rclcpp::Subscription<std_msgs::msg::String>::SharedPtr sub_;
};
int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Listener>());
}
"""
LISTENER_CMAKE = """project(listener_pkg)
add_executable(listener src/listener.cpp)
install(TARGETS listener DESTINATION lib/${PROJECT_NAME})
"""
LAUNCH = """from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='derived_pkg', executable='worker_node', name='worker'),
        Node(package='listener_pkg', executable='listener', name='listener_a'),
        Node(package='listener_pkg', executable='listener', name='listener_b'),
    ])
"""


def _workspace(tmp_path: Path, with_base: bool = True) -> Path:
    files = {
        "derived_pkg/package.xml": PACKAGE_XML.format(name="derived_pkg"),
        "derived_pkg/CMakeLists.txt": DERIVED_CMAKE,
        "derived_pkg/include/derived_pkg/worker.hpp": WORKER_HPP,
        "derived_pkg/src/worker.cpp": WORKER_CPP,
        "derived_pkg/src/worker_node.cpp": MAIN,
        "derived_pkg/launch/demo.launch.py": LAUNCH,
        "listener_pkg/package.xml": PACKAGE_XML.format(name="listener_pkg"),
        "listener_pkg/CMakeLists.txt": LISTENER_CMAKE,
        "listener_pkg/src/listener.cpp": LISTENER_CPP,
    }
    if with_base:
        files.update({"base_pkg/package.xml": PACKAGE_XML.format(name="base_pkg"),
                      "base_pkg/CMakeLists.txt": BASE_CMAKE,
                      "base_pkg/include/base_pkg/base_client.hpp": BASE_HPP,
                      "base_pkg/src/base_client.cpp": BASE_CPP})
    for rel, text in files.items():
        (tmp_path / "src" / rel).parent.mkdir(parents=True, exist_ok=True)
        (tmp_path / "src" / rel).write_text(text)
    return tmp_path


def test_the_base_class_of_another_workspace_package_adds_its_typed_endpoints_and_parameters(
        tmp_path: Path) -> None:
    store, _ = build_interface_store([], build_package_index(str(_workspace(tmp_path))), "humble")
    worker: Any = store.get("derived_pkg", "worker_node")
    assert worker is not None
    assert not worker.publishers  # (named only as kind and type: a base may publish per parameter)
    assert worker.unnamed == [("publishers", "std_msgs/msg/String")]  # not the generic wrapper's
    assert worker.parameters is not None and sorted(worker.parameters) == ["period", "rate"]


def test_a_subscription_the_base_may_serve_is_not_reported(tmp_path: Path) -> None:
    from physai_lint.engine import CheckOptions, run_check

    ws = _workspace(tmp_path)
    opts = CheckOptions(paths=[str(ws / "src/derived_pkg/launch/demo.launch.py")], workspace=str(ws), cache=False)
    assert [f.message for f in run_check(opts).findings if f.code == "T201"] == []


def test_without_the_base_package_nothing_is_added(tmp_path: Path) -> None:
    store, _ = build_interface_store([], build_package_index(str(_workspace(tmp_path, with_base=False))),
                                     "humble")
    worker: Any = store.get("derived_pkg", "worker_node")
    assert worker is not None and worker.unnamed == [] and sorted(worker.parameters) == ["rate"]
