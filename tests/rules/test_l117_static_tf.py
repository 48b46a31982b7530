"""L117's mirror of tf2_ros ``static_transform_broadcaster_program.cpp :: parse_args``."""
from __future__ import annotations

import pytest

from physai_lint.checks.programs import static_tf_problem


@pytest.mark.parametrize("line", [
    "--frame-id map --child-frame-id odom",
    "--x 1 --y 2 --z 3 --roll 0.1 --pitch 0 --yaw 1.57 --frame-id a --child-frame-id b",
    "--qx 0 --qy 0 --qz 0.7071 --qw 0.7071 --frame-id a --child-frame-id b",
    "0 0 0 0 0 0 a b",  # old form, Euler angles
    "0 0 0 0 0 0 1 a b",  # old form, quaternion
    "0 0 0 0 0 0 a b --yaw 1",  # Euler flags do not count against the old form
    "--x 1.5m --frame-id a --child-frame-id b",  # std::stod reads a number's prefix
    "--help",
])
def test_accepted(line: str) -> None:
    assert static_tf_problem(line.split()) is None


@pytest.mark.parametrize(("line", "message", "index"), [
    ("--frame_id a --child_frame_id b", "Extra unparsed arguments on command-line", 0),
    ("0 0 0 0 0 0 a", "Extra unparsed arguments on command-line", 0),
    ("0 0 0 0 0 0 --frame-id a --child-frame-id b", "Extra unparsed arguments on command-line", 0),
    ("0 0 0 0 0 0 a b --frame-id c", "Cannot specify both new-style (flags) and old-style (arguments)", 0),
    ("--roll 1 --qw 1 --frame-id a --child-frame-id b", "Cannot specify both quaternion and Euler rotations", None),
    ("--x left --frame-id a --child-frame-id b", "Failed to parse --x argument as float", 1),
    ("0 0 zero 0 0 0 a b", "Failed to parse z argument as float", 2),
    ("--frame-id a --child-frame-id", "Not enough arguments for --child-frame-id", 2),
    ("--x 1", "Frame id must not be empty", None),
    ("--frame-id a", "Child frame id must not be empty", None),
])
def test_refused(line: str, message: str, index: int | None) -> None:
    found = static_tf_problem(line.split())
    assert found is not None and found[:2] == (message, index)


def test_quotes_and_one_string_arguments(demo_findings) -> None:
    launch = """from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='tf2_ros', executable='static_transform_publisher',
             arguments=['0 0 0 0 0 0 map odom']),
        Node(package='tf2_ros', executable='static_transform_publisher',
             arguments=['--x', 'one', '--frame-id', 'map', '--child-frame-id', 'odom']),
    ])
"""
    xml = """<launch>
  <node pkg="tf2_ros" exec="static_transform_publisher" args="--x '-0.5' --frame-id map --child-frame-id odom"/>
</launch>
"""
    found = demo_findings({"launch/a.launch.py": launch}, "launch/a.launch.py", "L117")
    assert [(line, "is one argument" in m or '"one" is not a number' in m) for line, m in found] == \
        [(8, True), (10, True)]
    # launch splits XML args with shlex: a quoted word is not known here as it is there
    assert demo_findings({"launch/a.launch.xml": xml}, "launch/a.launch.xml", "L117") == []
