"""``.lower()`` / ``.upper()`` / ``.strip()`` of a launch-time string in a Python launch file are
applied at resolution time, so the usual ``perform(context).lower() == 'true'`` decides branches."""

LAUNCH = """
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, OpaqueFunction
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node

def setup(context):
    separate = LaunchConfiguration("separate").perform(context).strip().lower() == "true"
    robot = LaunchConfiguration("robot").perform(context).upper()
    if not separate:
        return [Node(package="demo", executable="together", name="together", namespace=robot)]
    return [Node(package="demo", executable="apart", name="apart", namespace=robot)]

def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument("separate", default_value=" False "),
        DeclareLaunchArgument("robot", default_value="r1"),
        OpaqueFunction(function=setup),
    ])
"""


def test_str_methods_of_launch_time_strings(demo_graph):
    files = {"launch/a.launch.py": LAUNCH}
    nodes = demo_graph(files, "launch/a.launch.py")
    assert {n: (x["active"], x["fqn"]) for n, x in nodes.items()} == {
        "together": (True, "/R1/together"), "apart": (False, "/R1/apart")}
    nodes = demo_graph(files, "launch/a.launch.py", separate="TRUE", robot="b2")
    assert {n: x["active"] for n, x in nodes.items()} == {"together": False, "apart": True}
