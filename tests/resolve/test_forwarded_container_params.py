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
CAMERA = "package='demo', plugin='demo::Camera', name='camera', namespace='front'"
FORWARD = ", extra_arguments=[{'forward_global_arguments': True}]"


def _codes(tmp_path: Path, demo_package: Any, component_launch: Any, extra: str, params: str
           ) -> list[tuple[str, int]]:
    launch = component_launch(CAMERA + extra, namespace="front", container=", parameters=[params]")
    pkg = demo_package({"launch/a.launch.py": launch, "config/cam.yaml": params})
    (tmp_path / "interfaces.yaml").write_text(INTERFACES)
    opts = CheckOptions(paths=[str(pkg / "launch/a.launch.py")], workspace=str(tmp_path), cache=False,
                        interfaces=[str(tmp_path / "interfaces.yaml")])
    return sorted((f.code, f.span.line) for f in run_check(opts).findings if f.code.startswith("P"))


@pytest.mark.parametrize("key", ["/front/camera", "/**/camera", "front/*"])
def test_the_container_file_reaches_a_forwarding_component(tmp_path: Path, demo_package: Any,
                                                           component_launch: Any,
                                                           key: str) -> None:
    # rcl matches the keys, wildcards included (launch_ros alone honours only "/**" and exact keys)
    params = f"{key}:\n  ros__parameters:\n    rate: 30\n"
    assert _codes(tmp_path, demo_package, component_launch, FORWARD, params) == [("P105", 3)]


def test_without_forwarding_the_container_file_does_not_reach_it(tmp_path: Path, demo_package: Any,
                                                                  component_launch: Any) -> None:
    params = "/front/camera:\n  ros__parameters:\n    rate: 30\n"
    assert _codes(tmp_path, demo_package, component_launch, "", params) == [("P103", 1)]


def test_the_load_request_overrides_the_forwarded_value(tmp_path: Path, demo_package: Any,
                                                        component_launch: Any) -> None:
    launch_extra = FORWARD + ", parameters=[{'rate': 15.0}]"
    params = "/front/camera:\n  ros__parameters:\n    rate: 30\n"
    assert _codes(tmp_path, demo_package, component_launch, launch_extra, params) == []
