"""A value launch coerces to the declared type (XML/YAML ``type="float"``, ``ParameterValue(...,
value_type=float)``) reaches the node as that type: launch's ``coerce_to_type`` calls ``float()``
on the performed text, so ``50`` is 50.0 and no P105. Without the type it stays YAML-typed."""
from __future__ import annotations

from typing import Any

XML = """<launch>
  <arg name="rate" default="50"/>
  <node pkg="robot_state_publisher" exec="robot_state_publisher" name="typed">
    <param name="publish_frequency" value="$(var rate)" type="float"/>
  </node>
  <node pkg="robot_state_publisher" exec="robot_state_publisher" name="literal">
    <param name="publish_frequency" value="20" type="float"/>
  </node>
  <node pkg="robot_state_publisher" exec="robot_state_publisher" name="untyped">
    <param name="publish_frequency" value="$(var rate)"/>
  </node>
</launch>
"""
PY = """from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node
from launch_ros.parameter_descriptions import ParameterValue


def generate_launch_description():
    rate = LaunchConfiguration('rate')
    return LaunchDescription([
        DeclareLaunchArgument('rate', default_value='50'),
        Node(package='robot_state_publisher', executable='robot_state_publisher', name='typed',
             parameters=[{'publish_frequency': ParameterValue(rate, value_type=float)}]),
        Node(package='robot_state_publisher', executable='robot_state_publisher', name='untyped',
             parameters=[{'publish_frequency': rate}]),
    ])
"""


def _p105(demo_findings: Any, name: str, text: str) -> list[tuple[int, str]]:
    return [(line, msg.split(" is declared")[0]) for line, msg in
            demo_findings({f"launch/{name}": text}, f"launch/{name}", "P105")]


def test_xml_type_float_coerces(demo_findings: Any) -> None:
    assert _p105(demo_findings, "a.launch.xml", XML) == [
        (10, 'parameter "publish_frequency" of /untyped')]


def test_parameter_value_type_float_coerces(demo_findings: Any) -> None:
    assert _p105(demo_findings, "a.launch.py", PY) == [
        (15, 'parameter "publish_frequency" of /untyped')]


YAML = """launch:
- arg: {name: rate, default: "50.0"}
- node:
    pkg: robot_state_publisher
    exec: robot_state_publisher
    name: quoted
    param:
    - {name: publish_frequency, value: "50.0"}
- node:
    pkg: robot_state_publisher
    exec: robot_state_publisher
    name: plain
    param:
    - {name: publish_frequency, value: 50.0}
- node:
    pkg: robot_state_publisher
    exec: robot_state_publisher
    name: substituted
    param:
    - {name: publish_frequency, value: "$(var rate)"}
"""


def test_yaml_launch_keeps_a_quoted_value_a_string(demo_findings: Any) -> None:
    """launch_yaml converts nothing, and parse_if_substitutions keeps a string without
    substitutions as a str: value: "50.0" reaches the node as the string "50.0" (XML's
    value="50.0" is a double). A substituted value is YAML-typed when it is evaluated."""
    assert _p105(demo_findings, "a.launch.yaml", YAML) == [
        (8, 'parameter "publish_frequency" of /quoted')]
