"""P113 for a robot description given as ``Command(['xacro ', file])`` without
``ParameterValue(..., value_type=str)``: launch_ros reads the command's output with YAML rules, so a
line xacro keeps with ": ", " #" or a leading tab makes the launch fail (checked against xacro 2.0
and PyYAML: xacro keeps comments, apart from those right before a xacro: element, and re-indents
elements with spaces)."""
from __future__ import annotations

from typing import Any

import pytest

LAUNCH = """from launch import LaunchDescription
from launch.substitutions import Command, FindExecutable, PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.parameter_descriptions import ParameterValue
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    xacro_file = PathJoinSubstitution([FindPackageShare('demo'), 'urdf', 'robot.urdf.xacro'])
    description = {value}
    return LaunchDescription([
        Node(package='robot_state_publisher', executable='robot_state_publisher',
             parameters=[{{'robot_description': description}}]),
    ])
"""

CMAKE = """cmake_minimum_required(VERSION 3.8)
project(demo)
find_package(ament_cmake REQUIRED)
install(DIRECTORY launch urdf DESTINATION share/${PROJECT_NAME})
ament_package()
"""

URDF = """<?xml version="1.0"?>
<robot name="rover" xmlns:xacro="http://www.ros.org/wiki/xacro">
{body}
  <link name="base_link"/>
</robot>
"""

COMMAND = "Command([FindExecutable(name='xacro'), ' ', xacro_file])"


def _check(demo_findings: Any, body: str, value: str = COMMAND, launch: str = LAUNCH,
           entry: str = "launch/a.launch.py") -> list[tuple[int, str]]:
    files = {entry: launch.format(value=value), "CMakeLists.txt": CMAKE,
             "urdf/robot.urdf.xacro": URDF.format(body=body)}
    return demo_findings(files, entry, "P113")


@pytest.mark.parametrize(("body", "says"), [
    ("  <!-- Chassis: 0.5 m long -->", 'line 3 of robot.urdf.xacro ("<!-- Chassis: 0.5 m long -->")'),
    ("  <!-- sizes:\n       0.5 m long -->", 'makes YAML read a mapping'),
    ("  <!-- wheel #1 -->", "starts a YAML comment"),
    ("  <!-- wheels\n\tfront and rear -->", "line 4 of robot.urdf.xacro"),
    ('  <link name="arm #2"/>', "starts a YAML comment"),
])
def test_a_line_xacro_keeps_that_yaml_cannot_read(demo_findings: Any, body: str, says: str):
    found = _check(demo_findings, body)
    assert len(found) == 1 and found[0][0] == 13, found
    assert says in found[0][1] and "Unable to parse the value of parameter robot_description" in found[0][1]


@pytest.mark.parametrize("body", [
    "  <!-- Chassis 0.5 m long, see http://example.com -->",
    "  <!-- Macros: -->\n  <xacro:property name=\"w\" value=\"0.5\"/>",  # dropped by xacro
    "  <!-- a: b -->\n  <!-- c: d -->\n  <xacro:include filename=\"$(find demo)/urdf/x.xacro\"/>",
    "  <xacro:macro name=\"m\">\n    <!-- inside: only where it is called -->\n  </xacro:macro>",
    "  <xacro:if value=\"true\">\n    <!-- conditional: not looked at -->\n  </xacro:if>",
    "  <!-- xacro:eval-comments -->\n  <!-- ${1}: x -->",
    '  <link name="${prefix}: x"/>',
    "\t<!-- a tab before an element is re-indented -->",
    '  <material name="c"><color rgba="0 0 0 1"/></material> <!-- #fff is a colour, no space -->'.replace(" #", "#"),
])
def test_lines_xacro_drops_or_rewrites_are_left_alone(demo_findings: Any, body: str):
    assert _check(demo_findings, body) == []


def test_a_description_passed_as_a_string_is_fine(demo_findings: Any):
    assert _check(demo_findings, "  <!-- Chassis: 0.5 m -->",
                  value=f"ParameterValue({COMMAND}, value_type=str)") == []


def test_cat_prints_the_file_as_it_is(demo_findings: Any):
    found = _check(demo_findings, "\t<link name=\"wheel\"/>", value="Command(['cat ', xacro_file])")
    assert len(found) == 1 and "line 3 of robot.urdf.xacro" in found[0][1] and "tab" in found[0][1]
    assert _check(demo_findings, "\t<link name=\"wheel\"/>") == []  # xacro re-indents it


def test_an_xml_command_fails_in_coerce_to_type(demo_findings: Any):
    launch = """<launch>
  <node pkg="robot_state_publisher" exec="robot_state_publisher">
    <param name="robot_description" value="$(command 'xacro $(find-pkg-share demo)/urdf/robot.urdf.xacro')"/>
  </node>
</launch>
"""
    found = _check(demo_findings, "  <!-- Chassis: 0.5 m -->", launch=launch.replace("{", "{{").replace("}", "}}"),
                   entry="launch/a.launch.xml")
    assert len(found) == 1 and found[0][0] == 3 and "Failed to convert" in found[0][1], found
    assert 'given without type="str"' in found[0][1] and "ParameterValue" not in found[0][1], found


def test_a_parameter_value_without_a_type_fails_in_coerce_to_type(demo_findings: Any):
    found = _check(demo_findings, "  <!-- Chassis: 0.5 m -->", value=f"ParameterValue({COMMAND})")
    assert len(found) == 1 and "given as ParameterValue without value_type=str" in found[0][1], found
    assert "ValueError" in found[0][1] and "TypeError" not in found[0][1]
