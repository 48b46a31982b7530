"""T203 compares message types whose packages are known: ``gm::msg::Pose`` written through a
namespace alias (``namespace gm = geometry_msgs;`` in a header) is not a type of its own."""
from __future__ import annotations

from typing import Any

CMAKE = """project(demo)
add_executable(source src/source.cpp)
add_executable(sink src/sink.cpp)
install(TARGETS source sink DESTINATION lib/${PROJECT_NAME})
install(DIRECTORY launch DESTINATION share/${PROJECT_NAME})
"""
SOURCE = """#include "demo/aliases.hpp"
Source::Source() : Node("source") {
  pub_ = create_publisher<gm::msg::PoseStamped>("pose", 10);
}
"""
SINK = """
Sink::Sink() : Node("sink") {
  sub_ = create_subscription<TYPE>("pose", 10, [this](auto m) { on(m); });
}
"""
LAUNCH = """<launch>
  <node pkg="demo" exec="source" name="source"/>
  <node pkg="demo" exec="sink" name="sink"/>
</launch>
"""


def _t203(demo_findings: Any, sink_type: str) -> list[str]:
    files = {"CMakeLists.txt": CMAKE, "src/source.cpp": SOURCE, "src/sink.cpp": SINK.replace("TYPE", sink_type),
             "include/demo/aliases.hpp": "namespace gm = geometry_msgs;\n", "launch/a.launch.xml": LAUNCH}
    return [m for _, m in demo_findings(files, "launch/a.launch.xml", "T203")]


def test_an_aliased_type_is_not_a_mismatch(demo_findings: Any) -> None:
    assert _t203(demo_findings, "geometry_msgs::msg::PoseStamped") == []


def test_known_types_still_are(demo_findings: Any) -> None:
    source = SOURCE.replace("gm::msg::PoseStamped", "geometry_msgs::msg::PoseStamped")
    files = {"CMakeLists.txt": CMAKE, "src/source.cpp": source, "src/sink.cpp": SINK.replace("TYPE", "std_msgs::msg::String"),
             "launch/a.launch.xml": LAUNCH}
    assert len(demo_findings(files, "launch/a.launch.xml", "T203")) == 1
