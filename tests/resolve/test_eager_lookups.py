"""``get_package_share_directory('p')`` runs while the description is built: launch fails with
PackageNotFoundError when ``p`` does not exist, whether or not the path reaches an action (a URDF
read with ``open()``, an unused directory). Not when an ``except`` may catch it, in a branch the
linter cannot decide, or in a function launch calls later (an OpaqueFunction)."""
from __future__ import annotations

LAUNCH = """
import os
from ament_index_python.packages import PackageNotFoundError, get_package_share_directory
from launch import LaunchDescription
from launch.actions import OpaqueFunction
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare


def later(context):
    get_package_share_directory('missing_in_function')
    return []


def generate_launch_description():
    urdf = os.path.join(get_package_share_directory('missing_description'), 'urdf', 'robot.urdf')
    with open(urdf) as f:
        description = f.read()
    get_package_share_directory('demo')
    FindPackageShare('x').find('missing_found')
    try:
        get_package_share_directory('optional_driver')
    except PackageNotFoundError:
        pass
    if os.environ.get('WITH_GRIPPER'):
        get_package_share_directory('missing_gripper')
    return LaunchDescription([
        OpaqueFunction(function=later),
        Node(package='robot_state_publisher', executable='robot_state_publisher',
             parameters=[{'robot_description': description}]),
    ])
"""


def test_lookups_that_surely_run_are_checked(demo_findings):
    found = demo_findings({"launch/a.launch.py": LAUNCH}, "launch/a.launch.py", "U101")
    assert [(line, msg.split(" is not")[0]) for line, msg in found] == [
        (16, 'package "missing_description"'),
        (20, 'package "missing_found"'),
    ]
