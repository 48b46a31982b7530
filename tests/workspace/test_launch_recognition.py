"""Which files are launch files: by name, else by text, the way ros2 launch loads them (launch
``any_launch_file_utilities.get_launch_description_from_any_launch_file``: any extension, the
frontend parsers first, Python last), without linting ROS 1 roslaunch files found in a directory."""
from __future__ import annotations

import json
import os
import subprocess
import sys
from collections.abc import Callable
from pathlib import Path

import pytest

from physai_lint import files as files_module
from physai_lint.engine import CheckOptions, Report, run_check

REPO = Path(__file__).resolve().parents[2]
PACKAGE_XML = """<package format="3"><name>demo</name><version>0.0.0</version><description>d</description>
<maintainer email="m@example.com">a</maintainer><license>MIT</license>
<exec_depend>demo_nodes_cpp</exec_depend><export><build_type>ament_cmake</build_type></export></package>
"""
CMAKE = "project(demo)\ninstall(DIRECTORY launch config DESTINATION share/${PROJECT_NAME})\n"

# ROS 2 XML named *.launch (topic_tools' relay.launch, create_robot's create_2.launch)
ROS2_XML = """<launch>
  <node pkg="demo_nodes_cpp" exec="talker" name="talker" namespace="$(var ns)"/>
</launch>
"""
# ROS 1 roslaunch XML (root <launch> too): never linted as ROS 2
ROS1_XML = """<launch>
  <arg name="ns" default="r1"/>
  <node name="urg_node" pkg="urg_node" type="urg_node" ns="$(arg ns)">
    <rosparam command="load" file="$(find urg_node)/config/urg.yaml"/>
  </node>
</launch>
"""
YAML_LAUNCH = 'launch:\n- node: {pkg: demo_nodes_cpp, exec: talker, name: "talker-1"}\n'
PY_LAUNCH = """from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([Node(package="demo_nodes_cpp", executable="talker", name="talker-1")])
"""


@pytest.fixture
def demo(tmp_path: Path) -> Callable[[dict[str, str]], Path]:
    """Write ``src/demo`` (package.xml, CMakeLists.txt installing launch/ and config/) with
    ``files`` (relative to the package); returns the workspace."""

    def write(files: dict[str, str | bytes]) -> Path:
        pkg = tmp_path / "src" / "demo"
        for rel, text in {"package.xml": PACKAGE_XML, "CMakeLists.txt": CMAKE, **files}.items():
            (pkg / rel).parent.mkdir(parents=True, exist_ok=True)
            if isinstance(text, bytes):
                (pkg / rel).write_bytes(text)
            else:
                (pkg / rel).write_text(text)
        return tmp_path

    return write


def check(ws: Path, *paths: str) -> Report:
    return run_check(CheckOptions(paths=[str(ws / p) for p in paths], workspace=str(ws), cache=False, jobs=1))


def found(report: Report, ws: Path) -> list[tuple[str, int, str]]:
    return sorted((os.path.relpath(f.span.file, ws), f.span.line, f.code) for f in report.findings)


def checked(report: Report, ws: Path) -> list[str]:
    return sorted(os.path.relpath(f, ws) for f in report.files)


def test_explicit_dot_launch_xml_is_checked(demo):
    ws = demo({"launch/relay.launch": ROS2_XML})
    report = check(ws, "src/demo/launch/relay.launch")
    assert found(report, ws) == [("src/demo/launch/relay.launch", 2, "L101")]  # $(var ns) undeclared
    assert checked(report, ws) == ["src/demo/launch/relay.launch"] and report.skipped == []


def test_walk_takes_ros2_dot_launch_files_only(demo):
    ws = demo({
        "launch/relay.launch": ROS2_XML,
        "launch/urg.launch": ROS1_XML,
        "launch/bare.launch": "<launch>\n  <arg name=\"a\" default=\"1\"/>\n</launch>\n",  # could be either
        "launch/noisy.launch": b"\x00\x01 not text",  # a binary file is no finding either
        "launch/py.launch": PY_LAUNCH,  # Python named *.launch: ros2 launch loads it last
        "launch/y.launch": YAML_LAUNCH,  # both frontends claim the .launch extension
    })
    report = check(ws, "src")
    assert checked(report, ws) == ["src/demo/launch/py.launch", "src/demo/launch/relay.launch",
                                   "src/demo/launch/y.launch"]
    assert found(report, ws) == [("src/demo/launch/py.launch", 6, "N102"),
                                 ("src/demo/launch/relay.launch", 2, "L101"),
                                 ("src/demo/launch/y.launch", 2, "N102")]


def test_walk_leaves_ros1_launch_xml_out(demo):
    # ROS 1 packages also named included files *.launch.xml (turtlebot's move_base.launch.xml)
    ws = demo({"launch/move_base.launch.xml": ROS1_XML, "launch/relay.launch.xml": ROS2_XML})
    assert found(check(ws, "src"), ws) == [("src/demo/launch/relay.launch.xml", 2, "L101")]


def test_explicit_ros1_launch_file_is_skipped_with_its_reason(demo):
    ws = demo({"launch/urg.launch": ROS1_XML, "launch/urg.launch.xml": ROS1_XML})
    report = check(ws, "src/demo/launch/urg.launch", "src/demo/launch/urg.launch.xml")
    assert report.findings == [] and report.files == []
    reason = "a ROS 1 (roslaunch) launch file (<node type=...> on line 3), which ros2 launch cannot load"
    assert [(os.path.relpath(p, ws), why) for p, why in report.skipped] == [
        ("src/demo/launch/urg.launch", reason), ("src/demo/launch/urg.launch.xml", reason)]


def test_include_of_dot_launch_file_is_followed(demo):
    from physai_lint import api

    ws = demo({
        "launch/robot.launch.xml": '<launch>\n  <node pkg="demo_nodes_cpp" exec="talker" name="talker"/>\n'
                                   '  <include file="$(find-pkg-share demo)/launch/sub.launch"/>\n</launch>\n',
        "launch/sub.launch": '<launch>\n  <node pkg="demo_nodes_cpp" exec="listener" name="talker"/>\n</launch>\n',
    })
    entry = str(ws / "src/demo/launch/robot.launch.xml")
    graph = json.loads(api.graph(CheckOptions(paths=[entry], workspace=str(ws), cache=False), entry, "json"))
    assert sorted((n["fqn"], n["executable"]) for n in graph["nodes"]) == [("/talker", "listener"), ("/talker", "talker")]
    assert ("src/demo/launch/sub.launch", 2, "N101") in found(check(ws, "src/demo/launch/robot.launch.xml"), ws)


XML_BAD_NAME = '<?xml version="1.0"?>\n<launch>\n  <node pkg="demo_nodes_cpp" exec="talker" name="talker-1"/>\n</launch>\n'


@pytest.mark.parametrize("name, text, line", [
    ("launch/talker.launch", XML_BAD_NAME, 3),  # the XML frontend
    ("launch/talker", XML_BAD_NAME, 3),  # no extension: the text decides
    ("launch/talker.launch", YAML_LAUNCH, 2),  # the YAML frontend
    ("launch/talker.launch", PY_LAUNCH, 6),  # neither XML nor YAML: Python, as launch tries it last
    ("launch/talker.txt", PY_LAUNCH, 6),
])
def test_explicit_file_of_no_launch_extension_is_loaded_by_its_text(demo, name, text, line):
    ws = demo({name: text})
    report = check(ws, f"src/demo/{name}")
    assert [(ln, code) for _, ln, code in found(report, ws) if code != "U101"] == [(line, "N102")]
    assert checked(report, ws) == [f"src/demo/{name}"]


def test_explicit_file_that_is_no_launch_file_is_skipped_with_its_reason(demo):
    # what `git diff --name-only | xargs physai-lint` hands over besides launch files
    ws = demo({"README.md": "# Demo\n\nRun `ros2 launch demo relay.launch`.\n",
               "setup.py": "from setuptools import setup\nsetup(name='demo')\n"})
    for name in ("README.md", "setup.py"):
        report = check(ws, f"src/demo/{name}")
        assert report.findings == [] and checked(report, ws) == []
        assert [reason for _, reason in report.skipped] == [
            "not a launch file: no launch frontend takes it, and as Python it defines no generate_launch_description"]


def test_an_included_file_no_loader_takes_is_one_clear_finding(demo):
    ws = demo({"launch/notes.txt": "# Demo\n\nRun `ros2 launch demo relay.launch`.\n",
               "launch/a.launch.xml": '<launch>\n  <include file="$(find-pkg-share demo)/launch/notes.txt"/>\n</launch>\n'})
    report = check(ws, "src/demo/launch/a.launch.xml")
    x001 = [f for f in report.findings if f.code == "X001"]
    assert [f.span.line for f in x001] == [3]
    assert x001[0].message.startswith(
        'no launch frontend can load "notes.txt": it is neither XML, nor YAML with a "launch" key, nor Python (')


@pytest.mark.parametrize("data, code", [
    (b"\x00\x01\x02 binary", "X002"),
    (b"<launch>\xff\xfe</launch>", "X002"),
    (b"<launch><!-- " + b"<node " * 20000, "X001"),  # unclosed: malformed XML, no traceback
    (b"<!DOCTYPE launch [<!ENTITY a 'aaaa'>]><launch>&a;</launch>", "X001"),
])
def test_explicit_broken_dot_launch_file_is_a_clean_finding(demo, data, code):
    ws = demo({"launch/broken.launch": data})
    report = check(ws, "src/demo/launch/broken.launch")
    assert [f.code for f in report.findings] == [code]


def test_launch_yaml_that_is_no_launch_file(demo):
    # nmea_navsat_driver's test/configs/config_launch.yaml: a test matrix, not a broken launch file
    matrix = "serial_driver.launch.py:\n  interface: serial\n  messages:\n    - NavSatFix\n"
    params = "driver:\n  ros__parameters:\n    rate: [1, 'a']\n"
    ws = demo({"test/configs/config_launch.yaml": matrix, "config/driver_launch.yaml": params,
               "launch/demo_launch.yaml": YAML_LAUNCH})
    walked = check(ws, "src")
    assert found(walked, ws) == [("src/demo/config/driver_launch.yaml", 3, "P106"),  # a parameter file
                                 ("src/demo/launch/demo_launch.yaml", 2, "N102")]
    # named on the command line, it is what its name says, and broken
    named = check(ws, "src/demo/test/configs/config_launch.yaml")
    assert [(f.code, f.span.line, f.message) for f in named.findings] == [
        ("X001", 1, 'a YAML launch file must be one mapping with the key "launch"')]


def test_explicit_yaml_file_is_a_launch_file_when_it_says_so(demo):
    ws = demo({"config/talker.yaml": YAML_LAUNCH, "config/plain.yaml": "a: 1\n"})
    assert found(check(ws, "src/demo/config/talker.yaml"), ws) == [("src/demo/config/talker.yaml", 2, "N102")]
    assert [f.code for f in check(ws, "src/demo/config/plain.yaml").findings] == ["P104"]


def test_suppression_comment_in_dot_launch_file(demo):
    text = ROS2_XML.replace('"/>', '"/> <!-- physai-lint: ignore[L101] -->')
    ws = demo({"launch/relay.launch": text})
    report = check(ws, "src/demo/launch/relay.launch")
    assert checked(report, ws) == ["src/demo/launch/relay.launch"] and report.findings == []


def test_each_file_is_read_and_parsed_once(demo, monkeypatch):
    ws = demo({"launch/relay.launch": ROS2_XML, "launch/urg.launch": ROS1_XML, "launch/y.launch": YAML_LAUNCH,
               "launch/robot.launch.xml": '<launch>\n  <include file="$(find-pkg-share demo)/launch/relay.launch">'
                                          '\n    <arg name="ns" value="a"/>\n  </include>\n</launch>\n',
               "test/config_launch.yaml": "a: 1\n"})
    reads: list[str] = []
    parses: list[str] = []
    read, parse = files_module.FileStore._read, files_module.parse_launch_text

    def counting_read(self, path, fail):
        reads.append(os.path.relpath(path, ws))
        return read(self, path, fail)

    def counting_parse(path, *args, **kwargs):
        parses.append(os.path.relpath(path, ws))
        return parse(path, *args, **kwargs)

    monkeypatch.setattr(files_module.FileStore, "_read", counting_read)
    monkeypatch.setattr(files_module, "parse_launch_text", counting_parse)
    check(ws, "src")
    assert sorted(reads) == sorted(set(reads)) and "src/demo/launch/urg.launch" in reads
    assert sorted(parses) == ["src/demo/launch/relay.launch", "src/demo/launch/robot.launch.xml",
                              "src/demo/launch/y.launch"]


def _cli(args: list[str], cwd: Path) -> subprocess.CompletedProcess[str]:
    env = {**os.environ, "PYTHONPATH": str(REPO), "PHYSAI_LINT_CACHE_DIR": str(cwd / ".cache")}
    return subprocess.run([sys.executable, "-m", "physai_lint", *args], cwd=cwd, env=env, check=False,
                          capture_output=True, text=True, timeout=120)


def test_cli_says_which_named_files_it_skipped(demo):
    ws = demo({"launch/urg.launch": ROS1_XML, "launch/relay.launch": ROS2_XML})
    proc = _cli(["src/demo/launch/urg.launch", "--no-cache"], ws)
    assert proc.returncode == 0 and proc.stdout.strip() == "All checks passed! (0 files)"
    assert proc.stderr == ('physai-lint: warning: skipped "src/demo/launch/urg.launch": a ROS 1 (roslaunch) '
                           "launch file (<node type=...> on line 3), which ros2 launch cannot load\n")
    graph = _cli(["graph", "src/demo/launch/urg.launch"], ws)
    assert graph.returncode == 2 and graph.stderr.startswith(
        'error: "src/demo/launch/urg.launch" is not a launch file: a ROS 1 (roslaunch) launch file')


def test_cli_warns_when_a_directory_holds_nothing_to_check(demo):
    ws = demo({"launch/urg.launch": ROS1_XML, "test/configs/config_launch.yaml": "a: 1\n"})
    proc = _cli(["src", "--no-cache"], ws)
    assert proc.returncode == 0 and proc.stdout.strip() == "All checks passed! (0 files)"
    assert proc.stderr == 'physai-lint: warning: no launch or parameter file found in "src"\n'


def test_cli_graph_plan_params_of_a_file_that_cannot_load_say_why(demo):
    """An empty plan would read as a launch that starts nothing: the parse error instead, exit 1
    (an error finding, as `check` exits)."""
    ws = demo({"launch/bad.launch.py": "from launch import LaunchDescription\n"
                                       "def generate_launch_description(:\n    return LaunchDescription([])\n",
               "setup.py": "from setuptools import setup\nsetup(name='demo')\n"})
    for command in ("graph", "plan", "params"):
        proc = _cli([command, "src/demo/launch/bad.launch.py"], ws)
        assert (proc.returncode, proc.stdout) == (1, "")
        assert proc.stderr == ('error: src/demo/launch/bad.launch.py:2:33: X001 [parse-error] python syntax '
                               'error: "invalid syntax"\n')
    proc = _cli(["plan", "src/demo/setup.py"], ws)  # the reason said once
    assert proc.returncode == 2 and proc.stderr == (
        'error: "src/demo/setup.py" is not a launch file: no launch frontend takes it, and as Python it '
        'defines no generate_launch_description\n')
