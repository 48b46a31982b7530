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


MOVEIT = """
from launch import LaunchDescription
from launch.actions import OpaqueFunction
from launch_ros.actions import Node
from moveit_configs_utils import MoveItConfigsBuilder
from moveit_configs_utils.moveit_configs_builder import MoveItConfigsBuilder as Builder


def later(context):
    MoveItConfigsBuilder('gone_in_function').to_moveit_configs()
    return []


def generate_launch_description():
    arm = MoveItConfigsBuilder('arm').robot_description(file_path='config/arm.urdf.xacro').to_moveit_configs()
    named = Builder('ignored', package_name='missing_named_config').to_dict()
    fine = MoveItConfigsBuilder('anything', 'robot_description', 'demo').to_moveit_configs()
    released = MoveItConfigsBuilder('moveit_resources_panda').to_moveit_configs()
    return LaunchDescription([
        OpaqueFunction(function=later),
        Node(package='moveit_ros_move_group', executable='move_group', parameters=[arm.to_dict()]),
    ])
"""


def test_moveit_configs_builder_looks_its_package_up(demo_findings):
    # MoveItConfigsBuilder.__init__ -> ParameterBuilder.__init__: get_package_share_directory of
    # package_name, else of robot_name + "_moveit_config", when the builder is made
    found = demo_findings({"launch/m.launch.py": MOVEIT}, "launch/m.launch.py", "U101")
    assert [(line, msg.split(" is not")[0]) for line, msg in found] == [
        (15, 'package "arm_moveit_config"'),
        (16, 'package "missing_named_config"'),
    ]
