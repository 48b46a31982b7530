"""A process action's ``on_exit=``: launch registers ``OnProcessExit(target_action=self,
on_exit=...)`` when the process starts (``ExecuteLocal.execute``), so what it holds is launched
and checked like the actions of an event handler; in XML/YAML only ``on_exit="shutdown"`` exists,
and only from jazzy on (humble's ``ExecuteProcess.parse`` does not read it)."""
from __future__ import annotations

from pathlib import Path

from physai_lint.api_plan import compute_plan
from physai_lint.engine import CheckOptions, run_check

LAUNCH = """
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, LogInfo
from launch.conditions import IfCondition
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def restart(event, context):
    return [Node(package='demo_nodes_cpp', executable='talker', name='from_function')]


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('with_driver', default_value='true'),
        Node(package='demo_nodes_cpp', executable='talker', name='driver',
             condition=IfCondition(LaunchConfiguration('with_driver')),
             on_exit=[LogInfo(msg=LaunchConfiguration('exit_message')),
                      Node(package='demo_nodes_cpp', executable='listener', name='after_driver')]),
        Node(package='demo_nodes_cpp', executable='talker', name='watched', on_exit=restart),
    ])
"""


def test_on_exit_actions_are_launched_after_the_process(demo_graph):
    nodes = demo_graph({"launch/a.launch.py": LAUNCH}, "launch/a.launch.py")
    assert nodes["after_driver"]["active"] is True
    assert nodes["from_function"]["active"] is True


def test_on_exit_actions_follow_their_process_condition(demo_graph):
    nodes = demo_graph({"launch/a.launch.py": LAUNCH}, "launch/a.launch.py", with_driver="false")
    assert nodes["driver"]["active"] is False
    assert nodes["after_driver"]["active"] is False
    assert nodes["from_function"]["active"] is True


def test_on_exit_actions_are_checked(demo_findings):
    found = demo_findings({"launch/a.launch.py": LAUNCH}, "launch/a.launch.py", "L101")
    assert [(line, '"exit_message"' in msg) for line, msg in found] == [(18, True)]


def test_on_exit_waits_for_the_process_in_the_plan(tmp_path: Path, demo_package) -> None:
    demo_package({"launch/a.launch.py": LAUNCH})
    plan, _ = compute_plan(CheckOptions(paths=[], workspace=str(tmp_path)), "src/demo/launch/a.launch.py",
                           cwd=str(tmp_path))
    edges = {(plan.labels[e.before], plan.labels[e.after], e.reason) for e in plan.edges}
    assert any(b == "/driver" and a == "/after_driver" and "exit" in r.lower() for b, a, r in edges), edges
    assert any(b == "/watched" and a == "/from_function" for b, a, _ in edges), edges


XML = """<launch>
  <node pkg="demo_nodes_cpp" exec="talker" name="a" on_exit="shutdown" emulate_tty="true"/>
  <executable cmd="sleep 1" on_exit="restart"/>
</launch>
"""
YAML = """launch:
- node:
    pkg: demo_nodes_cpp
    exec: talker
    sigterm_timeout: 5.0
    on_exit: respawn
"""


def _codes(tmp_path: Path, demo_package, distro: str) -> list[tuple[str, int, str]]:
    pkg = demo_package({"launch/a.launch.xml": XML, "launch/b.launch.yaml": YAML})
    opts = CheckOptions(paths=[str(pkg / "launch")], workspace=str(tmp_path), distro=distro, cache=False)
    return sorted((f.code, f.span.line, f.message.split(";")[0]) for f in run_check(opts).findings
                  if f.code in ("L002", "L010"))


def test_markup_process_attributes_newer_than_humble_are_unknown_there(tmp_path: Path, demo_package) -> None:
    found = [(c, line, m) for c, line, m in _codes(tmp_path, demo_package, "humble") if c == "L002"]
    assert found == [
        ("L002", 2, 'attribute "emulate_tty" on "node" does not exist in humble (launch reads it from jazzy on)'),
        ("L002", 2, 'attribute "on_exit" on "node" does not exist in humble (launch reads it from jazzy on)'),
        ("L002", 3, 'attribute "on_exit" on "executable" does not exist in humble (launch reads it from jazzy on)'),
        ("L002", 5, 'key "sigterm_timeout" on "node" does not exist in humble (launch reads it from jazzy on)'),
        ("L002", 6, 'key "on_exit" on "node" does not exist in humble (launch reads it from jazzy on)'),
    ]


def test_markup_on_exit_other_than_shutdown_fails(tmp_path: Path, demo_package) -> None:
    assert _codes(tmp_path, demo_package, "jazzy") == [
        ("L010", 3, '"on_exit" of "executable" is "restart"'),
        ("L010", 6, '"on_exit" of "node" is "respawn"'),
    ]


def test_markup_on_exit_shutdown_is_a_handler_of_the_process(tmp_path: Path, demo_package) -> None:
    from physai_lint.frontends.xml_launch import parse_xml_launch
    from physai_lint.model import launch as L

    actions = parse_xml_launch("a.launch.xml", XML).launch.actions
    node, handler = actions[0], actions[1]
    assert isinstance(node, L.NodeAction) and isinstance(handler, L.EventHandler)
    assert (handler.event, handler.target_id, handler.target_known) == ("on_process_exit", node.id, True)
    assert [type(a) for a in handler.actions] == [L.Shutdown]
    assert not any(isinstance(a, L.EventHandler) for a in actions[2:])  # "restart" makes none


def test_an_on_exit_callable_that_cannot_be_followed_leaves_the_launch_known(tmp_path: Path, demo_package) -> None:
    """A library's function given as on_exit stays out of the model, as before, instead of making
    an unknown part that turns off the rules that need the whole launch (S201, ...)."""
    from physai_lint.engine import build_project

    launch = ("from launch import LaunchDescription\nfrom launch_ros.actions import Node\n"
              "from my_helpers import restart\n\n\n"
              "def generate_launch_description():\n"
              "    return LaunchDescription([Node(package='demo_nodes_cpp', executable='talker', name='a',"
              " on_exit=restart)])\n")
    pkg = demo_package({"launch/c.launch.py": launch})
    project = build_project(CheckOptions(paths=[str(pkg / "launch/c.launch.py")], workspace=str(tmp_path),
                                         cache=False))
    assert [r.opaque for r in project.launches] == [[]]
