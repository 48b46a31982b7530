"""A dependency's CONFIG_EXTRAS macro that installs files: what the calling package installs is
then not known, so a parameter file is not reported as not installed (P102)."""
from __future__ import annotations

from pathlib import Path

from physai_lint.engine import CheckOptions, run_check

TOOLS_CMAKE = """cmake_minimum_required(VERSION 3.8)
project(dcf_tools)
find_package(ament_cmake REQUIRED)
ament_package(CONFIG_EXTRAS "cmake/dcf_tools-extras.cmake")
"""

EXTRAS = """macro(_copy_bus TARGET)
  install(DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}/config/${TARGET}/
          DESTINATION share/${PROJECT_NAME}/config/${TARGET}/)
endmacro()
macro(generate_bus TARGET)
  add_custom_target(${TARGET}_bus ALL)
  _copy_bus(${TARGET})
endmacro()
macro(describe_bus TARGET)
  message(STATUS "bus ${TARGET}")
endmacro()
"""

ROBOT_CMAKE = """cmake_minimum_required(VERSION 3.8)
project(robot)
find_package(ament_cmake REQUIRED)
find_package(dcf_tools REQUIRED)
{call}(arm)
install(DIRECTORY launch DESTINATION share/${{PROJECT_NAME}})
ament_package()
"""

LAUNCH = """from launch import LaunchDescription
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare
from launch.substitutions import PathJoinSubstitution


def generate_launch_description():
    params = PathJoinSubstitution([FindPackageShare('robot'), 'config', 'arm', 'bus.yaml'])
    return LaunchDescription([
        Node(package='demo_nodes_cpp', executable='talker', name='arm', parameters=[params]),
    ])
"""


def _manifest(name: str, deps: str = "") -> str:
    return (f'<?xml version="1.0"?>\n<package format="3"><name>{name}</name><version>0.1.0</version>'
            f'<description>d</description><maintainer email="a@b.c">m</maintainer>'
            f'<license>Apache-2.0</license><buildtool_depend>ament_cmake</buildtool_depend>{deps}'
            f'<export><build_type>ament_cmake</build_type></export></package>\n')


def _p102(tmp_path: Path, call: str) -> list[str]:
    files = {
        "src/dcf_tools/package.xml": _manifest("dcf_tools"),
        "src/dcf_tools/CMakeLists.txt": TOOLS_CMAKE,
        "src/dcf_tools/cmake/dcf_tools-extras.cmake": EXTRAS,
        "src/robot/package.xml": _manifest("robot", "<depend>dcf_tools</depend><exec_depend>demo_nodes_cpp</exec_depend>"),
        "src/robot/CMakeLists.txt": ROBOT_CMAKE.format(call=call),
        "src/robot/launch/arm.launch.py": LAUNCH,
        "src/robot/config/arm/bus.yaml": "arm:\n  ros__parameters:\n    rate: 10\n",
    }
    for rel, text in files.items():
        (tmp_path / rel).parent.mkdir(parents=True, exist_ok=True)
        (tmp_path / rel).write_text(text)
    opts = CheckOptions(paths=[str(tmp_path / "src/robot/launch/arm.launch.py")], workspace=str(tmp_path),
                        cache=False)
    return [f.message for f in run_check(opts).findings if f.code == "P102"]


def test_a_dependency_macro_that_installs_leaves_the_install_unknown(tmp_path: Path) -> None:
    # generate_bus installs through another macro of the same file
    assert _p102(tmp_path, "generate_bus") == []


def test_a_dependency_macro_that_installs_nothing_changes_nothing(tmp_path: Path) -> None:
    found = _p102(tmp_path, "describe_bus")
    assert len(found) == 1 and "config/arm/bus.yaml" in found[0]
