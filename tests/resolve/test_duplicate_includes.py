"""N101 when one line launches a node twice because its file is included twice: the message
names the includes, which are what differ, not the node's own line twice."""
from __future__ import annotations

NODES = """<launch>
  <node pkg="demo_nodes_cpp" exec="talker" name="talker"/>
</launch>
"""
MAIN = """<launch>
  <include file="$(find-pkg-share demo)/launch/nodes.launch.xml"/>
  <group>
    <include file="$(find-pkg-share demo)/launch/nodes.launch.xml"/>
  </group>
</launch>
"""


def test_a_file_included_twice_names_both_includes(tmp_path, demo_package):
    from physai_lint.engine import CheckOptions, run_check

    pkg = demo_package({"launch/nodes.launch.xml": NODES, "launch/main.launch.xml": MAIN})
    report = run_check(CheckOptions(paths=[str(pkg / "launch/main.launch.xml")], workspace=str(tmp_path),
                                    cache=False))
    (f,) = [f for f in report.findings if f.code == "N101"]
    assert f.message.startswith('node "/talker" is launched twice: ')
    assert "nodes.launch.xml is included 2 times in the same namespace" in f.message
    assert [(r.span.file.rsplit("/", 1)[-1], r.span.line, r.message) for r in f.related] == [
        ("main.launch.xml", 2, "included here"), ("main.launch.xml", 4, "included here")]


LOOP = """from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    ld = LaunchDescription()
    for i in range(3):
        ld.add_action(Node(package='demo_nodes_cpp', executable='talker', name='talker'))
    return ld
"""
ONE = """<launch>
  <arg name="robot" default="r0"/>
  <node pkg="demo_nodes_cpp" exec="talker" name="talker"/>
</launch>
"""
INCLUDE_LOOP = """from launch import LaunchDescription
from launch.actions import IncludeLaunchDescription
from launch.launch_description_sources import AnyLaunchDescriptionSource
from launch.substitutions import PathJoinSubstitution
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    ld = LaunchDescription()
    for i in range(3):
        ld.add_action(IncludeLaunchDescription(
            AnyLaunchDescriptionSource(
                PathJoinSubstitution([FindPackageShare('demo'), 'launch', 'one.launch.xml'])),
            launch_arguments={'robot': 'r' + str(i)}.items()))
    return ld
"""


def _n101(tmp_path, demo_package, files, entry):
    from physai_lint.engine import CheckOptions, run_check

    pkg = demo_package(files)
    report = run_check(CheckOptions(paths=[str(pkg / "launch" / entry)], workspace=str(tmp_path), cache=False))
    return [f for f in report.findings if f.code == "N101"]


def test_a_node_in_a_loop_says_how_often_one_action_launches_it(tmp_path, demo_package):
    (f,) = _n101(tmp_path, demo_package, {"launch/loop.launch.py": LOOP}, "loop.launch.py")
    assert f.message.startswith('node "/talker" is launched 3 times by this one action (in a loop')
    assert "also at line" not in f.message and f.related == ()
    assert "name=f'talker_{i}'" in f.help


def test_a_file_included_in_a_loop_points_at_the_include(tmp_path, demo_package):
    (f,) = _n101(tmp_path, demo_package, {"launch/one.launch.xml": ONE, "launch/main.launch.py": INCLUDE_LOOP},
                 "main.launch.py")
    assert f.message.startswith('node "/talker" is launched 3 times: ')
    assert "one.launch.xml is included 3 times through one include" in f.message
    assert [(r.span.file.rsplit("/", 1)[-1], r.span.line, r.message) for r in f.related] == [
        ("main.launch.py", 11, "included here")]
