"""L106 (include-undeclared-argument) counts every read of the included file the linter cannot
rule out: a configuration handed to a helper it cannot follow (which reads it at launch), the
default of another configuration, and the operands after an undecided one in ``and``/``or``."""
from __future__ import annotations

TOP = """
from launch import LaunchDescription
from launch.actions import IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import PathJoinSubstitution
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    return LaunchDescription([
        IncludeLaunchDescription(
            PythonLaunchDescriptionSource(
                PathJoinSubstitution([FindPackageShare('demo'), 'launch', 'child.launch.py'])),
            launch_arguments={ARGS}.items()),
    ])
"""
HEAD = """
from launch import LaunchDescription
from launch.actions import OpaqueFunction
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node
"""


def _l106(demo_findings, child: str, args: str) -> list[tuple[int, str]]:
    return demo_findings({"launch/top.launch.py": TOP.replace("{ARGS}", args),
                          "launch/child.launch.py": HEAD + child}, "launch/top.launch.py", "L106")


def test_a_configuration_given_to_a_helper_is_read(demo_findings) -> None:
    child = """from my_helpers import build_description


def generate_launch_description():
    desc = build_description({'limited': LaunchConfiguration('limited', default='false')})
    return LaunchDescription([Node(package='demo', executable='talker',
                                   parameters=[{'robot_description': desc}])])
"""
    found = _l106(demo_findings, child, "{'limited': 'true', 'typo': '1'}")
    assert [m.split(" is passed")[0] for _, m in found] == ['argument "typo"']


def test_the_default_of_a_configuration_given_to_a_helper_is_read(demo_findings) -> None:
    child = """from my_helpers import build_description


def setup(context):
    dof_1 = LaunchConfiguration('dof_1', default=LaunchConfiguration('dof', default='7'))
    return [Node(package='demo', executable='talker',
                 parameters=[{'robot_description': build_description({'dof': dof_1})}])]


def generate_launch_description():
    return LaunchDescription([OpaqueFunction(function=setup)])
"""
    assert _l106(demo_findings, child, "{'dof': '6'}") == []


def test_an_operand_after_an_undecided_one_is_read(demo_findings) -> None:
    child = """

def setup(context):
    add = LaunchConfiguration('add_gripper', default='false')
    use = LaunchConfiguration('use_gripper_node', default='true')
    nodes = [Node(package='demo', executable='talker')]
    if add.perform(context) in ('True', 'true') and use.perform(context) in ('True', 'true'):
        nodes.append(Node(package='demo', executable='listener'))
    return nodes


def generate_launch_description():
    return LaunchDescription([OpaqueFunction(function=setup)])
"""
    assert _l106(demo_findings, child, "{'add_gripper': 'true', 'use_gripper_node': 'false'}") == []
