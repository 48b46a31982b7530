"""physai-lint never executes what it reads.

The workspace below is booby-trapped: its launch files (Python, XML, YAML), parameter YAML,
package.xml, setup.py, setup.cfg, CMakeLists.txt and node sources each create a marker file under
tmp_path if they are imported or run, or if their ``$(command)``/``Command``/``PythonExpression``/
``$(eval)``/YAML python tags/XML external entities are evaluated; many also connect to a listening
socket the test owns. Every subcommand runs over it; afterwards there is no marker and nothing
connected to the socket.
"""
from __future__ import annotations

import socket
from pathlib import Path

import pytest
from hardening_helpers import assert_no_traceback, run_cli, write

PY_TRAP = """import os, socket
open({marker!r}, "w").write("{label}")
try:
    socket.create_connection(("127.0.0.1", {port}), timeout=1).sendall(b"{label}")
except OSError:
    pass
"""


def _trap(marker_dir: Path, port: int, label: str) -> str:
    return PY_TRAP.format(marker=str(marker_dir / f"{label}.marker"), port=port, label=label)


def _files(markers: Path, port: int) -> dict[str, str | bytes]:
    m = markers
    url = f"http://127.0.0.1:{port}"
    py_launch = f'''import os, subprocess, sys
{_trap(m, port, "py_launch_module")}
sys.path.insert(0, os.path.dirname(__file__))
import evil_helper  # a helper next to the launch file: importing it would run it
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, ExecuteProcess, OpaqueFunction
from launch.substitutions import Command, LaunchConfiguration, PythonExpression
from launch.conditions import IfCondition
from launch_ros.actions import Node

MARK = {str(m / "py_constant.marker")!r}
exec(open(MARK, "w").write("exec") and "pass")
eval("__import__('os').system('touch {m / "py_eval.marker"}')")


def _opaque(context, *args, **kwargs):
    open({str(m / "py_opaque.marker")!r}, "w").write("opaque")
    return []


def helper(n):
    os.system("touch {m / "py_helper.marker"}")
    return helper(n - 1) if n else []


def generate_launch_description():
    open({str(m / "py_gld.marker")!r}, "w").write("gld")
    subprocess.run(["touch", {str(m / "py_subprocess.marker")!r}])
    robot = Command(["touch ", {str(m / "py_command.marker")!r}, "; echo <robot/>"])
    flag = PythonExpression(["__import__('os').system('touch {m / "py_pyexpr.marker"}') == 0"])
    return LaunchDescription([
        DeclareLaunchArgument("x", default_value=Command("touch {m / "py_command_arg.marker"}")),
        OpaqueFunction(function=_opaque),
        ExecuteProcess(cmd=["touch", {str(m / "py_execproc.marker")!r}]),
        Node(package="evil_py", executable="talker", name="talker",
             parameters=[{{"robot_description": robot, "flag": flag}}],
             condition=IfCondition(flag)),
        *helper(3),
    ])
'''
    xml_launch = f'''<?xml version="1.0"?>
<launch>
  <arg name="desc" default="$(command 'touch {m / "xml_command.marker"}')"/>
  <arg name="flag" default="$(eval '__import__(&quot;os&quot;).system(&quot;touch {m / "xml_eval.marker"}&quot;) == 0')"/>
  <include file="{url}/xml_include.launch.xml"/>
  <node pkg="evil_py" exec="talker" name="xml_talker" if="$(var flag)">
    <param name="robot_description" value="$(var desc)"/>
    <param from="$(find-pkg-share evil_py)/config/evil.yaml"/>
  </node>
  <executable cmd="touch {m / "xml_executable.marker"}"/>
</launch>
'''
    # A DOCTYPE refuses the whole file, so the entity traps live in a file of their own.
    xml_entities = f'''<?xml version="1.0"?>
<!DOCTYPE launch [<!ENTITY ext SYSTEM "{url}/xml_entity">
  <!ENTITY file SYSTEM "file://{m / "xml_entity.marker"}">]>
<launch><arg name="e" default="&ext;&file;"/></launch>
'''
    yaml_launch = f'''launch:
- arg: {{name: desc, default: "$(command 'touch {m / "yaml_command.marker"}')"}}
- arg: {{name: flag, default: "$(eval '__import__(\\"os\\").system(\\"touch {m / "yaml_eval.marker"}\\") == 0')"}}
- let: {{name: obj, value: !!python/object/apply:os.system ["touch {m / "yaml_tag.marker"}"]}}
- include: {{file: "{url}/yaml_include.launch.yaml"}}
- node:
    pkg: evil_py
    exec: talker
    name: yaml_talker
    if: $(var flag)
    param: [{{name: robot_description, value: $(var desc)}}]
- executable: {{cmd: "touch {m / "yaml_executable.marker"}"}}
'''
    params = f'''talker:
  ros__parameters:
    a: !!python/object/apply:os.system ["touch {m / "param_tag.marker"}"]
    b: !!python/object/new:subprocess.Popen [["touch", "{m / "param_popen.marker"}"]]
    c: $(command 'touch {m / "param_command.marker"}')
'''
    setup_py = f'''{_trap(m, port, "setup_py")}
from setuptools import setup
import os
os.system("touch {m / "setup_system.marker"}")
setup(
    name="evil_py",
    packages=["evil_py"],
    data_files=[("share/evil_py/launch", ["launch/evil.launch.py", "launch/evil.launch.xml",
                                         "launch/evil.launch.yaml"]),
                ("share/evil_py/config", ["config/evil.yaml"]),
                ("share/evil_py", ["package.xml"])],
    entry_points={{"console_scripts": ["talker = evil_py.talker:main"]}},
)
'''
    package_xml = f'''<?xml version="1.0"?>
<!DOCTYPE package SYSTEM "{url}/package_dtd">
<package format="3">
  <name>evil_py</name>
  <version>0.1.0</version>
  <description>trap</description>
  <maintainer email="m@example.com">x</maintainer>
  <license>Apache-2.0</license>
  <exec_depend>evil_cpp</exec_depend>
  <export><build_type>ament_python</build_type></export>
</package>
'''
    talker = f'''{_trap(m, port, "node_source")}
import rclpy
from rclpy.node import Node
from std_msgs.msg import String


class Talker(Node):
    def __init__(self):
        super().__init__("talker")
        self.create_publisher(String, "chatter", 10)
        self.declare_parameter("a", __import__("os").system("touch {m / "node_param.marker"}"))


def main():
    rclpy.init()
'''
    cmake = f'''cmake_minimum_required(VERSION 3.8)
project(evil_cpp)
execute_process(COMMAND touch {m / "cmake_execute.marker"})
file(WRITE {m / "cmake_file.marker"} "cmake")
find_package(ament_cmake REQUIRED)
add_executable(node src/node.cpp)
install(TARGETS node DESTINATION lib/${{PROJECT_NAME}})
install(CODE "execute_process(COMMAND touch {m / "cmake_install_code.marker"})")
install(DIRECTORY launch DESTINATION share/${{PROJECT_NAME}})
ament_package()
'''
    cpp_launch = f'''from launch import LaunchDescription
from launch_ros.actions import Node
from launch.substitutions import Command
{_trap(m, port, "cpp_launch")}

def generate_launch_description():
    return LaunchDescription([Node(package="evil_cpp", executable="node",
                                   arguments=[Command("touch {m / "cpp_command.marker"}")])])
'''
    return {
        "src/evil_py/package.xml": package_xml,
        "src/evil_py/setup.py": setup_py,
        "src/evil_py/setup.cfg": f"[develop]\nscript_dir=$base/lib/evil_py\n[options]\n"
                                 f"setup_requires = {url}/setup_cfg\n",
        "src/evil_py/resource/evil_py": "",
        "src/evil_py/evil_py/__init__.py": _trap(m, port, "pkg_init"),
        "src/evil_py/evil_py/talker.py": talker,
        "src/evil_py/launch/evil_helper.py": _trap(m, port, "launch_helper"),
        "src/evil_py/launch/evil.launch.py": py_launch,
        "src/evil_py/launch/evil.launch.xml": xml_launch,
        "src/evil_py/launch/evil.launch.yaml": yaml_launch,
        "src/evil_py/launch/entities.launch.xml": xml_entities,
        "src/evil_py/config/evil.yaml": params,
        "src/evil_py/conftest.py": _trap(m, port, "conftest"),
        "src/evil_py/sitecustomize.py": _trap(m, port, "sitecustomize"),
        "src/evil_cpp/package.xml": package_xml.replace("evil_py", "evil_cpp")
        .replace("<exec_depend>evil_cpp</exec_depend>", "")
        .replace("ament_python", "ament_cmake"),
        "src/evil_cpp/CMakeLists.txt": cmake,
        "src/evil_cpp/src/node.cpp": '#include <cstdlib>\nint main() { return std::system("touch '
                                     f'{m / "cpp_node.marker"}"); }}\n',
        "src/evil_cpp/launch/cpp.launch.py": cpp_launch,
    }


@pytest.fixture()
def listener():
    """A listening socket; whatever connects to it is evidence of execution or fetching."""
    srv = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
    srv.bind(("127.0.0.1", 0))
    srv.listen(16)
    srv.setblocking(False)
    yield srv
    srv.close()


def _connections(srv: socket.socket) -> list[bytes]:
    got = []
    while True:
        try:
            conn, _ = srv.accept()
        except BlockingIOError:
            return got
        conn.settimeout(1)
        try:
            got.append(conn.recv(100))
        except OSError:
            got.append(b"?")
        conn.close()


COMMANDS = [
    ["check", "."],
    ["check", ".", "--format", "json"],
    ["check", ".", "--format", "sarif", "--strict"],
    ["check", "src/evil_py/launch/evil.launch.py", "x:=$(command touch)"],
    ["graph", "src/evil_py/launch/evil.launch.py", "--format", "json"],
    ["graph", "src/evil_py/launch/evil.launch.xml", "--format", "dot"],
    ["graph", "src/evil_py/launch/evil.launch.yaml", "--format", "mermaid"],
    ["plan", "src/evil_py/launch/evil.launch.py"],
    ["plan", "src/evil_py/launch/evil.launch.xml", "--format", "json"],
    ["plan", "src/evil_cpp/launch/cpp.launch.py"],
    ["graph", "src/evil_py/launch/entities.launch.xml", "--format", "json"],
    ["params", "src/evil_py/launch/evil.launch.py"],
    ["params", "src/evil_py/launch/evil.launch.yaml", "--format", "json"],
    ["params", "src/evil_py/launch/evil.launch.xml"],
]


def test_no_subcommand_executes_or_fetches_anything(tmp_path: Path, listener: socket.socket) -> None:
    markers = tmp_path / "markers"
    markers.mkdir()
    ws = write(tmp_path / "ws", _files(markers, listener.getsockname()[1]))
    out = {}
    for args in COMMANDS:
        proc = run_cli(args, ws, tmp_path)
        out[" ".join(args[:2])] = proc.stdout
        assert_no_traceback(proc)
        assert proc.returncode != 2, (args, proc.stderr)
        assert sorted(p.name for p in markers.iterdir()) == [], f"{args} executed user code"
        assert _connections(listener) == [], f"{args} connected to the test's socket"
    # The traps were reached: the files were read and analysed, not skipped.
    assert '"name": "talker"' in out["graph src/evil_py/launch/evil.launch.py"]
    assert "xml_talker" in out["graph src/evil_py/launch/evil.launch.xml"]
    assert "evil.launch.yaml" in out["check ."] and "entities.launch.xml" in out["check ."]


def test_traps_are_armed(tmp_path: Path, listener: socket.socket) -> None:
    """The traps work when Python does run them: the test above could not pass by accident."""
    import subprocess
    import sys

    markers = tmp_path / "markers"
    markers.mkdir()
    ws = write(tmp_path / "ws", _files(markers, listener.getsockname()[1]))
    helper = ws / "src/evil_py/launch/evil_helper.py"
    subprocess.run([sys.executable, str(helper)], check=True, timeout=30)
    assert (markers / "launch_helper.marker").is_file()
    assert _connections(listener) == [b"launch_helper"]
