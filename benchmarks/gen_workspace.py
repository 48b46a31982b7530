#!/usr/bin/env python3
"""Generate a synthetic colcon workspace for benchmarking physai-lint.

    python benchmarks/gen_workspace.py N M OUT [--seed S]

writes OUT/src/ with N packages, each holding M launch files that rotate through Python, XML
and YAML, a parameter file, a package.xml and install rules (ament_python and ament_cmake
alternate). Launch file 0 of a package includes the package's other launch files, and also
launch file 0 of the previous package unless the package starts a new group of ten, so
include chains cross formats and packages but stay at most ten packages deep. The same
arguments always produce the same bytes.
"""
from __future__ import annotations

import argparse
import random
import shutil
from pathlib import Path

FORMATS = ("py", "xml", "yaml")
GROUP = 10
NODES_PER_FILE = 3


def pkg_name(i: int) -> str:
    return f"bench_pkg_{i:04d}"


def launch_name(j: int) -> str:
    return f"part_{j}.launch.{FORMATS[j % len(FORMATS)]}"


def node_name(j: int, k: int) -> str:
    return f"node_{j}_{k}"


def includes_of(i: int, j: int, m: int) -> list[tuple[str, str]]:
    """(package, launch file) pairs that launch file j of package i includes."""
    if j != 0:
        return []
    out = [(pkg_name(i), launch_name(jj)) for jj in range(1, m)]
    if i % GROUP:
        out.append((pkg_name(i - 1), launch_name(0)))
    return out


def package_xml(name: str, build_type: str, deps: list[str]) -> str:
    lines = "\n".join(f"  <exec_depend>{d}</exec_depend>" for d in deps)
    tool = "  <buildtool_depend>ament_cmake</buildtool_depend>\n" if build_type == "ament_cmake" else ""
    return f"""<?xml version="1.0"?>
<package format="3">
  <name>{name}</name>
  <version>0.0.1</version>
  <description>Synthetic benchmark package</description>
  <maintainer email="bench@example.com">bench</maintainer>
  <license>Apache-2.0</license>
{tool}  <exec_depend>launch</exec_depend>
  <exec_depend>launch_ros</exec_depend>
  <exec_depend>ros2launch</exec_depend>
  <exec_depend>rclcpp</exec_depend>
{lines}
  <export>
    <build_type>{build_type}</build_type>
  </export>
</package>
"""


def python_package(root: Path, name: str) -> None:
    (root / "resource").mkdir()
    (root / "resource" / name).write_text("")
    (root / name).mkdir()
    (root / name / "__init__.py").write_text("")
    (root / name / "worker.py").write_text(
        "import rclpy\nfrom rclpy.node import Node\nfrom std_msgs.msg import String\n\n\n"
        "def main():\n    rclpy.init()\n    node = Node('worker')\n"
        "    node.declare_parameter('rate', 10.0)\n"
        "    node.create_publisher(String, 'out', 10)\n"
        "    node.create_subscription(String, 'in', lambda m: None, 10)\n"
        "    rclpy.spin(node)\n")
    (root / "setup.cfg").write_text(
        f"[develop]\nscript_dir=$base/lib/{name}\n[install]\ninstall_scripts=$base/lib/{name}\n")
    (root / "setup.py").write_text(f"""import os
from glob import glob

from setuptools import setup

package_name = '{name}'

setup(
    name=package_name,
    version='0.0.1',
    packages=[package_name],
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
        (os.path.join('share', package_name, 'launch'), glob('launch/*launch.[pxy][yma]*')),
        (os.path.join('share', package_name, 'config'), glob('config/*.yaml')),
    ],
    install_requires=['setuptools'],
    entry_points={{'console_scripts': ['worker = {name}.worker:main']}},
)
""")


def cmake_package(root: Path, name: str) -> None:
    (root / "src").mkdir()
    (root / "src" / "worker.cpp").write_text(
        '#include "rclcpp/rclcpp.hpp"\n#include "std_msgs/msg/string.hpp"\n\n'
        "int main(int argc, char ** argv)\n{\n  rclcpp::init(argc, argv);\n"
        '  auto node = std::make_shared<rclcpp::Node>("worker");\n'
        '  node->declare_parameter("rate", 10.0);\n'
        '  auto pub = node->create_publisher<std_msgs::msg::String>("out", 10);\n'
        "  rclcpp::spin(node);\n  return 0;\n}\n")
    (root / "CMakeLists.txt").write_text(f"""cmake_minimum_required(VERSION 3.8)
project({name})
find_package(ament_cmake REQUIRED)
find_package(rclcpp REQUIRED)
find_package(std_msgs REQUIRED)
add_executable(worker src/worker.cpp)
ament_target_dependencies(worker rclcpp std_msgs)
install(TARGETS worker DESTINATION lib/${{PROJECT_NAME}})
install(DIRECTORY launch config DESTINATION share/${{PROJECT_NAME}})
ament_package()
""")


def params_yaml(m: int, rng: random.Random) -> str:
    out = ["/**:", "  ros__parameters:", "    use_sim_time: false", ""]
    for j in range(m):
        for k in range(NODES_PER_FILE):
            out += [
                f"/**/{node_name(j, k)}:",
                "  ros__parameters:",
                f"    rate: {rng.uniform(1.0, 100.0):.2f}",
                f"    frame_id: frame_{rng.randrange(1000)}",
                f"    enabled: {str(rng.random() < 0.5).lower()}",
                f"    gains: [{rng.uniform(0, 1):.3f}, {rng.uniform(0, 1):.3f}, {rng.uniform(0, 1):.3f}]",
                "",
            ]
    return "\n".join(out)


def launch_py(pkg: str, j: int, includes: list[tuple[str, str]]) -> str:
    lines = [
        "from launch import LaunchDescription",
        "from launch.actions import DeclareLaunchArgument, GroupAction, IncludeLaunchDescription",
        "from launch.conditions import IfCondition",
        "from launch.substitutions import LaunchConfiguration, PathJoinSubstitution",
        "from launch_ros.actions import Node, PushRosNamespace",
        "from launch_ros.substitutions import FindPackageShare",
        "",
        "",
        "def generate_launch_description():",
        "    use_sim_time = LaunchConfiguration('use_sim_time')",
        "    enabled = LaunchConfiguration('enabled')",
        f"    params = PathJoinSubstitution([FindPackageShare('{pkg}'), 'config', 'params.yaml'])",
        "    actions = [",
        "        DeclareLaunchArgument('use_sim_time', default_value='false'),",
        "        DeclareLaunchArgument('enabled', default_value='true', choices=['true', 'false']),",
        "    ]",
    ]
    for k in range(NODES_PER_FILE):
        lines += [
            "    actions.append(GroupAction([",
            f"        PushRosNamespace('ns_{k}'),",
            "        Node(",
            f"            package='{pkg}',",
            "            executable='worker',",
            f"            name='{node_name(j, k)}',",
            "            parameters=[params, {'use_sim_time': use_sim_time}],",
            f"            remappings=[('in', 'topic_{k}'), ('out', 'topic_{k + 1}')],",
            "            condition=IfCondition(enabled),",
            "        ),",
            "    ]))",
        ]
    for other_pkg, file in includes:
        lines += [
            "    actions.append(IncludeLaunchDescription(",
            f"        PathJoinSubstitution([FindPackageShare('{other_pkg}'), 'launch', '{file}']),",
            "        launch_arguments={'use_sim_time': use_sim_time}.items(),",
            "    ))",
        ]
    lines += ["    return LaunchDescription(actions)", ""]
    return "\n".join(lines)


def launch_xml(pkg: str, j: int, includes: list[tuple[str, str]]) -> str:
    lines = [
        "<launch>",
        '  <arg name="use_sim_time" default="false"/>',
        '  <arg name="enabled" default="true"/>',
    ]
    for k in range(NODES_PER_FILE):
        lines += [
            "  <group>",
            f'    <push-ros-namespace namespace="ns_{k}"/>',
            f'    <node pkg="{pkg}" exec="worker" name="{node_name(j, k)}" if="$(var enabled)">',
            f'      <param from="$(find-pkg-share {pkg})/config/params.yaml"/>',
            '      <param name="use_sim_time" value="$(var use_sim_time)"/>',
            f'      <remap from="in" to="topic_{k}"/>',
            f'      <remap from="out" to="topic_{k + 1}"/>',
            "    </node>",
            "  </group>",
        ]
    for other_pkg, file in includes:
        lines += [
            f'  <include file="$(find-pkg-share {other_pkg})/launch/{file}">',
            '    <arg name="use_sim_time" value="$(var use_sim_time)"/>',
            "  </include>",
        ]
    lines += ["</launch>", ""]
    return "\n".join(lines)


def launch_yaml(pkg: str, j: int, includes: list[tuple[str, str]]) -> str:
    lines = [
        "launch:",
        "- arg:",
        "    name: use_sim_time",
        '    default: "false"',
        "- arg:",
        "    name: enabled",
        '    default: "true"',
    ]
    for k in range(NODES_PER_FILE):
        lines += [
            "- group:",
            "  - push-ros-namespace:",
            f"      namespace: ns_{k}",
            "  - node:",
            f"      pkg: {pkg}",
            "      exec: worker",
            f"      name: {node_name(j, k)}",
            "      if: $(var enabled)",
            "      param:",
            f"      - from: $(find-pkg-share {pkg})/config/params.yaml",
            "      - name: use_sim_time",
            "        value: $(var use_sim_time)",
            "      remap:",
            "      - from: in",
            f"        to: topic_{k}",
            "      - from: out",
            f"        to: topic_{k + 1}",
        ]
    for other_pkg, file in includes:
        lines += [
            "- include:",
            f"    file: $(find-pkg-share {other_pkg})/launch/{file}",
            "    arg:",
            "    - name: use_sim_time",
            "      value: $(var use_sim_time)",
        ]
    lines.append("")
    return "\n".join(lines)


WRITERS = {"py": launch_py, "xml": launch_xml, "yaml": launch_yaml}


def generate(n: int, m: int, out: Path, seed: int = 0) -> int:
    """Write the workspace; return the number of launch and parameter files written."""
    rng = random.Random(seed)
    src = out / "src"
    if src.exists():
        shutil.rmtree(src)
    src.mkdir(parents=True)
    for i in range(n):
        name = pkg_name(i)
        root = src / name
        (root / "launch").mkdir(parents=True)
        (root / "config").mkdir()
        build_type = "ament_python" if i % 2 else "ament_cmake"
        deps = sorted({p for j in range(m) for p, _ in includes_of(i, j, m) if p != name})
        (root / "package.xml").write_text(package_xml(name, build_type, deps))
        (python_package if build_type == "ament_python" else cmake_package)(root, name)
        (root / "config" / "params.yaml").write_text(params_yaml(m, rng))
        for j in range(m):
            fmt = FORMATS[j % len(FORMATS)]
            text = WRITERS[fmt](name, j, includes_of(i, j, m))
            (root / "launch" / launch_name(j)).write_text(text)
    return n * (m + 1)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("n", type=int, help="number of packages")
    parser.add_argument("m", type=int, help="launch files per package")
    parser.add_argument("out", type=Path, help="workspace directory to (re)create src/ in")
    parser.add_argument("--seed", type=int, default=0)
    args = parser.parse_args()
    files = generate(args.n, args.m, args.out, args.seed)
    print(f"wrote {files} launch/parameter files in {args.n} packages under {args.out / 'src'}")


if __name__ == "__main__":
    main()
