"""A component loaded with extra_arguments forward_global_arguments: true reads its container's
command line: rclcpp_components sets NodeOptions.use_global_arguments from it
(component_manager.cpp :: create_node_options), and rclcpp resolves those global arguments (the
container's --params-file, read by rcl with wildcard keys) before the load request's parameter
overrides (resolve_parameter_overrides). Without it the container's file does not reach the
component."""
from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest

from physai_lint.engine import CheckOptions, run_check

INTERFACES = """demo/demo::Camera:
  parameters:
    rate: {type: double, default: 30.0}
"""
LAUNCH = """from launch import LaunchDescription
from launch.substitutions import PathJoinSubstitution
from launch_ros.actions import ComposableNodeContainer
from launch_ros.descriptions import ComposableNode
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    params = PathJoinSubstitution([FindPackageShare('demo'), 'config', 'cam.yaml'])
    return LaunchDescription([
        ComposableNodeContainer(
            name='container', namespace='front', package='rclcpp_components',
            executable='component_container', parameters=[params],
            composable_node_descriptions=[
                ComposableNode(package='demo', plugin='demo::Camera', name='camera',
                               namespace='front'{extra}),
            ]),
    ])
"""
FORWARD = ", extra_arguments=[{'forward_global_arguments': True}]"


def _codes(tmp_path: Path, demo_package: Any, extra: str, params: str) -> list[tuple[str, int]]:
    pkg = demo_package({"launch/a.launch.py": LAUNCH.format(extra=extra), "config/cam.yaml": params})
    (tmp_path / "interfaces.yaml").write_text(INTERFACES)
    opts = CheckOptions(paths=[str(pkg / "launch/a.launch.py")], workspace=str(tmp_path), cache=False,
                        interfaces=[str(tmp_path / "interfaces.yaml")])
    return sorted((f.code, f.span.line) for f in run_check(opts).findings if f.code.startswith("P"))


@pytest.mark.parametrize("key", ["/front/camera", "/**/camera", "front/*"])
def test_the_container_file_reaches_a_forwarding_component(tmp_path: Path, demo_package: Any,
                                                           key: str) -> None:
    # rcl matches the keys, wildcards included (launch_ros alone honours only "/**" and exact keys)
    params = f"{key}:\n  ros__parameters:\n    rate: 30\n"
    assert _codes(tmp_path, demo_package, FORWARD, params) == [("P105", 3)]


def test_without_forwarding_the_container_file_does_not_reach_it(tmp_path: Path,
                                                                  demo_package: Any) -> None:
    params = "/front/camera:\n  ros__parameters:\n    rate: 30\n"
    assert _codes(tmp_path, demo_package, "", params) == [("P103", 1)]


def test_the_load_request_overrides_the_forwarded_value(tmp_path: Path, demo_package: Any) -> None:
    launch_extra = FORWARD + ", parameters=[{'rate': 15.0}]"
    params = "/front/camera:\n  ros__parameters:\n    rate: 30\n"
    assert _codes(tmp_path, demo_package, launch_extra, params) == []
