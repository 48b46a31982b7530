"""Component descriptions made under an ``if`` the Python evaluator cannot decide while parsing
(it depends on a launch argument) carry that ``if`` as their condition: only the branch the
arguments select is loaded, and the argument counts as read."""
import json

LAUNCH = """
import os
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, OpaqueFunction
from launch.conditions import IfCondition
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import ComposableNodeContainer, LoadComposableNodes
from launch_ros.descriptions import ComposableNode


class Pipeline:
    def __init__(self, context):
        self.mode = LaunchConfiguration("mode").perform(context)

    def create(self):
        if self.mode == "compare":
            return [ComposableNode(package="demo", plugin="demo::Compare", name="filter")]
        else:
            return [ComposableNode(package="demo", plugin="demo::Plain", name="filter",
                                   condition=IfCondition(LaunchConfiguration("plain")))]


def setup(context):
    components = Pipeline(context).create()
    if os.getenv("HOME") == "/root":
        components.append(ComposableNode(package="demo", plugin="demo::Env", name="env"))
    return [LoadComposableNodes(composable_node_descriptions=components, target_container="/box")]


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument("mode", default_value="compare"),
        DeclareLaunchArgument("plain", default_value="true"),
        ComposableNodeContainer(name="box", namespace="", package="rclcpp_components",
                                executable="component_container"),
        OpaqueFunction(function=setup),
    ])
"""


def _components(tmp_path, demo_package, distro="humble", **args):
    from physai_lint import api
    from physai_lint.engine import CheckOptions

    path = str(demo_package({"launch/a.launch.py": LAUNCH}) / "launch/a.launch.py")
    opts = CheckOptions(paths=[path], launch_args=args, workspace=str(tmp_path), distro=distro)
    nodes = json.loads(api.graph(opts, path, "json"))["nodes"]  # two are named "filter"
    return sorted((n["executable"], n["active"]) for n in nodes if n["kind"] == "composable_node")


def test_only_the_selected_branch_is_loaded(tmp_path, demo_package):
    # the function is evaluated again with the arguments' values (as launch runs it): the branch
    # not taken makes no component at all; the one on the environment stays undecided
    assert _components(tmp_path, demo_package) == [("demo::Compare", True), ("demo::Env", "unknown")]
    assert _components(tmp_path, demo_package, mode="plain") == [("demo::Env", "unknown"), ("demo::Plain", True)]
    # the component's own condition applies from iron on; humble's LoadComposableNodes ignores it
    assert _components(tmp_path, demo_package, "jazzy", mode="plain", plain="false") == [
        ("demo::Env", "unknown"), ("demo::Plain", False)]
    assert _components(tmp_path, demo_package, mode="plain", plain="false") == [
        ("demo::Env", "unknown"), ("demo::Plain", True)]


def test_no_duplicate_component_across_exclusive_branches(tmp_path, demo_package):
    from physai_lint.engine import CheckOptions, run_check

    path = str(demo_package({"launch/a.launch.py": LAUNCH}) / "launch/a.launch.py")
    codes = {f.code for f in run_check(CheckOptions(paths=[path], workspace=str(tmp_path))).findings}
    assert "N107" not in codes and "L102" not in codes
    # the Python if a description was made under is no condition launch_ros is given: humble's
    # LoadComposableNodes ignoring conditions (L115) does not make it loaded
    assert "L115" not in codes
