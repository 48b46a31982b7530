"""Which files are launch files: by name, else by text, the way ros2 launch loads them (launch
``any_launch_file_utilities.get_launch_description_from_any_launch_file``: any extension, the
frontend parsers first, Python last), without linting ROS 1 roslaunch files found in a directory."""
from __future__ import annotations

import json
import os
from collections.abc import Callable
from pathlib import Path

import pytest

from physai_lint.engine import CheckOptions, Report, run_check

PACKAGE_XML = """<package format="3"><name>demo</name><version>0.0.0</version><description>d</description>
<maintainer email="m@example.com">a</maintainer><license>MIT</license>
<exec_depend>demo_nodes_cpp</exec_depend><export><build_type>ament_cmake</build_type></export></package>
"""
CMAKE = "project(demo)\ninstall(DIRECTORY launch config DESTINATION share/${PROJECT_NAME})\n"


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
