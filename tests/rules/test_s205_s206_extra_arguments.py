"""S205/S206: a component's extra_arguments, typed as launch_ros sends them in the load request
(Python literals keep their type, substitutions and markup values are typed by YAML), against the
names and the bool type rclcpp's component manager requires (component_manager.cpp ::
create_node_options)."""
from __future__ import annotations

from typing import Any

import pytest

PY = """from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import ComposableNodeContainer
from launch_ros.descriptions import ComposableNode


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('flag', default_value='{default}'),
        ComposableNodeContainer(
            name='container', namespace='', package='rclcpp_components',
            executable='component_container',
            composable_node_descriptions=[
                ComposableNode(package='image_proc', plugin='image_proc::RectifyNode', name='rectify',
                               extra_arguments=[{{'{name}': {value}}}]),
            ]),
    ])
"""

XML = """<launch>
  <arg name="flag" default="{default}"/>
  <node_container pkg="rclcpp_components" exec="component_container" name="container" namespace="">
    <composable_node pkg="image_proc" plugin="image_proc::RectifyNode" name="rectify">
      <extra_arg name="{name}" value="{value}"/>
    </composable_node>
  </node_container>
</launch>
"""


def _py(demo_findings: Any, code: str, value: str, name: str = "use_intra_process_comms",
        default: str = "true", distro: str = "humble") -> list[tuple[int, str]]:
    text = PY.format(name=name, value=value, default=default)
    return demo_findings({"launch/a.launch.py": text}, "launch/a.launch.py", code, distro)


def _xml(demo_findings: Any, code: str, value: str, name: str = "use_intra_process_comms",
         default: str = "true", distro: str = "humble") -> list[tuple[int, str]]:
    text = XML.format(name=name, value=value, default=default)
    return demo_findings({"launch/a.launch.xml": text}, "launch/a.launch.xml", code, distro)


@pytest.mark.parametrize(("value", "default", "shown"), [
    ("1", "true", "the integer 1"),
    ("'true'", "true", 'the string "true" (a Python string stays a string'),
    ("'True'", "true", 'the string "True"'),
    ("LaunchConfiguration('flag')", "1", 'the integer 1 (YAML of "1")'),
    ("LaunchConfiguration('flag')", "on", None),  # YAML 1.1 (PyYAML): "on" is true
    ("True", "true", None),
    ("LaunchConfiguration('flag')", "false", None),
    ("LaunchConfiguration('other')", "false", None),  # not known: silent
])
def test_python_values_are_typed_as_the_load_request_carries_them(demo_findings: Any, value: str, default: str,
                                                                  shown: str | None):
    found = _py(demo_findings, "S205", value, default=default)
    if shown is None:
        assert found == []
    else:
        assert len(found) == 1 and found[0][0] == 16, found
        assert shown in found[0][1] and "must be a boolean" in found[0][1]


@pytest.mark.parametrize(("value", "default", "bad"), [
    ("true", "x", False), ("True", "x", False), ("1", "x", True), ("$(var flag)", "0", True),
    ("$(var flag)", "false", False), ("enabled", "x", True),
])
def test_markup_values_are_typed_by_yaml(demo_findings: Any, value: str, default: str, bad: bool):
    found = _xml(demo_findings, "S205", value, default=default)
    assert (found != []) is bad, found
    if bad:
        assert found[0][0] == 5


def test_forward_global_arguments_is_checked_too(demo_findings: Any):
    found = _py(demo_findings, "S205", "'yes'", name="forward_global_arguments")
    assert len(found) == 1 and "forward_global_arguments" in found[0][1]


def test_kilted_reads_more_names_and_refuses_the_others(demo_findings: Any):
    assert _py(demo_findings, "S205", "1", name="enable_rosout", distro="kilted") != []
    assert _py(demo_findings, "S205", "1", name="enable_rosout", distro="humble") == []
    humble = _py(demo_findings, "S206", "True", name="enable_rosout", distro="humble")
    assert len(humble) == 1 and "ignores it" in humble[0][1]
    kilted = _py(demo_findings, "S206", "True", name="use_intra_process_comm", distro="kilted")
    assert len(kilted) == 1 and "is not supported" in kilted[0][1]
    assert 'did you mean "use_intra_process_comms"' in kilted[0][1]
    assert _py(demo_findings, "S206", "True", name="enable_rosout", distro="kilted") == []


def test_a_component_switched_off_is_not_reported(demo_findings: Any):
    text = PY.format(name="use_intra_process_comms", value="1", default="true").replace(
        "name='rectify',", "name='rectify', condition=IfCondition('false'),").replace(
        "ComposableNodeContainer(", "ComposableNodeContainer(condition=IfCondition('false'), ").replace(
        "from launch.actions import", "from launch.conditions import IfCondition\nfrom launch.actions import")
    assert demo_findings({"launch/a.launch.py": text}, "launch/a.launch.py", "S205") == []


def test_a_name_given_by_a_substitution_is_not_known(demo_findings: Any):
    assert _xml(demo_findings, "S206", "true", name="$(var flag)") == []


def test_python_names_by_substitution_and_nested_dicts(demo_findings: Any):
    assert _py(demo_findings, "S206", "True", name="x").__len__() == 1
    text = PY.format(name="use_intra_process_comms", value="True", default="true").replace(
        "{'use_intra_process_comms': True}", "{LaunchConfiguration('flag'): True}")
    assert demo_findings({"launch/a.launch.py": text}, "launch/a.launch.py", "S206") == []
    text = PY.format(name="use_intra_process_comms", value="True", default="true").replace(
        "{'use_intra_process_comms': True}", "{'use': {'intra_process_comms': True}}")
    (found,) = demo_findings({"launch/a.launch.py": text}, "launch/a.launch.py", "S206")
    assert 'extra argument "use.intra_process_comms"' in found[1]
