"""L102 unused-argument and reads the linter cannot see one by one: code that iterates, copies or
hands on ``context.launch_configurations`` reads every configuration, and nav2_common's
ParseMultiRobotPose("robots") takes ``robots:=`` from the command line itself."""
from physai_lint.engine import CheckOptions, run_check

OPAQUE = """
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, OpaqueFunction
from launch_ros.actions import Node


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


def _l102(tmp_path, demo_package, text: str) -> list[str]:
    pkg = demo_package({"launch/a.launch.py": text})
    report = run_check(CheckOptions(paths=[str(pkg / "launch/a.launch.py")], workspace=str(tmp_path),
                                    select=("L102",)), cwd=str(tmp_path))
    return [f.message for f in report.findings]


def test_the_whole_launch_configurations_mapping_reads_every_argument(tmp_path, demo_package):
    for body in ('return [Node(package="demo_nodes_cpp", executable="talker", '
                 'parameters=[dict(context.launch_configurations)])]',
                 "for name, value in context.launch_configurations.items():\n        print(name, value)",
                 "for name in context.launch_configurations:\n        print(name)"):
        assert _l102(tmp_path, demo_package, OPAQUE.format(body=body)) == [], body


def test_a_single_other_read_still_leaves_it_unused(tmp_path, demo_package):
    body = 'print(context.launch_configurations.get("other"))'
    assert _l102(tmp_path, demo_package, OPAQUE.format(body=body)) == [
        'launch argument "rate" is declared but never read']


def test_parse_multi_robot_pose_reads_its_argument(tmp_path, demo_package):
    assert _l102(tmp_path, demo_package, MULTI) == []
