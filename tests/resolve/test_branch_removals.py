"""A ``pop``/``remove`` under an ``if`` decided only at launch time removes the item only in that
branch: a declaration removed there still declares the argument otherwise (no L101), and a node
removed there may still be launched (its activity is unknown, not gone)."""
import json

LAUNCH = """
import os
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    actions = [
        DeclareLaunchArgument("rate", default_value="1.0"),
        Node(package="demo_nodes_cpp", executable="talker", name="talker",
             parameters=[{"rate": LaunchConfiguration("rate")}]),
        Node(package="demo_nodes_cpp", executable="listener", name="listener"),
    ]
    if os.environ.get("NO_LISTENER"):
        actions.pop()
    if os.environ.get("FIXED_RATE"):
        actions.remove(actions[0])
    return LaunchDescription(actions)
"""


def test_removed_under_an_undecided_if_is_kept_for_the_other_branch(tmp_path, demo_package):
    from physai_lint import api
    from physai_lint.engine import CheckOptions, run_check

    path = str(demo_package({"launch/a.launch.py": LAUNCH}) / "launch/a.launch.py")
    opts = CheckOptions(paths=[path], workspace=str(tmp_path))
    assert [f.code for f in run_check(opts, cwd=str(tmp_path)).findings if f.severity == "error"] == []
    nodes = json.loads(api.graph(opts, path, "json"))["nodes"]
    assert sorted((n["name"], n["active"]) for n in nodes) == [("listener", "unknown"), ("talker", True)]
