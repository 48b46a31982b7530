"""N101 for one node of a file included twice says why the two instances get one name: an
absolute namespace the includes' pushed namespaces do not change, or a launch configuration that
keeps its value from one include to the next (IncludeLaunchDescription pushes no scope)."""
from __future__ import annotations

from typing import Any

CHILD = """<launch>
  <arg name="robot_name" default="rover2"/>
  <node pkg="demo_nodes_cpp" exec="talker" name="talker" namespace="{ns}"/>
</launch>
"""
PARENT = """<launch>
  <group>
    <push-ros-namespace namespace="a"/>
    <include file="$(find-pkg-share demo)/launch/child.launch.xml">{arg}</include>
  </group>
  <group>
    <push-ros-namespace namespace="{second}"/>
    <include file="$(find-pkg-share demo)/launch/child.launch.xml"/>
  </group>
</launch>
"""


def _n101(demo_findings: Any, ns: str, second: str = "b", arg: str = "") -> list[str]:
    files = {"launch/child.launch.xml": CHILD.format(ns=ns),
             "launch/parent.launch.xml": PARENT.format(second=second, arg=arg)}
    return [m for _, m in demo_findings(files, "launch/parent.launch.xml", "N101")]


def test_an_absolute_namespace_is_named_as_the_cause(demo_findings: Any):
    (msg,) = _n101(demo_findings, "/sensors")
    assert 'its namespace "/sensors" is absolute' in msg


def test_a_configuration_that_keeps_its_value_is_named_as_the_cause(demo_findings: Any):
    parent = """<launch>
  <include file="$(find-pkg-share demo)/launch/child.launch.xml">
    <arg name="robot_name" value="rover1"/>
  </include>
  <include file="$(find-pkg-share demo)/launch/child.launch.xml"/>
</launch>
"""
    files = {"launch/child.launch.xml": CHILD.format(ns="$(var robot_name)"), "launch/parent.launch.xml": parent}
    (msg,) = [m for _, m in demo_findings(files, "launch/parent.launch.xml", "N101")]
    assert 'reads the launch configuration "robot_name" with the same value each time' in msg


def test_otherwise_the_same_namespace(demo_findings: Any):
    (msg,) = _n101(demo_findings, "", second="a")
    assert "included 2 times in the same namespace" in msg
