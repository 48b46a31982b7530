"""graph JSON says when a node's parameters are not fully known, instead of implying it gets none."""

LAUNCH = """
from launch import LaunchDescription
from launch_ros.actions import Node
from mystuff import make_params

def generate_launch_description():
    return LaunchDescription([
        Node(package="demo", executable="a", name="known", parameters=[{"rate": 5.0}]),
        Node(package="demo", executable="a", name="opaque", parameters=[{"rate": 5.0}, make_params()]),
    ])
"""


def test_unknown_parameter_source_marks_parameters_incomplete(demo_graph):
    by_name = demo_graph({"launch/a.launch.py": LAUNCH}, "launch/a.launch.py")
    assert by_name["known"]["parameters"] == {"rate": 5.0}
    assert by_name["known"]["parameters_complete"] is True
    assert by_name["opaque"]["parameters_complete"] is False
    # the value written in the launch file is still shown; parameters_complete says it may be overridden
    assert by_name["opaque"]["parameters"] == {"rate": 5.0}
