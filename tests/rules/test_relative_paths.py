"""A relative path launch opens (a parameter file, an included launch file) is resolved against the
directory ``ros2 launch`` is started in (open(), SourceFileLoader, rcl), which the linter cannot
know: it is reported the same way whatever directory the linter runs in."""
from __future__ import annotations

import os
from pathlib import Path
from typing import Any

import pytest

PARAMS = """from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package="demo_nodes_cpp", executable="talker", parameters=["config/params.yaml"]),
    ])
"""

INCLUDE = """<launch>
  <include file="launch/b.launch.xml"/>
</launch>
"""


@pytest.mark.parametrize("inside", [False, True])
def test_a_relative_path_is_reported_from_any_working_directory(demo_findings: Any, tmp_path: Path,
                                                                   monkeypatch: Any, inside: bool):
    files = {"launch/a.launch.py": PARAMS, "config/params.yaml": "talker:\n  ros__parameters:\n    a: 1\n",
             "launch/c.launch.xml": INCLUDE, "launch/b.launch.xml": "<launch/>\n"}
    if inside:  # where the relative paths do name the files
        (tmp_path / "src" / "demo").mkdir(parents=True)
        monkeypatch.chdir(tmp_path / "src" / "demo")
    ((line, message),) = demo_findings(files, "launch/a.launch.py", "P101")
    assert line == 7 and 'parameter file path "config/params.yaml" is relative' in message, os.getcwd()
    ((line, message),) = demo_findings(files, "launch/c.launch.xml", "L105")
    assert line == 2 and 'included launch file "launch/b.launch.xml" is relative' in message
