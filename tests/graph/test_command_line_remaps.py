"""Remap rules on a node's command line: ``ros_arguments=['-r', 'a:=b']``, ``arguments=['--ros-args',
'--remap', 'a:=b']`` and XML ``ros_args="-r a:=b"``. launch_ros puts them before its own
``--ros-args`` section (SEMANTICS §3) and rcl applies the first rule that matches, so they rename
topics in the graph, win over SetRemap and remappings=, and rcl refuses one it cannot parse (a
relative ``__ns:=``), which stops the node. Outside a ``--ros-args`` section a bare ``a:=b`` is the
deprecated form rcl still reads; a flag's value (``--log-level x:=warn``) is no rule."""
from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest

from physai_lint.engine import CheckOptions, run_check
from physai_lint.resolve.nodes import command_line_rules

INTERFACES = """demo/filter:
  publishers: [{name: scan_filtered, type: sensor_msgs/msg/LaserScan}]
demo/consumer:
  subscribers: [{name: scan_clean, type: sensor_msgs/msg/LaserScan}]
"""
PY = """from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='demo', executable='filter', name='filter', {how}),
        Node(package='demo', executable='consumer', name='consumer'),
    ])
"""


def _findings(tmp_path: Path, demo_nodes: Any, files: dict[str, str], entry: str) -> list[tuple[str, int, str]]:
    pkg = demo_nodes({"filter": "", "consumer": ""}, files)
    (tmp_path / "interfaces.yaml").write_text(INTERFACES)
    opts = CheckOptions(paths=[str(pkg / entry)], workspace=str(tmp_path), cache=False,
                        interfaces=[str(tmp_path / "interfaces.yaml")])
    return sorted((f.code, f.span.line, f.message) for f in run_check(opts).findings)


@pytest.mark.parametrize("how", [
    "ros_arguments=['-r', 'scan_filtered:=scan_clean']",
    "ros_arguments=['--log-level', 'warn', '--remap', 'scan_filtered:=scan_clean']",
    "arguments=['--ros-args', '-r', 'scan_filtered:=scan_clean']",
    "arguments=['scan_filtered:=scan_clean']",  # the deprecated form, outside --ros-args
])
def test_a_command_line_rule_renames_the_topic(tmp_path: Path, demo_nodes: Any, how: str) -> None:
    found = _findings(tmp_path, demo_nodes, {"launch/a.launch.py": PY.format(how=how)}, "launch/a.launch.py")
    assert [f for f in found if f[0] in ("T201", "T202")] == []


def test_without_the_rule_the_topics_do_not_meet(tmp_path: Path, demo_nodes: Any) -> None:
    found = _findings(tmp_path, demo_nodes, {"launch/a.launch.py": PY.format(how="arguments=['--ros-args', "
                                                                               "'--log-level', 'x:=warn']")},
                      "launch/a.launch.py")
    assert [f[0] for f in found if f[0] in ("T201", "T202")] == ["T201"]  # T202: near misses only


def test_a_command_line_rule_wins_over_remappings(tmp_path: Path, demo_nodes: Any) -> None:
    how = "ros_arguments=['-r', 'scan_filtered:=scan_clean'], remappings=[('scan_filtered', 'other')]"
    found = _findings(tmp_path, demo_nodes, {"launch/a.launch.py": PY.format(how=how)}, "launch/a.launch.py")
    assert [f for f in found if f[0] in ("T201", "T202")] == []
    assert [(f[0], f[1]) for f in found if f[0] == "T102"] == [("T102", 7)]


XML = """<launch>
  <node pkg="demo" exec="filter" name="front" ros_args="-r __ns:=robot1 -r scan:=front/scan"/>
  <node pkg="demo" exec="filter" name="back" ros_args="--remap cloud_in:=/velodyne/3d_points"/>
  <node pkg="demo" exec="filter" name="ok" ros_args="-r __ns:=/robot2 -r __node:=renamed"/>
  <node pkg="demo" exec="filter" name="outside" args="cloud:=3d use_sim_time:=true"/>
</launch>
"""


def test_rcl_refuses_a_relative_namespace_and_a_bad_token(tmp_path: Path, demo_nodes: Any) -> None:
    found = _findings(tmp_path, demo_nodes, {"launch/a.launch.xml": XML}, "launch/a.launch.xml")
    assert [(line, msg) for code, line, msg in found if code == "N105"] == [
        (2, 'remap rule "__ns:=robot1" is invalid: "robot1" is not a fully qualified namespace (it must '
            'start with "/"); rcl cannot parse it, so the node fails to start'),
        (3, 'remap to name "/velodyne/3d_points" is invalid: topic name token "3d_points" must not start '
            "with a digit"),
    ]


def test_node_and_namespace_rules_rename_the_node(demo_graph: Any) -> None:
    nodes = demo_graph({"launch/a.launch.xml": XML}, "launch/a.launch.xml")
    assert nodes["renamed"]["fqn"] == "/robot2/renamed"


def test_the_parse_follows_rcl() -> None:
    def rules(arguments: list[Any], ros_arguments: list[Any]) -> list[tuple[Any, bool]]:
        pairs = lambda xs: [(x, None) for x in xs]  # noqa: E731
        return [(t, inside) for t, _, inside in command_line_rules(pairs(arguments), pairs(ros_arguments))]

    assert rules(["-d", "x.rviz", "a:=b", "--ros-args", "-p", "p:=1", "-r", "c:=d", "--", "e:=f"], []) == [
        ("a:=b", False), ("c:=d", True), ("e:=f", False)]
    assert rules([], ["--params-file", "x:=y.yaml", "--remap", "g:=h", "i:=j"]) == [("g:=h", True)]
    # an unknown argument where a flag would be may be -r: the rule after it may count
    assert rules([], [None, "k:=l"]) == [("k:=l", True)]
    assert rules([], ["-r", None]) == [(None, True)]


PREFIXED = """from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='demo', executable='filter', name='announcer',
             arguments=['--ros-args', '-r', 'filter:scan_filtered:=scan_clean']),
        Node(package='demo', executable='filter', name='second',
             remappings=[('second:scan_filtered', 'scan_clean'), ('other:x', 'y')]),
        Node(package='demo', executable='filter',
             arguments=['--ros-args', '-r', 'helper:scan_filtered:=scan_clean']),
    ])
"""


def test_prefixed_rule_for_another_node_name_never_applies(tmp_path: Path, demo_nodes: Any) -> None:
    # rcl_remap_first_match compares the prefix with the node's final name, and name= renames
    # every node of the process (-r __node:=announcer): "filter:" matches none there. A node
    # launch does not name may hold others (a manual composition): its prefixes are left alone.
    found = [(line, msg) for code, line, msg in
             _findings(tmp_path, demo_nodes, {"launch/p.launch.py": PREFIXED}, "launch/p.launch.py")
             if code == "T102"]
    assert [line for line, _ in found] == [8, 10]
    assert found[0][1].startswith('remap "filter:scan_filtered" -> "scan_clean" never applies: it is only '
                                  'for a node named "filter", and this node is named "announcer"')
    assert '"other:x" -> "y" never applies' in found[1][1]
