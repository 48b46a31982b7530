"""A branch that the evaluation never takes (a ROS_DISTRO guard for Dashing-era code) never runs
under this launch: its calls and names are not judged. An undecided test still judges both."""
from __future__ import annotations

LAUNCH = """import os
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    TEST
        node = Node(package='demo_nodes_cpp', node_executable='talker', node_name='t')
        undefined_helper()
    else:
        node = Node(package='demo_nodes_cpp', executable='talker', name='t')
    return LaunchDescription([node])
"""


def _codes(demo_findings, test: str) -> list[tuple[str, int]]:
    files = {"launch/a.launch.py": LAUNCH.replace("TEST", test)}
    return [(code, line) for code in ("L001", "L005") for line, _ in demo_findings(files, "launch/a.launch.py", code)]


def test_a_branch_the_distro_rules_out_is_not_judged(demo_findings):
    # sick_scan_xd: launch runs with ROS_DISTRO set, and "h" <= "e" is false
    assert _codes(demo_findings, "if os.environ.get('ROS_DISTRO')[0] <= 'e':") == []


def test_an_undecided_branch_is_judged(demo_findings):
    assert _codes(demo_findings, "if os.environ.get('LEGACY'):") == [("L001", 8), ("L001", 8), ("L005", 9)]
