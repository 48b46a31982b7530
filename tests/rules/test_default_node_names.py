"""A node the launch file names nothing gets the name its code gives it (``Node("talker")``,
``super().__init__('talker')``): parameter files are matched against that name (P103), two
such nodes in one namespace collide (N101), the graph lists it. A name the code computes, or
an executable making several nodes, leaves the node unnamed and the rules silent."""
from __future__ import annotations

from pathlib import Path

from physai_lint.engine import CheckOptions, run_check

CMAKE = """project(demo)
add_executable(talker src/talker.cpp)
install(TARGETS talker DESTINATION lib/${PROJECT_NAME})
install(DIRECTORY launch config DESTINATION share/${PROJECT_NAME})
"""
TALKER = """#include <rclcpp/rclcpp.hpp>
class Talker : public rclcpp::Node {
 public:
  explicit Talker(const rclcpp::NodeOptions & options) : Node("talker", options) {
    declare_parameter("rate", 1.0);
  }
};
int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Talker>(rclcpp::NodeOptions()));
}
"""
# the lifecycle demo's way: the constructor passes its argument on, main() gives the name
LIFECYCLE_TALKER = """#include <rclcpp_lifecycle/lifecycle_node.hpp>
class LifecycleTalker : public rclcpp_lifecycle::LifecycleNode {
 public:
  explicit LifecycleTalker(const std::string & node_name, bool intra_process_comms = false)
  : rclcpp_lifecycle::LifecycleNode(node_name, rclcpp::NodeOptions()) {}
};
int main(int argc, char ** argv) {
  auto lc_node = std::make_shared<LifecycleTalker>("lc_talker");
}
"""
# the name is computed: nothing can be said
COMPUTED = """#include <rclcpp/rclcpp.hpp>
int main(int argc, char ** argv) {
  auto node = rclcpp::Node::make_shared("talker_" + std::to_string(getpid()));
}
"""


def _launch(*nodes: str) -> str:
    return ("import os\nfrom ament_index_python.packages import get_package_share_directory\n"
            "from launch import LaunchDescription\nfrom launch_ros.actions import Node\n\n\n"
            "def generate_launch_description():\n"
            "    params = os.path.join(get_package_share_directory('demo'), 'config', 'talker.yaml')\n"
            "    return LaunchDescription([\n" + "".join(f"        {n},\n" for n in nodes) + "    ])\n")


def _check(demo_package, source: str, launch: str, params: str, code: str) -> list[tuple[int, str]]:
    pkg = demo_package({"CMakeLists.txt": CMAKE, "src/talker.cpp": source, "launch/a.launch.py": launch,
                        "config/talker.yaml": params})
    opts = CheckOptions(paths=[str(pkg / "launch/a.launch.py")], workspace=str(pkg.parent.parent), cache=False)
    return sorted((f.span.line, f.message) for f in run_check(opts).findings if f.code == code)


NAMESPACED = "Node(package='demo', executable='talker', namespace='robot1', parameters=[params])"


def test_a_file_keyed_by_the_default_name_misses_the_namespaced_node(demo_package):
    found = _check(demo_package, TALKER, _launch(NAMESPACED), "talker:\n  ros__parameters:\n    rate: 2.0\n",
                   "P103")
    assert len(found) == 1
    line, message = found[0]
    assert line == 1
    assert '"/robot1/talker"' in message
    assert '"talker" is the name its code gives it (' in message and "talker.cpp:4)" in message


def test_a_wildcard_key_or_the_full_name_matches(demo_package):
    for key in ("/**/talker", "/robot1/talker", "robot1/talker"):
        assert _check(demo_package, TALKER, _launch(NAMESPACED), f"{key}:\n  ros__parameters:\n    rate: 2.0\n",
                      "P103") == []


def test_a_key_one_typo_from_the_default_name(demo_package):
    launch = _launch("Node(package='demo', executable='talker', parameters=[params])")
    found = _check(demo_package, TALKER, launch,
                   "talker:\n  ros__parameters:\n    rate: 2.0\ntalkr:\n  ros__parameters:\n    rate: 3.0\n", "P103")
    assert found == []  # "talker" serves the node: a key for another node is left alone
    found = _check(demo_package, TALKER, launch, "/**:\n  ros__parameters:\n    x: 1\ntalkr:\n  ros__parameters:\n"
                   "    rate: 3.0\n", "P103")
    assert [line for line, _ in found] == [4]
    assert 'node key "talkr"' in found[0][1]


def test_the_name_a_constructor_passes_on_is_the_one_main_gives(demo_package):
    launch = _launch("Node(package='demo', executable='talker', namespace='robot1', parameters=[params])")
    found = _check(demo_package, LIFECYCLE_TALKER, launch, "lc_talker:\n  ros__parameters:\n    rate: 2.0\n",
                   "P103")
    assert len(found) == 1 and '"/robot1/lc_talker"' in found[0][1]


def test_a_computed_name_leaves_the_node_unnamed(demo_package):
    assert _check(demo_package, COMPUTED, _launch(NAMESPACED), "talker:\n  ros__parameters:\n    rate: 2.0\n",
                  "P103") == []


def test_a_node_remap_names_the_node(demo_package):
    launch = _launch("Node(package='demo', executable='talker', namespace='robot1', parameters=[params], "
                     "remappings=[('__node', 'speaker')])")
    found = _check(demo_package, TALKER, launch, "talker:\n  ros__parameters:\n    rate: 2.0\n", "P103")
    assert len(found) == 1 and '"/robot1/speaker"' in found[0][1]
    assert "its code gives it" not in found[0][1]


def test_two_unnamed_instances_in_one_namespace_collide(demo_package):
    plain = "Node(package='demo', executable='talker')"
    found = _check(demo_package, TALKER, _launch(plain, plain), "{}\n", "N101")
    assert len(found) == 1
    assert found[0][1].startswith('node "/talker" is launched twice (also at line 10)')
    assert "is the name its code gives it" in found[0][1]
    other = "Node(package='demo', executable='talker', namespace='r2')"
    assert _check(demo_package, TALKER, _launch(plain, other), "{}\n", "N101") == []
    assert _check(demo_package, COMPUTED, _launch(plain, plain), "{}\n", "N101") == []


PY_PACKAGE_XML = """<package format="3"><name>pybot</name><version>0.0.0</version><description>d</description>
<maintainer email="m@example.com">a</maintainer><license>MIT</license>
<export><build_type>ament_python</build_type></export></package>
"""
PY_SETUP = """from setuptools import setup

setup(
    name='pybot',
    packages=['pybot'],
    data_files=[('share/pybot', ['package.xml']), ('share/pybot/launch', ['launch/a.launch.py']),
                ('share/pybot/config', ['config/teleop.yaml'])],
    entry_points={'console_scripts': ['teleop = pybot.teleop:main']},
)
"""
PY_SETUP_CFG = "[develop]\nscript_dir=$base/lib/pybot\n[install]\ninstall_scripts=$base/lib/pybot\n"
PY_NODE = """import rclpy
from rclpy.node import Node


class Teleop(Node):
    def __init__(self):
        super().__init__('teleop_node')
        self.declare_parameter('scale', 1.0)


def main():
    rclpy.init()
    rclpy.spin(Teleop())
"""
PY_LAUNCH = """import os
from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    params = os.path.join(get_package_share_directory('pybot'), 'config', 'teleop.yaml')
    return LaunchDescription([Node(package='pybot', executable='teleop', parameters=[params])])
"""


def test_a_python_node_keyed_by_its_executable_name(tmp_path: Path):
    pkg = tmp_path / "src" / "pybot"
    files = {"package.xml": PY_PACKAGE_XML, "setup.py": PY_SETUP, "setup.cfg": PY_SETUP_CFG,
             "resource/pybot": "", "pybot/__init__.py": "", "pybot/teleop.py": PY_NODE,
             "launch/a.launch.py": PY_LAUNCH, "config/teleop.yaml": "teleop:\n  ros__parameters:\n    scale: 2.0\n"}
    for rel, text in files.items():
        (pkg / rel).parent.mkdir(parents=True, exist_ok=True)
        (pkg / rel).write_text(text)
    report = run_check(CheckOptions(paths=[str(pkg / "launch/a.launch.py")], workspace=str(tmp_path), cache=False))
    found = [f for f in report.findings if f.code == "P103"]
    assert len(found) == 1
    assert '("/teleop_node")' in found[0].message
    assert '"teleop_node" is the name its code gives it (' in found[0].message and "teleop.py:7)" in found[0].message
    assert found[0].help.startswith('key the file by the node\'s full name, e.g. "/teleop_node:"')


def test_the_graph_lists_the_default_name(demo_graph):
    nodes = demo_graph({"CMakeLists.txt": CMAKE, "src/talker.cpp": TALKER,
                        "launch/a.launch.py": _launch(NAMESPACED), "config/talker.yaml": "{}\n"},
                       "launch/a.launch.py")
    assert nodes["talker"]["fqn"] == "/robot1/talker"


LIFECYCLE_LAUNCH = """from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='nav2_map_server', executable='map_server', parameters=[{'yaml_filename': 'map.yaml'}]),
        Node(package='nav2_lifecycle_manager', executable='lifecycle_manager', name='lifecycle_manager_map',
             parameters=[{'autostart': True, 'node_names': ['map_server', 'amcl']}]),
    ])
"""


def test_a_lifecycle_manager_finds_a_node_by_its_default_name(demo_findings):
    # map_server's bundled declaration names it "map_server": only "amcl" is missing
    found = demo_findings({"launch/a.launch.py": LIFECYCLE_LAUNCH}, "launch/a.launch.py", "S201")
    assert [(line, message.split(";")[0]) for line, message in found] == [
        (9, 'lifecycle manager /lifecycle_manager_map manages "amcl" (/amcl) but no such node is launched')]


NAMESPACED_IN_CODE = TALKER.replace('Node("talker", options)', 'Node("talker", "robot1", options)')


def test_the_namespace_the_code_gives_stands_when_launch_gives_none(demo_package):
    plain = _launch("Node(package='demo', executable='talker', parameters=[params])")
    assert _check(demo_package, NAMESPACED_IN_CODE, plain, "/robot1/talker:\n  ros__parameters:\n    rate: 2.0\n",
                  "P103") == []
    found = _check(demo_package, NAMESPACED_IN_CODE, plain, "talker:\n  ros__parameters:\n    rate: 2.0\n", "P103")
    assert len(found) == 1 and '"/robot1/talker"' in found[0][1]
    # launch's namespace= replaces it (-r __ns:=)
    assert _check(demo_package, NAMESPACED_IN_CODE, _launch(NAMESPACED.replace("robot1", "r2")),
                  "/r2/talker:\n  ros__parameters:\n    rate: 2.0\n", "P103") == []
    # and so for a node launch names but does not place
    named = _launch("Node(package='demo', executable='talker', name='speaker', parameters=[params])")
    found = _check(demo_package, NAMESPACED_IN_CODE, named, "speaker:\n  ros__parameters:\n    rate: 2.0\n", "P103")
    assert len(found) == 1 and '"/robot1/speaker"' in found[0][1]


PROGRAM_CMAKE = """project(demo)
install(PROGRAMS scripts/tucker.py DESTINATION lib/${PROJECT_NAME})
install(DIRECTORY launch config DESTINATION share/${PROJECT_NAME})
"""
TUCKER = """#!/usr/bin/env python3
import rclpy
from rclpy.node import Node


class Tucker(Node):
    def __init__(self):
        super().__init__('arm_tucker')


def main():
    rclpy.init()
    rclpy.spin(Tucker())
"""


def test_a_python_script_installed_as_a_cmake_program(demo_package):
    launch = _launch("Node(package='demo', executable='tucker.py', parameters=[params])")
    pkg = demo_package({"CMakeLists.txt": PROGRAM_CMAKE, "scripts/tucker.py": TUCKER, "launch/a.launch.py": launch,
                        "config/talker.yaml": "tucker:\n  ros__parameters:\n    x: 1\n"})
    opts = CheckOptions(paths=[str(pkg / "launch/a.launch.py")], workspace=str(pkg.parent.parent), cache=False)
    found = [f.message for f in run_check(opts).findings if f.code == "P103"]
    assert len(found) == 1 and '("/arm_tucker")' in found[0]


LIST_VALUE_LAUNCH = """from launch import LaunchDescription
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    return LaunchDescription([
        Node(package='demo', executable='tucker.py', parameters=[
            {'yaml_path': [FindPackageShare('demo'), '/config/left.yaml'], 'names': ['a', 'b']}]),
    ])
"""
TYPED_TUCKER = TUCKER.replace("super().__init__('arm_tucker')",
                              "super().__init__('arm_tucker')\n        self.declare_parameter('yaml_path', '')\n"
                              "        self.declare_parameter('names', ['x'])")


def test_a_list_of_a_substitution_and_strings_is_one_string(demo_package):
    # launch_ros normalize_parameter_value: [FindPackageShare('demo'), '/config/left.yaml'] is a path
    pkg = demo_package({"CMakeLists.txt": PROGRAM_CMAKE, "scripts/tucker.py": TYPED_TUCKER,
                        "launch/a.launch.py": LIST_VALUE_LAUNCH})
    opts = CheckOptions(paths=[str(pkg / "launch/a.launch.py")], workspace=str(pkg.parent.parent), cache=False)
    assert [f.message for f in run_check(opts).findings if f.code == "P105"] == []
