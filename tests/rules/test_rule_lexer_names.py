"""Names rmw accepts but rcl cannot read in the ``-r`` rules launch hands them in (rcl lexer.c:
a repeated "_" ends a name part, "{" is no lexeme; arguments.c: "Couldn't parse remap rule"):
node names (``-r __node:=``), namespaces (``-r __ns:=``) and remap rules."""
from __future__ import annotations

from typing import Any

import pytest

from physai_lint.resolve.names import rule_lex_problem

LAUNCH = """from launch import LaunchDescription
from launch.actions import GroupAction
from launch_ros.actions import Node, PushRosNamespace


def generate_launch_description():
    return LaunchDescription([
        {action},
    ])
"""


@pytest.mark.parametrize(("name", "ok"), [
    ("cmd_vel", True), ("~/cmd_vel", True), ("/robot_1_/scan", True), ("_hidden", True), ("a_", True),
    ("_", True), ("lidar2_points", True),
    # test_lexer.cpp: "a__bcd" lexes as "a_" then "_bcd"; "__a" is no lexeme
    ("a__bcd", False), ("/front__points", False), ("a___b", False), ("{node}/status", False),
])
def test_the_lexer_model(name: str, ok: bool):
    assert (rule_lex_problem(name) is None) is ok


@pytest.mark.parametrize(("action", "code", "says"), [
    ("Node(package='demo_nodes_cpp', executable='talker', name='rover1__camera')", "N102",
     'launch passes it to rcl as the rule "__node:=rover1__camera"'),
    ("Node(package='demo_nodes_cpp', executable='talker', namespace='front__lidar')", "N103",
     'launch passes it to rcl as the rule "__ns:=/front__lidar"'),
    ("GroupAction([PushRosNamespace('front__lidar'), Node(package='demo_nodes_cpp', executable='talker')])",
     "N103", 'pushed namespace "front__lidar"'),
    ("Node(package='demo_nodes_cpp', executable='talker', remappings=[('chatter', 'front__points')])", "N105",
     '"front__points" has a repeated "_"'),
    ("Node(package='demo_nodes_cpp', executable='talker', remappings=[('chatter', '{node}/status')])", "N105",
     "holds a substitution"),
])
def test_names_the_rule_lexer_cannot_read(demo_findings: Any, action: str, code: str, says: str):
    files = {"launch/a.launch.py": LAUNCH.format(action=action)}
    found = demo_findings(files, "launch/a.launch.py", code)
    assert len(found) == 1 and found[0][0] == 8 and says in found[0][1], found
    assert demo_findings(files, "launch/a.launch.py", "N106") == []


def test_a_trailing_underscore_stays_a_style_note(demo_findings: Any):
    action = "Node(package='demo_nodes_cpp', executable='talker', name='scan_maker_')"
    files = {"launch/a.launch.py": LAUNCH.format(action=action)}
    assert demo_findings(files, "launch/a.launch.py", "N102") == []
    assert len(demo_findings(files, "launch/a.launch.py", "N106")) == 1
