"""L101 stays silent where launch would not fail: a read after an action or include the linter
cannot follow (it may declare or set the configuration: includes and opaque functions do not
scope configurations), in execution order rather than line order; and a
LaunchConfigurationEquals of an unset configuration, which is false (true for expected_value
None), not an error. A read before such an action, or in a file without one, is still reported."""
from __future__ import annotations

OPAQUE = """from launch import LaunchDescription
from launch.actions import OpaqueFunction
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node

from vendor_helpers import get_end_effector


def declare_args(context, *args, **kwargs):
    return [get_end_effector('tiago')]


def generate_launch_description():
    return LaunchDescription([
        Node(package='demo_nodes_cpp', executable='listener', parameters=[{'a': LaunchConfiguration('before')}]),
        OpaqueFunction(function=declare_args),
        Node(package='demo_nodes_cpp', executable='talker', parameters=[{'b': LaunchConfiguration('after')}]),
    ])
"""
CALLBACK_AFTER_INCLUDE = """from launch import LaunchDescription
from launch.actions import IncludeLaunchDescription, OpaqueFunction
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution
from launch_ros.substitutions import FindPackageShare


def robot(context):
    address = LaunchConfiguration('sim_address').perform(context)
    return []


def generate_launch_description():
    sitl = IncludeLaunchDescription(PythonLaunchDescriptionSource(
        PathJoinSubstitution([FindPackageShare('sim_vendor_pkg'), 'launch', 'sitl.launch.py'])))
    return LaunchDescription([sitl, OpaqueFunction(function=robot)])
"""
EQUALS = """from launch import LaunchDescription
from launch.conditions import LaunchConfigurationEquals, LaunchConfigurationNotEquals
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='demo_nodes_cpp', executable='talker', name='a',
             condition=LaunchConfigurationEquals('end_effector', 'pal-gripper')),
        Node(package='demo_nodes_cpp', executable='talker', name='b',
             condition=LaunchConfigurationNotEquals('end_effector', None)),
    ])
"""


def test_after_an_opaque_action_in_execution_order(demo_findings):
    found = demo_findings({"launch/a.launch.py": OPAQUE}, "launch/a.launch.py", "L101")
    assert [(line, message.split(";")[0]) for line, message in found] == [
        (15, 'launch configuration "before" is read but never declared or set')]


def test_a_callback_written_above_the_include_runs_after_it(demo_findings):
    assert demo_findings({"launch/a.launch.py": CALLBACK_AFTER_INCLUDE}, "launch/a.launch.py", "L101") == []


def test_launch_configuration_equals_tolerates_an_unset_configuration(demo_findings, demo_graph):
    assert demo_findings({"launch/a.launch.py": EQUALS}, "launch/a.launch.py", "L101") == []
    nodes = demo_graph({"launch/a.launch.py": EQUALS}, "launch/a.launch.py")
    assert (nodes["a"]["active"], nodes["b"]["active"]) == (False, False)
    nodes = demo_graph({"launch/a.launch.py": EQUALS}, "launch/a.launch.py", end_effector="pal-gripper")
    assert (nodes["a"]["active"], nodes["b"]["active"]) == (True, True)
