"""Parameters on a node's own command line: ``ros_arguments=['-p', 'name:=value']``,
``arguments=['--ros-args', '--params-file', path]`` and XML ``ros_args``. rcl reads ``-p`` values
with its YAML value parser (``_rcl_parse_param_rule`` -> ``rcl_parse_yaml_value``) under node key
``/**`` (or ``node`` for ``-p node:name:=v``), and merges every source in command-line order;
launch_ros puts the user's arguments before its own ``--ros-args`` section (``Node.__init__``), so
SetParameter and ``parameters=`` override them."""
from __future__ import annotations

from typing import Any

import pytest

PY = """from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='robot_state_publisher', executable='robot_state_publisher', name='rsp',
             {how}),
    ])
"""


def _with_imports(launch: str) -> str:
    """``launch`` importing the substitutions the ``how`` of a test may use."""
    return launch.replace(
        "from launch_ros.actions import Node\n",
        "from launch.substitutions import LaunchConfiguration, PathJoinSubstitution\n"
        "from launch_ros.actions import Node\nfrom launch_ros.substitutions import FindPackageShare\n")


def _p105(demo_findings: Any, files: dict[str, str], entry: str) -> list[tuple[int, str]]:
    return [(line, msg.split(" is declared")[0]) for line, msg in
            demo_findings(files, entry, "P105")]


@pytest.mark.parametrize("how", [
    "ros_arguments=['-p', 'publish_frequency:=10']",
    "ros_arguments=['--log-level', 'info', '--param', 'publish_frequency:=10']",
    "arguments=['--ros-args', '-p', 'publish_frequency:=10']",
    "ros_arguments=['-p', 'publish_frequency:=[1.0, 2.0]']",  # a YAML flow list is an array
    "ros_arguments=['-p', 'rsp:publish_frequency:=10']",
])
def test_a_command_line_parameter_reaches_the_node(demo_findings: Any, how: str) -> None:
    assert _p105(demo_findings, {"launch/a.launch.py": PY.format(how=how)}, "launch/a.launch.py") == [
        (8, 'parameter "publish_frequency" of /rsp')]


@pytest.mark.parametrize("how", [
    "ros_arguments=['-p', 'publish_frequency:=10.0']",
    # launch's own file keys the dict by the full name: resolved after "/**", it wins
    "namespace='r1', ros_arguments=['-p', 'publish_frequency:=10'], "
    "parameters=[{'publish_frequency': 20.0}]",
    "ros_arguments=['-p', 'other:publish_frequency:=10']",  # node key "other": not this node
    "ros_arguments=['--log-level', 'publish_frequency:=10']",  # a flag's value, not a parameter
    "arguments=['-p', 'publish_frequency:=10']",  # outside --ros-args: the program's own argument
])
def test_what_does_not_reach_the_node_as_given(demo_findings: Any, how: str) -> None:
    assert _p105(demo_findings, {"launch/a.launch.py": PY.format(how=how)}, "launch/a.launch.py") == []


def test_a_later_double_under_the_same_key_does_not_replace_the_integer(demo_findings: Any) -> None:
    # without a namespace launch keys the dict by "/**" too: rcl_variant_t then holds both the
    # integer and the double, and the client library reads the integer first
    how = "ros_arguments=['-p', 'publish_frequency:=10'], parameters=[{'publish_frequency': 20.0}]"
    found = demo_findings({"launch/a.launch.py": PY.format(how=how)}, "launch/a.launch.py", "P105")
    assert len(found) == 1
    assert "(the later 20.0 at line 8 does not replace it: rcl keeps one value per type" in found[0][1]


def test_a_params_file_in_arguments_is_read_by_rcl(demo_findings: Any) -> None:
    how = ("arguments=['--ros-args', '--params-file', "
           "PathJoinSubstitution([FindPackageShare('demo'), 'config', 'rsp.yaml'])]")
    launch = _with_imports(PY.format(how=how))
    files = {"launch/a.launch.py": launch,
             "config/rsp.yaml": "rsp:\n  ros__parameters:\n    publish_frequency: 10\n"}
    found = demo_findings(files, "launch/a.launch.py", "P105")
    assert [line for line, _ in found] == [3]


def test_xml_ros_args(demo_findings: Any) -> None:
    xml = """<launch>
  <node pkg="robot_state_publisher" exec="robot_state_publisher" name="rsp"
        ros_args="--log-level info -p publish_frequency:=10"/>
</launch>
"""
    assert _p105(demo_findings, {"launch/a.launch.xml": xml}, "launch/a.launch.xml") == [
        (3, 'parameter "publish_frequency" of /rsp')]


def test_a_missing_params_file_on_the_command_line_stops_the_node(demo_findings: Any) -> None:
    # rcl_parse_arguments fails ("Couldn't parse params file"), unlike a parameters= path that
    # launch_ros drops with a warning
    how = ("ros_arguments=['--params-file', "
           "PathJoinSubstitution([FindPackageShare('demo'), 'config', 'none.yaml'])]")
    launch = _with_imports(PY.format(how=how))
    found = demo_findings({"launch/a.launch.py": launch}, "launch/a.launch.py", "P101")
    assert len(found) == 1
    assert "exits at start-up with \"Couldn't parse params file" in found[0][1]


@pytest.mark.parametrize("how", [
    "ros_arguments=['-p', 'publish_frequency:={a: 1}']",  # a mapping is no value to rcl
    "ros_arguments=[LaunchConfiguration('flag'), 'publish_frequency:=10']",  # -p or -r: unknown
])
def test_values_rcl_would_not_read_as_given_are_unknown(demo_findings: Any, how: str) -> None:
    launch = _with_imports(PY.format(how=how))
    assert _p105(demo_findings, {"launch/a.launch.py": launch}, "launch/a.launch.py") == []


def test_a_null_on_the_command_line_is_a_string_to_rcl(demo_findings: Any) -> None:
    how = "ros_arguments=['-p', 'frame_prefix:=null']"
    assert demo_findings({"launch/a.launch.py": PY.format(how=how)}, "launch/a.launch.py", "P112") == []
