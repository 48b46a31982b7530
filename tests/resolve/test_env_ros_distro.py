"""``$(env ROS_DISTRO)`` / ``EnvironmentVariable('ROS_DISTRO')`` is the checked distro (--distro);
every other variable stays unknown, and so does ROS_DISTRO once the launch sets it."""

XML = """<launch>
  <node pkg="demo" exec="humble_only" name="humble_only" if="$(equals $(env ROS_DISTRO) humble)"/>
  <node pkg="demo" exec="other" name="other" unless="$(equals $(env ROS_DISTRO) humble)"/>
  <node pkg="demo" exec="home" name="home" if="$(equals $(env HOME) /root)"/>
</launch>
"""
PY = """
from launch import LaunchDescription
from launch.actions import OpaqueFunction, SetEnvironmentVariable
from launch.substitutions import EnvironmentVariable
from launch_ros.actions import Node

def setup(context):
    if EnvironmentVariable("ROS_DISTRO").perform(context) == "jazzy":
        return [Node(package="demo", executable="jazzy_only", name="jazzy_only")]
    return [Node(package="demo", executable="not_jazzy", name="not_jazzy")]

def generate_launch_description():
    return LaunchDescription([
        OpaqueFunction(function=setup),
        SetEnvironmentVariable("ROS_DISTRO", "rolling"),
        OpaqueFunction(function=setup),
    ])
"""


def _active(nodes):
    return {name: n["active"] for name, n in nodes.items()}


def test_env_ros_distro_in_xml(demo_graph):
    files = {"launch/a.launch.xml": XML}
    assert _active(demo_graph(files, "launch/a.launch.xml", distro="humble")) == {
        "humble_only": True, "other": False, "home": "unknown"}
    assert _active(demo_graph(files, "launch/a.launch.xml", distro="jazzy")) == {
        "humble_only": False, "other": True, "home": "unknown"}


def test_environment_variable_in_python_until_the_launch_sets_it(tmp_path, demo_package):
    import json

    from physai_lint import api
    from physai_lint.engine import CheckOptions

    path = str(demo_package({"launch/b.launch.py": PY}) / "launch/b.launch.py")
    opts = CheckOptions(paths=[path], workspace=str(tmp_path), distro="jazzy")
    nodes = json.loads(api.graph(opts, path, "json"))["nodes"]
    got = sorted((n["name"], str(n["active"])) for n in nodes)
    # first OpaqueFunction: ROS_DISTRO is jazzy; after SetEnvironmentVariable it is not known
    assert got == [("jazzy_only", "True"), ("jazzy_only", "unknown"), ("not_jazzy", "False"), ("not_jazzy", "unknown")]
