"""Reads an OpaqueFunction makes that reach no action are still reads (L102): a looked-up value
only compared (``context.launch_configurations.get('use_sim_time', 'false') == 'true'``), and a
membership test (``'robot_name' in context.launch_configurations``), which the resolver decides
where it knows the configuration is set."""
LAUNCH = """from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, OpaqueFunction
from launch_ros.actions import Node


def launch_setup(context, *args, **kwargs):
    sim = context.launch_configurations.get('use_sim_time', 'false')
    nodes = [Node(package='demo_nodes_cpp', executable='talker', name='talker',
                  parameters=[{'use_sim_time': sim == 'true'}])]
    if 'robot_name' in context.launch_configurations:
        nodes.append(Node(package='demo_nodes_cpp', executable='listener', name='listener'))
    if 'never_set' not in context.launch_configurations:
        nodes.append(Node(package='demo_nodes_cpp', executable='listener', name='maybe'))
    return nodes


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('use_sim_time', default_value='false'),
        DeclareLaunchArgument('robot_name', default_value='r1'),
        DeclareLaunchArgument('unused', default_value='1'),
        OpaqueFunction(function=launch_setup),
    ])
"""


def test_compared_and_tested_configurations_are_read(demo_findings):
    found = demo_findings({"launch/a.launch.py": LAUNCH}, "launch/a.launch.py", "L102")
    assert found == [(21, 'launch argument "unused" is declared but never read')]


def test_a_membership_test_is_decided_where_the_configuration_is_set(demo_graph):
    nodes = demo_graph({"launch/a.launch.py": LAUNCH}, "launch/a.launch.py")
    assert nodes["listener"]["active"] is True
    assert nodes["maybe"]["active"] == "unknown"  # not known to be unset: not known to start


SETS = """import os
from launch import LaunchDescription
from launch.actions import OpaqueFunction
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def setup(context):
    context.launch_configurations['calib_file'] = os.path.join('/opt', 'calib.yaml')
    return [Node(package='demo_nodes_cpp', executable='talker', name='talker',
                 arguments=[LaunchConfiguration('calib_file')])]


def generate_launch_description():
    return LaunchDescription([
        OpaqueFunction(function=setup),
        Node(package='demo_nodes_cpp', executable='listener', name='listener',
             arguments=[LaunchConfiguration('calib_file')]),
    ])
"""


def test_a_configuration_stored_into_the_context_is_set(demo_findings, demo_graph):
    # launch's context hands out the live mapping: a store is a SetLaunchConfiguration
    assert demo_findings({"launch/a.launch.py": SETS}, "launch/a.launch.py", "L101") == []
    nodes = demo_graph({"launch/a.launch.py": SETS}, "launch/a.launch.py")
    assert nodes["listener"]["arguments"] == ["/opt/calib.yaml"]
