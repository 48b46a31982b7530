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


# A parameter file loaded with allow_substs has its $(var ...) performed by launch_ros: when its
# path is not known here (an includer's argument), it may read any configuration (autoware's
# pose_initializer.param.yaml reads user_defined_initial_pose/enable, which the includer passes).
INNER_XML = """<launch>
  <arg name="config_file" default="$(find-pkg-share demo)/config/p.param.yaml"/>
  <node pkg="demo" exec="talker" name="talker">
    <param from="$(var config_file)" allow_substs="true"/>
  </node>
</launch>
"""
PARAMS = "/**:\n  ros__parameters:\n    enable: $(var feature/enable)\n"


def _outer_xml(extra: str) -> str:
    return f"""<launch>
  <arg name="param_path"/>
  <include file="$(find-pkg-share demo)/launch/inner.launch.xml">
    <arg name="feature/enable" value="true"/>
    <arg name="typo" value="1"/>
{extra}  </include>
</launch>
"""


def test_an_allow_substs_file_of_unknown_path_may_read_any_argument(demo_findings) -> None:
    found = demo_findings({"launch/inner.launch.xml": INNER_XML, "config/p.param.yaml": PARAMS,
                           "launch/outer.launch.xml": _outer_xml(
                               '    <arg name="config_file" value="$(var param_path)"/>\n')},
                          "launch/outer.launch.xml", "L106")
    assert found == []


def test_a_known_allow_substs_file_reads_only_what_it_names(demo_findings) -> None:
    found = demo_findings({"launch/inner.launch.xml": INNER_XML, "config/p.param.yaml": PARAMS,
                           "launch/outer.launch.xml": _outer_xml("")},
                          "launch/outer.launch.xml", "L106")
    assert [m.split(" is passed")[0] for _, m in found] == ['argument "typo"']


def test_python_parameter_file_with_allow_substs_of_unknown_path(demo_findings) -> None:
    child = """from launch.actions import DeclareLaunchArgument
from launch_ros.parameter_descriptions import ParameterFile


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('params'),
        DeclareLaunchArgument('unused_here'),
        Node(package='demo', executable='talker',
             parameters=[ParameterFile(LaunchConfiguration('params'), allow_substs=True)]),
    ])
"""
    assert _l106(demo_findings, child, "{'params': LaunchConfiguration('p'), 'x': '1'}") == []
    assert demo_findings({"launch/child.launch.py": HEAD + child}, "launch/child.launch.py", "L102") == []


def test_l102_an_unknown_allow_substs_file_reads_along_its_chain_only(demo_findings) -> None:
    """The includer's argument may be what the file reads (configurations are not scoped by
    includes); a sibling file's unused argument is still reported."""
    outer = """<launch>
  <arg name="param_path"/>
  <arg name="feature_enable" default="true"/>
  <include file="$(find-pkg-share demo)/launch/inner.launch.xml">
    <arg name="config_file" value="$(var param_path)"/>
  </include>
  <include file="$(find-pkg-share demo)/launch/sibling.launch.xml"/>
</launch>
"""
    sibling = '<launch>\n  <arg name="never_read" default="1"/>\n</launch>\n'
    found = demo_findings({"launch/inner.launch.xml": INNER_XML, "launch/sibling.launch.xml": sibling,
                           "launch/outer.launch.xml": outer}, "launch/outer.launch.xml", "L102")
    assert [m for _, m in found] == ['launch argument "never_read" is declared but never read']


def test_a_long_list_of_arguments_is_cut_short(demo_findings) -> None:
    # Autoware's perception.launch.xml declares or reads some 400 names: the message lists a
    # dozen, counts the rest, and the did-you-mean hint still searches all of them
    names = [f"arg_{i:02d}" for i in range(30)]
    declares = "".join(f"    DeclareLaunchArgument('{n}', default_value='x'),\n" for n in names)
    child = f"""from launch.actions import DeclareLaunchArgument


def generate_launch_description():
    return LaunchDescription([
{declares}    ])
"""
    found = _l106(demo_findings, child, "{'arg_29x': 'y'}")
    assert [m for _, m in found] == [
        'argument "arg_29x" is passed to "child.launch.py", which never declares or reads it (it declares or reads '
        + ", ".join(f'"{n}"' for n in names[:12]) + ' and 18 more); the value is silently ignored; '
        'did you mean "arg_29" or "arg_28" or "arg_27"?']
