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


FALLBACK = """from launch import LaunchDescription
from launch_ros.actions import Node


def _talker():
    try:
        return Node(package='demo_nodes_cpp', executable='talker', name='t')
    except CAUGHT:
        return Node(package='demo_nodes_cpp', node_executable='talker', node_name='t')


def generate_launch_description():
    return LaunchDescription([_talker()])
"""


def test_the_fallback_for_another_distros_api_is_not_judged(demo_findings):
    # rosbridge_suite: the except TypeError branch is for distros before Foxy's keyword arguments
    for caught in ("TypeError", "(TypeError, AttributeError)"):
        files = {"launch/a.launch.py": FALLBACK.replace("CAUGHT", caught)}
        assert demo_findings(files, "launch/a.launch.py", "L001") == []


def test_handlers_of_other_errors_or_after_a_raise_are_judged(demo_findings):
    files = {"launch/a.launch.py": FALLBACK.replace("CAUGHT", "Exception")}
    assert len(demo_findings(files, "launch/a.launch.py", "L001")) == 2
    raising = FALLBACK.replace("CAUGHT", "TypeError").replace(
        "        return Node(package='demo_nodes_cpp', executable='talker', name='t')",
        "        raise TypeError('old distro')")
    assert len(demo_findings({"launch/a.launch.py": raising}, "launch/a.launch.py", "L001")) == 2


MODULE_BLOCK = """import launch
from launch_ros.actions import Node

BLOCK
"""


def test_an_entry_point_defined_in_a_module_level_block_is_the_files(demo_findings):
    # launch asks hasattr(module, 'generate_launch_description'), wherever the def stands
    for block in ("if True:\n    def generate_launch_description():\n"
                  "        return launch.LaunchDescription([Node(package='demo_nodes_cpp', executable='talker', name='t-1')])",
                  "try:\n    import yaml  # noqa: F401\n\n    def generate_launch_description():\n"
                  "        return launch.LaunchDescription([Node(package='demo_nodes_cpp', executable='talker', name='t-1')])\n"
                  "except ImportError:\n    def generate_launch_description():\n"
                  "        return launch.LaunchDescription([])"):
        files = {"launch/a.launch.py": MODULE_BLOCK.replace("BLOCK", block)}
        assert demo_findings(files, "launch/a.launch.py", "L006") == []
        assert [m.split(" is ")[0] for _, m in demo_findings(files, "launch/a.launch.py", "N102")] == \
            ['node name "t-1"']
