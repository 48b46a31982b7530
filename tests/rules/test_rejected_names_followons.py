"""A node launch_ros refuses (an invalid name or namespace: Node._perform_substitutions raises and
the launch ends) has no topics, services or parameter file matches: N102/N103 report it, and the
graph and P103 leave it out instead of describing a node that never exists."""
from __future__ import annotations

from typing import Any

LAUNCH = """from launch import LaunchDescription
from launch.actions import GroupAction
from launch_ros.actions import Node, PushRosNamespace


def generate_launch_description():
    return LaunchDescription([
        GroupAction([
            PushRosNamespace('{ns}'),
            Node(package='demo_nodes_cpp', executable='talker', name='{name}',
                 parameters=[__file__.replace('launch/a.launch.py', 'config/p.yaml')]),
        ]),
    ])
"""


def _codes(demo_findings: Any, ns: str, name: str, code: str) -> list[tuple[int, str]]:
    files = {"launch/a.launch.py": LAUNCH.format(ns=ns, name=name),
             "config/p.yaml": "/**/other:\n  ros__parameters:\n    a: 1\n"}
    return demo_findings(files, "launch/a.launch.py", code)


def test_invalid_names_are_reported_without_follow_ons(demo_findings: Any):
    assert _codes(demo_findings, "robot-1", "talker", "N103") != []
    assert _codes(demo_findings, "robot_1", "robot_1/talker", "N102") != []
    for ns, name in (("robot-1", "talker"), ("robot_1", "robot_1/talker")):
        assert _codes(demo_findings, ns, name, "P103") == []
        assert _codes(demo_findings, ns, name, "T202") == []


def test_the_names_a_refused_node_s_code_uses_are_still_checked(tmp_path: Any, demo_package: Any):
    from physai_lint.engine import CheckOptions, run_check

    launch = """from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([Node(package='demo', executable='bridge', name='arm/bridge')])
"""
    pkg = demo_package({"launch/a.launch.py": launch, "CMakeLists.txt":
                        "project(demo)\nadd_executable(bridge src/b.cpp)\n"
                        "install(TARGETS bridge DESTINATION lib/${PROJECT_NAME})\n"
                        "install(DIRECTORY launch DESTINATION share/${PROJECT_NAME})\n", "src/b.cpp": ""})
    (tmp_path / "interfaces.yaml").write_text("demo/bridge:\n  subscribers: [imu/9dof]\n")
    opts = CheckOptions(paths=[str(pkg / "launch/a.launch.py")], workspace=str(tmp_path), cache=False,
                        interfaces=[str(tmp_path / "interfaces.yaml")])
    codes = {f.code for f in run_check(opts).findings}
    assert {"N102", "N104"} <= codes and "T201" not in codes, codes
