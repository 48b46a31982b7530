"""PathSubstitution and PathJoinSubstitution's ``/`` operator (launch on jazzy and later)."""

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


def test_path_substitution_and_truediv(demo_graph):
    files = {"config/p.yaml": "/**:\n  ros__parameters:\n    rate: 5.0\n", "launch/a.launch.py": LAUNCH}
    nodes = demo_graph(files, "launch/a.launch.py", distro="rolling")
    for name in ("slash", "join_then_slash", "list_path"):
        assert nodes[name]["parameters"] == {"rate": 5.0}, name
        assert nodes[name]["parameters_complete"] is True, name
    # cfg_file is undeclared: the path is unknown, and so are the parameters it brings
    assert nodes["unknown_part"]["parameters_complete"] is False


FIND = """
import os
from launch import LaunchDescription
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare

def generate_launch_description():
    share = FindPackageShare("other").find("demo")
    return LaunchDescription([
        Node(package="demo", executable="a", name="found", parameters=[os.path.join(share, "config", "p.yaml")]),
    ])
"""


def test_find_package_share_find_is_the_named_package_directory(demo_graph):
    # FindPackageShare(...).find(pkg) is launch_ros's get_package_share_directory(pkg), right away
    files = {"config/p.yaml": "/**:\n  ros__parameters:\n    rate: 5.0\n", "launch/a.launch.py": FIND}
    nodes = demo_graph(files, "launch/a.launch.py")
    assert nodes["found"]["parameters"] == {"rate": 5.0}
    assert nodes["found"]["parameters_complete"] is True


PATHLIB = """
from pathlib import Path
from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch_ros.actions import Node

def generate_launch_description():
    share = get_package_share_directory("demo")
    return LaunchDescription([
        Node(package="demo", executable="a", name="chained", parameters=[str(Path(share) / "config" / "p.yaml")]),
        Node(package="demo", executable="a", name="parts", parameters=[Path(share, "config", "p.yaml")]),
    ])
"""


def test_pathlib_joins_of_a_package_directory(demo_graph):
    # ouster-ros: Path(share) / 'launch' / 'driver.launch.py'; the second / joined a plain str
    files = {"config/p.yaml": "/**:\n  ros__parameters:\n    rate: 5.0\n", "launch/a.launch.py": PATHLIB}
    nodes = demo_graph(files, "launch/a.launch.py")
    for name in ("chained", "parts"):
        assert nodes[name]["parameters"] == {"rate": 5.0}, name
