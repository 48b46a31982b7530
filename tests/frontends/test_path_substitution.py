"""PathSubstitution and PathJoinSubstitution's ``/`` operator (launch on jazzy and later)."""
import json

from physai_lint import api
from physai_lint.engine import CheckOptions

PKG = """<package format="3"><name>demo</name><version>0.0.0</version><description>d</description>
<maintainer email="m@example.com">a</maintainer><license>MIT</license>
<export><build_type>ament_cmake</build_type></export></package>
"""

LAUNCH = """
from launch import LaunchDescription
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution, PathSubstitution
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare

def generate_launch_description():
    share = PathSubstitution(FindPackageShare("demo"))
    return LaunchDescription([
        Node(package="demo", executable="a", name="slash", parameters=[share / "config" / "p.yaml"]),
        Node(package="demo", executable="a", name="join_then_slash",
             parameters=[PathJoinSubstitution([FindPackageShare("demo"), "config"]) / ["p", ".yaml"]]),
        Node(package="demo", executable="a", name="list_path",
             parameters=[PathSubstitution([FindPackageShare("demo"), "config", "p.yaml"])]),
        Node(package="demo", executable="a", name="unknown_part",
             parameters=[share / "config" / LaunchConfiguration("cfg_file")]),
    ])
"""


def test_path_substitution_and_truediv(tmp_path):
    pkg = tmp_path / "src" / "demo"
    (pkg / "launch").mkdir(parents=True)
    (pkg / "config").mkdir()
    (pkg / "package.xml").write_text(PKG)
    (pkg / "CMakeLists.txt").write_text(
        "project(demo)\ninstall(DIRECTORY launch config DESTINATION share/${PROJECT_NAME})\n")
    (pkg / "config" / "p.yaml").write_text("/**:\n  ros__parameters:\n    rate: 5.0\n")
    entry = pkg / "launch" / "a.launch.py"
    entry.write_text(LAUNCH)
    opts = CheckOptions(paths=[str(entry)], workspace=str(tmp_path), distro="rolling")
    nodes = {n["name"]: n for n in json.loads(api.graph(opts, str(entry), "json"))["nodes"]}
    for name in ("slash", "join_then_slash", "list_path"):
        assert nodes[name]["parameters"] == {"rate": 5.0}, name
        assert nodes[name]["parameters_complete"] is True, name
    # cfg_file is undeclared: the path is unknown, and so are the parameters it brings
    assert nodes["unknown_part"]["parameters_complete"] is False
