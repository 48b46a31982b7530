"""Python launch code that works on values only launch knows: a declared argument's ``.name`` is
its literal name (every argument read back by name is read), and a recursive helper walking data
not known statically (a flatten of a YAML file read at launch) is one unknown value, not an
exponential walk of every branch that runs out the step budget and loses the node after it."""
from __future__ import annotations

READ_BACK = """
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, OpaqueFunction
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def make(context, args):
    params = {a.name: LaunchConfiguration(a.name).perform(context) for a in args}
    return [Node(package='demo', executable='talker', parameters=[params])]


def generate_launch_description():
    args = [DeclareLaunchArgument('width', default_value='640'),
            DeclareLaunchArgument('height', default_value='480')]
    return LaunchDescription(args + [OpaqueFunction(function=lambda context: make(context, args))])
"""
FLATTEN = """
import yaml
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, OpaqueFunction
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def flatten(data, prefix='', params=None):
    if params is None:
        params = {}
    if isinstance(data, dict):
        for key, value in data.items():
            params = flatten(value, prefix=f'{key}.' if prefix else key + '.', params=params)
    elif isinstance(data, list):
        for index, item in enumerate(data):
            params = flatten(item, prefix=f'[{index}].', params=params)
    else:
        params[prefix[:-1]] = data
    return params


def make(context):
    with open(LaunchConfiguration('config').perform(context)) as f:
        params = flatten(yaml.safe_load(f))
    return [Node(package='demo', executable='talker', name='talker', parameters=[params]),
            Node(package='demo', executable='listener', name='listener')]


def generate_launch_description():
    return LaunchDescription([DeclareLaunchArgument('config', default_value='/tmp/x.yaml'),
                              OpaqueFunction(function=make)])
"""


def test_arguments_read_back_by_their_name_are_read(demo_findings) -> None:
    assert demo_findings({"launch/a.launch.py": READ_BACK}, "launch/a.launch.py", "L102") == []


def test_a_recursive_walk_of_unknown_data_keeps_the_nodes(demo_graph) -> None:
    nodes = demo_graph({"launch/a.launch.py": FLATTEN}, "launch/a.launch.py")
    # the walk is one unknown value: the nodes built after it are there
    assert sorted(nodes) == ["listener", "talker"]
