"""L104 missing-required-argument needs the names an include passes: launch_arguments that cannot
be known (computed from a file read at launch, forwarded from ``context.launch_configurations``)
may pass any name, so nothing is reported; arguments known to leave one out still are."""

INNER = """
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument("robot_ip"),
        Node(package="demo_nodes_cpp", executable="talker", arguments=[LaunchConfiguration("robot_ip")]),
    ])
"""

OUTER = """
import os
import yaml
from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource


def generate_launch_description():
    share = get_package_share_directory("demo")
    with open(os.path.join(share, "config", "robot.yaml")) as f:
        robot = yaml.safe_load(f)
    return LaunchDescription([IncludeLaunchDescription(
        PythonLaunchDescriptionSource(os.path.join(share, "launch", "inner.launch.py")),
        launch_arguments={ARGS}.items())])
"""


def _l104(demo_findings, outer: str) -> list[str]:
    files = {"launch/inner.launch.py": INNER, "launch/outer.launch.py": outer,
             "config/robot.yaml": "robot_ip: 10.0.0.1\n"}
    return [message for _, message in demo_findings(files, "launch/outer.launch.py", "L104")]


def test_arguments_read_from_a_file_at_launch_may_pass_any_name(demo_findings):
    assert _l104(demo_findings, OUTER.replace("{ARGS}", "{k: str(v) for k, v in robot.items()}")) == []


def test_known_arguments_that_leave_one_out_are_reported(demo_findings):
    assert [m.split(";")[0] for m in _l104(demo_findings, OUTER.replace("{ARGS}", '{"port": "22"}'))] == [
        'include of "inner.launch.py" does not pass required argument "robot_ip" (given: port)']


FORWARD = """
import os
from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, IncludeLaunchDescription, OpaqueFunction
from launch.launch_description_sources import PythonLaunchDescriptionSource


def setup(context):
    share = get_package_share_directory("demo")
    return [IncludeLaunchDescription(
        PythonLaunchDescriptionSource(os.path.join(share, "launch", "inner.launch.py")),
        launch_arguments=context.launch_configurations.items())]


def generate_launch_description():
    return LaunchDescription([DeclareLaunchArgument("robot_ip", default_value="10.0.0.1"),
                              OpaqueFunction(function=setup)])
"""


def test_forwarded_launch_configurations_may_pass_any_name(demo_findings):
    assert _l104(demo_findings, FORWARD) == []
