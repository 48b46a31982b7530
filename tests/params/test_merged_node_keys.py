"""X006 for a node key repeated with a mapping as value: rcl (a node's --params-file) merges the two
blocks, a deliberate layout (one /** block per controller); launch_ros reads a composable node's
file with PyYAML, which keeps only the second."""
from __future__ import annotations

PARAMS = "/**:\n  ros__parameters:\n    a: 1\n/**:\n  ros__parameters:\n    b: 2\n"
NODE = """<launch>
  <node pkg="demo_nodes_cpp" exec="talker" name="talker">
    <param from="$(find-pkg-share demo)/config/p.yaml"/>
  </node>
</launch>
"""
COMPONENT = """<launch>
  <node_container pkg="rclcpp_components" exec="component_container" name="box" namespace="">
    <composable_node pkg="demo_nodes_cpp" plugin="demo_nodes_cpp::Talker" name="talker">
      <param from="$(find-pkg-share demo)/config/p.yaml"/>
    </composable_node>
  </node_container>
</launch>
"""


def _x006(demo_findings, launch: str) -> list[tuple[int, str]]:
    files = {"config/p.yaml": PARAMS, "launch/a.launch.xml": launch}
    return demo_findings(files, "launch/a.launch.xml", "X006")


def test_a_node_s_file_may_repeat_a_node_key(demo_findings):
    assert _x006(demo_findings, NODE) == []


def test_a_composable_node_s_file_loses_the_first_block(demo_findings):
    assert [(line, "keeps only the second" in msg) for line, msg in _x006(demo_findings, COMPONENT)] == [(4, True)]
