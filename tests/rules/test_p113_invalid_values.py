"""P113: a parameter value launch types with YAML rules (a substitution, an XML value) whose text
YAML cannot make a parameter value of. Checked against humble launch 1.0.7 / launch_ros 0.19.8:
Python dicts raise TypeError in evaluate_parameter_dict, XML substitutions ValueError in
coerce_to_type, an XML literal mapping TypeError in launch_xml's get_attr; an XML literal YAML
cannot read stays a string."""
from __future__ import annotations

from typing import Any

import pytest

PY = """from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('v', default_value={default!r}),
        Node(package='demo_nodes_cpp', executable='talker', name='talker',
             parameters=[{{'frame': {value}}}]),
    ])
"""

XML = """<launch>
  <arg name="v" default="{default}"/>
  <node pkg="demo_nodes_cpp" exec="talker" name="talker">
    <param name="frame" value="{value}"/>
  </node>
</launch>
"""


def _py(demo_findings: Any, value: str, default: str = "x") -> list[tuple[int, str]]:
    return demo_findings({"launch/a.launch.py": PY.format(value=value, default=default)},
                         "launch/a.launch.py", "P113")


def _xml(demo_findings: Any, value: str, default: str = "x") -> list[tuple[int, str]]:
    return demo_findings({"launch/a.launch.xml": XML.format(value=value, default=default)},
                         "launch/a.launch.xml", "P113")


@pytest.mark.parametrize(("default", "says"), [
    ("map: odom", "Got <class 'dict'>"),
    ("a: {", "Unable to parse the value of parameter frame as yaml"),
    ("\tx: 1", "Unable to parse the value of parameter frame as yaml"),
])
def test_a_python_substitution_that_yaml_cannot_type(demo_findings: Any, default: str, says: str):
    found = _py(demo_findings, "LaunchConfiguration('v')", default)
    assert len(found) == 1 and found[0][0] == 11 and says in found[0][1], found


@pytest.mark.parametrize("default", ["map odom", "a:b", "[1, 2]", "~", "'a: b'", "http://x"])
def test_texts_yaml_types_or_that_other_rules_own_are_left_alone(demo_findings: Any, default: str):
    assert _py(demo_findings, "LaunchConfiguration('v')", default) == []


def test_python_literals_and_str_values_stay_strings(demo_findings: Any):
    assert _py(demo_findings, "'map: odom'") == []
    text = PY.format(value="ParameterValue(LaunchConfiguration('v'), value_type=str)", default="a: b").replace(
        "from launch_ros.actions import Node",
        "from launch_ros.actions import Node\nfrom launch_ros.parameter_descriptions import ParameterValue")
    assert demo_findings({"launch/a.launch.py": text}, "launch/a.launch.py", "P113") == []


def test_xml_substitutions_fail_in_coerce_to_type(demo_findings: Any):
    found = _xml(demo_findings, "$(var v)", "map: odom")
    assert len(found) == 1 and found[0][0] == 4 and "Failed to convert 'map: odom' using yaml rules" in found[0][1]
    found = _xml(demo_findings, "$(var v)", "a: {")
    assert len(found) == 1 and "yaml.safe_load() failed" in found[0][1]


def test_an_xml_literal_mapping_fails_loading_the_file_and_an_unreadable_one_stays_text(demo_findings: Any):
    found = _xml(demo_findings, "map: odom")
    assert len(found) == 1 and "the launch file fails to load" in found[0][1]
    assert _xml(demo_findings, "a: {") == []
    assert demo_findings({"launch/a.launch.xml": XML.format(value="map: odom", default="x").replace(
        'name="frame"', 'name="frame" type="str"')}, "launch/a.launch.xml", "P113") == []


def test_a_node_that_never_starts_is_not_reported(demo_findings: Any):
    text = XML.format(value="$(var v)", default="map: odom").replace('name="talker">', 'name="talker" if="false">')
    assert demo_findings({"launch/a.launch.xml": text}, "launch/a.launch.xml", "P113") == []


@pytest.mark.parametrize(("default", "says"), [
    ("map: odom", "Failed to convert 'map: odom' using yaml rules: output type is not allowed"),
    ("a: {", "Failed to convert 'a: {' using yaml rules: yaml.safe_load() failed"),
])
def test_a_parameter_value_without_a_type_fails_in_coerce_to_type(demo_findings: Any, default: str, says: str):
    # ParameterValue.evaluate -> perform_typed_substitution -> coerce_to_type(None): ValueError,
    # not evaluate_parameter_dict's TypeError for a bare substitution (humble launch_ros 0.19.8)
    text = PY.format(value="ParameterValue(LaunchConfiguration('v'))", default=default).replace(
        "from launch_ros.actions import Node",
        "from launch_ros.actions import Node\nfrom launch_ros.parameter_descriptions import ParameterValue")
    found = demo_findings({"launch/a.launch.py": text}, "launch/a.launch.py", "P113")
    assert len(found) == 1 and says in found[0][1] and "ParameterValue without a value_type" in found[0][1], found
    assert "TypeError" not in found[0][1]
