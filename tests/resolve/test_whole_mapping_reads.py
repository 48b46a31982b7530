"""L102 unused-argument and reads the linter cannot see one by one: code that iterates, copies or
hands on ``context.launch_configurations`` reads every configuration, and nav2_common's
ParseMultiRobotPose("robots") takes ``robots:=`` from the command line itself."""
import pytest

OPAQUE = """
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, OpaqueFunction
from launch_ros.actions import Node
from some_helpers import helper


def setup(context):
    {body}


def generate_launch_description():
    return LaunchDescription([DeclareLaunchArgument("rate", default_value="10"),
                              OpaqueFunction(function=setup)])
"""

MULTI = """
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch_ros.actions import Node
from nav2_common.launch import ParseMultiRobotPose


def generate_launch_description():
    robots = ParseMultiRobotPose("robots").value()
    nodes = []
    for name in robots:
        nodes.append(Node(package="demo_nodes_cpp", executable="talker", namespace=name))
    return LaunchDescription([DeclareLaunchArgument("robots", default_value=""), *nodes])
"""


def _l102(demo_findings, text: str, **more: str) -> list[str]:
    files = {"launch/a.launch.py": text, **{f"launch/{name}.launch.py": t for name, t in more.items()}}
    return [message for _, message in demo_findings(files, "launch/a.launch.py", "L102")]


@pytest.mark.parametrize("body", [
    'return [Node(package="demo_nodes_cpp", executable="talker", parameters=[dict(context.launch_configurations)])]',
    "for name, value in context.launch_configurations.items():\n        print(name, value)",
    "for name in context.launch_configurations:\n        print(name)",
    "helper(context.launch_configurations)",
    "helper(**context.launch_configurations)",
    "print({**context.launch_configurations})",
    "print(context.launch_configurations[helper()])",
])
def test_the_whole_launch_configurations_mapping_reads_every_argument(demo_findings, body):
    assert _l102(demo_findings, OPAQUE.format(body=body)) == []


def test_a_whole_mapping_read_in_an_included_file_reads_the_includers_arguments(demo_findings):
    child = OPAQUE.format(body="print(dict(context.launch_configurations))").replace(
        'DeclareLaunchArgument("rate", default_value="10"), ', "")
    parent = """
import os
from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource


def generate_launch_description():
    child = os.path.join(get_package_share_directory("demo"), "launch", "child.launch.py")
    return LaunchDescription([DeclareLaunchArgument("rate", default_value="10"),
                              IncludeLaunchDescription(PythonLaunchDescriptionSource(child))])
"""
    assert _l102(demo_findings, parent, child=child) == []


def test_a_single_other_read_still_leaves_it_unused(demo_findings):
    body = 'print(context.launch_configurations.get("other"))'
    assert _l102(demo_findings, OPAQUE.format(body=body)) == [
        'launch argument "rate" is declared but never read']


def test_parse_multi_robot_pose_reads_its_argument(demo_findings):
    assert _l102(demo_findings, MULTI) == []


def test_parse_multi_robot_pose_given_a_substitution_reads_it(demo_findings):
    text = MULTI.replace('ParseMultiRobotPose("robots")', 'ParseMultiRobotPose(LaunchConfiguration("robots"))')
    text = text.replace("from launch.actions import DeclareLaunchArgument",
                        "from launch.actions import DeclareLaunchArgument\nfrom launch.substitutions import LaunchConfiguration")
    assert _l102(demo_findings, text) == []
