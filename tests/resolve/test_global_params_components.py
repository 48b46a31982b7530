"""A SetParameter reaches a process as ``-p name:=str(value)``, which rcl types again (a list is its
Python repr, a string), but a composable node gets the evaluated value itself: launch_ros
normalizes it (``get_composable_node_load_request`` -> ``normalize_parameter_dict``), so a list
stays a list (SEMANTICS §4a)."""
from __future__ import annotations

from pathlib import Path
from typing import Any

from physai_lint.engine import CheckOptions, run_check

INTERFACES = """demo/demo::Camera:
  parameters:
    streams: {type: string_array, default: [color]}
    ratios: {type: double_array, default: [1.0]}
demo/camera:
  parameters:
    streams: {type: string_array, default: [color]}
"""
LAUNCH = """from launch import LaunchDescription
from launch_ros.actions import ComposableNodeContainer, Node, SetParameter
from launch_ros.descriptions import ComposableNode


def generate_launch_description():
    return LaunchDescription([
        SetParameter(name='streams', value=['color', 'depth']),
        SetParameter(name='ratios', value=[1, 2.5]),
        ComposableNodeContainer(
            name='container', namespace='', package='rclcpp_components',
            executable='component_container',
            composable_node_descriptions=[
                ComposableNode(package='demo', plugin='demo::Camera', name='cam'),
            ]),
        Node(package='demo', executable='camera', name='plain'),
    ])
"""


def test_a_set_parameter_list_is_a_list_for_a_component_only(tmp_path: Path, demo_nodes: Any) -> None:
    pkg = demo_nodes({"camera": ""}, {"launch/a.launch.py": LAUNCH})
    (tmp_path / "interfaces.yaml").write_text(INTERFACES)
    opts = CheckOptions(paths=[str(pkg / "launch/a.launch.py")], workspace=str(tmp_path),
                        cache=False, interfaces=[str(tmp_path / "interfaces.yaml")])
    found = [(f.span.line, f.message.split(" is declared")[0])
             for f in run_check(opts).findings if f.code == "P105"]
    assert found == [(8, 'parameter "streams" of /plain')]
