"""What a file is from its text (physai_lint/sniff.py): the frontend ros2 launch would load it with,
and ROS 2 against ROS 1 (roslaunch) markup."""
from __future__ import annotations

import pytest

from physai_lint.sniff import Generation, classify, generation, launch_format, xml_root


@pytest.mark.parametrize("path, text, fmt", [
    ("a.launch.py", "<launch/>", "python"),  # the extension decides, whatever the text
    ("a.LAUNCH.XML", "x = 1", "xml"),
    ("a.yml", "", "yaml"),
    ("a.launch", "\ufeff  <?xml version='1.0'?>\n<launch/>", "xml"),
    ("a.launch", "# comment\nlaunch:\n- log: {message: hi}\n", "yaml"),
    ("a.launch", '"launch":\n- log: {message: hi}\n', "yaml"),
    ("a.launch", "launcher: 1\n", "python"),  # not the key "launch": no frontend takes it
    ("dir.d/launch", "from launch import LaunchDescription\n", "python"),  # a dot in a folder is no extension
    ("a.launch", "launch: int = 1\ndef generate_launch_description(): ...\n", "python"),
    ("a.launch", None, None),  # unknown until read
])
def test_launch_format(path, text, fmt):
    assert launch_format(path, text) == fmt


@pytest.mark.parametrize("text, root", [
    ('<?xml version="1.0"?>\n<!-- a <node> -->\n<!DOCTYPE launch>\n<launch>', "launch"),
    ("<launch_file/>", "launch_file"),
    ("<robot name='r'/>", "robot"),
    ("<!-- never closed <launch>", None),
    ("launch:", None),
])
def test_xml_root(text, root):
    assert xml_root(text) == root


@pytest.mark.parametrize("text, expected", [
    ('<node pkg="p" exec="e"/>', Generation(True, None)),
    ('<node_container pkg="p" exec="e" name="c" namespace=""/>', Generation(True, None)),
    ('<include file="$(find-pkg-share p)/a.launch.xml"/>', Generation(True, None)),
    ("<let name='a' value='1'/>", Generation(True, None)),
    # <param type=> is ROS 2 as well (type="str"); only a node's type= is ROS 1
    ('<node pkg="p" exec="e">\n  <param name="a" type="str" value="1"/>\n</node>', Generation(True, None)),
    ('<node pkg="p"\n      type="e"/>', Generation(False, ("<node type=...>", 2))),  # the line of type=
    ('<launch>\n  <arg name="a"/>\n  <param name="x" value="$(arg a)"/>', Generation(False, ("$(arg ...)", 3))),
    ('<launch>\n<rosparam command="load" file="x.yaml"/>', Generation(False, ("<rosparam>", 2))),
    ("<test test-name='t' pkg='p' type='t'/>", Generation(False, ("<test>", 1))),
    ('<node pkg="p" name="n" args="$(optenv X 1)"/>', Generation(False, ("$(optenv ...)", 1))),
    # markers in comments do not count
    ("<!-- was: <node pkg='p' type='e'/> -->\n<node pkg='p' exec='e'/>", Generation(True, None)),
    ("<!-- port with $(var ns) -->\n<node pkg='p' type='e'/>", Generation(False, ("<node type=...>", 2))),
    # neither: a file of arguments and includes only
    ('<launch><arg name="a" default="1"/><include file="x.launch"/></launch>', Generation(False, None)),
    # a half-ported file has both (the scan stops at the first ROS 2 marker)
    ('<node pkg="p" type="e"/>\n<node pkg="q" exec="e" args="$(arg a)"/>', Generation(True, ("<node type=...>", 1))),
])
def test_generation(text, expected):
    assert generation(text) == expected


ROS2 = '<launch>\n  <node pkg="p" exec="e"/>\n</launch>\n'
ROS1 = '<launch>\n  <node pkg="p" type="e"/>\n</launch>\n'
NEITHER = '<launch>\n  <arg name="a" default="1"/>\n</launch>\n'
YAML_LAUNCH = "launch:\n- node: {pkg: p, exec: e}\n"
PY_LAUNCH = "def generate_launch_description():\n    pass\n"
NOT_LAUNCH_REASON = ("not a launch file: no launch frontend takes it, and as Python it defines no "
                     "generate_launch_description")
ROS1_REASON = "a ROS 1 (roslaunch) launch file (<node type=...> on line 2), which ros2 launch cannot load"


@pytest.mark.parametrize("name, text, explicit, kind", [
    # found in a directory
    ("a.launch", ROS2, False, "launch"),
    ("a.launch", ROS1, False, None),
    ("a.launch", NEITHER, False, None),
    ("a.launch", ROS2.replace("<launch>", "<robot>").replace("</launch>", "</robot>"), False, None),
    ("a.launch", YAML_LAUNCH, False, "launch"),
    ("a.launch", PY_LAUNCH, False, "launch"),
    ("a.launch", "# Notes\n", False, None),
    ("a.launch", None, False, None),  # unreadable: most likely no launch file at all
    ("a.launch.xml", NEITHER, False, "launch"),
    ("a.launch.xml", ROS1, False, None),
    ("a.launch.xml", None, False, "launch"),  # unreadable, reported as the launch file it is named
    ("config_launch.yaml", "cases:\n- a\n", False, None),
    ("config_launch.yaml", "n:\n  ros__parameters:\n    a: 1\n", False, "params"),
    ("demo_launch.yml", YAML_LAUNCH, False, "launch"),
    # named on the command line
    ("a.launch", NEITHER, True, "launch"),
    ("a.launch", ROS1, True, None),
    ("a.launch.xml", ROS1, True, None),
    ("a.launch", "# Notes\n", True, "launch"),  # loaded as Python, last, like launch does
    ("README.md", "# Notes\n", True, None),  # not a launch file: skipped, with the reason
    ("setup.py", "from setuptools import setup\n", True, None),
    ("a.launch", None, True, "launch"),
    ("config_launch.yaml", "cases:\n- a\n", True, "launch"),  # what its name says
    ("a.yaml", YAML_LAUNCH, True, "launch"),
    ("a.yaml", "a: 1\n", True, "params"),
])
def test_classify(name, text, explicit, kind):
    verdict = classify(name, text, explicit)
    assert verdict.kind == kind
    no_launch = explicit and kind is None and text != ROS1
    assert verdict.reason == (ROS1_REASON if text == ROS1 else NOT_LAUNCH_REASON if no_launch else "")


@pytest.mark.parametrize("text, params", [
    ("camera:\n  ros__parameters:\n    rate: 30\n", True),
    ("/**:\n  ros__parameters: {rate: 30}\n", True),
    ("camera: {ros__parameters: {rate: 30}}\n", True),
    ('camera:\n  "ros__parameters":\n    rate: 30\n', True),
    ("camera:\r\n  ros__parameters:\r\n    rate: 30\r\n", True),
    ("camera:\n  ros__parameters_old: {}\n", True),  # rcl compares the key's prefix
    # a flat file for a composable node, saying so in a comment (husarion_ugv lights)
    ("# In ComposableNode ros__parameters are not supported\nrate: 30\n", False),
    ("controllers:\n  #   ros__parameters:\n  arm: {}\n", False),  # a commented-out block
    ("note: ros__parameters\n", False),
    ('note: "ros__parameters: x"\n', False),
])
def test_a_yaml_file_is_a_parameter_file_by_its_ros_parameters_key(tmp_path, text, params):
    from physai_lint.workspace.discovery import sniff_param_file

    assert classify("config.yaml", text, False).kind == ("params" if params else None)
    path = tmp_path / "config.yaml"
    path.write_bytes(text.encode())
    assert sniff_param_file(str(path)) is params
