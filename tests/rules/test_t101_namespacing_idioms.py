"""T101 (identity-remap) reports a rule that maps a name to itself for every node it reaches, in
every launch, whatever the launch arguments. The namespacing idioms are silent: ``('/tf', 'tf')``
and ``('scan', '/scan')`` only meet while the namespace is empty, and a side or a namespace taken
from a launch argument is written for the values the argument is there to take."""
from __future__ import annotations

NAV2_IDIOM = """
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, GroupAction
from launch.conditions import IfCondition
from launch.substitutions import LaunchConfiguration, NotEqualsSubstitution
from launch_ros.actions import Node, PushROSNamespace


def generate_launch_description():
    namespace = LaunchConfiguration('namespace')
    remappings = [('/tf', 'tf'), ('/tf_static', 'tf_static')]
    return LaunchDescription([
        DeclareLaunchArgument('namespace', default_value=''),
        GroupAction([
            PushROSNamespace(condition=IfCondition(NotEqualsSubstitution(namespace, '')),
                             namespace=namespace),
            Node(package='demo', executable='talker', name='a', remappings=remappings),
            Node(package='demo', executable='talker', name='b', namespace=namespace,
                 remappings=[('scan', '/scan')]),
        ]),
    ])
"""

FIXED = """
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('ns', default_value='robot1'),
        Node(package='demo', executable='talker', name='same_text',
             remappings=[('cmd_vel', 'cmd_vel')]),
        Node(package='demo', executable='talker', name='spelled_twice', namespace='robot1',
             remappings=[('scan', '/robot1/scan')]),
        Node(package='demo', executable='talker', name='from_argument', namespace=LaunchConfiguration('ns'),
             remappings=[('odom', '/robot1/odom')]),
        Node(package='demo', executable='talker', name='root', remappings=[('map', '/map')]),
    ])
"""

XML_ARGUMENT = """<launch>
  <arg name="input" default="/input"/>
  <arg name="output" default="output"/>
  <node pkg="demo" exec="talker" name="filter">
    <remap from="input" to="$(var input)"/>
    <remap from="$(var output)" to="output"/>
  </node>
</launch>
"""

INCLUDED = """<launch>
  <node pkg="demo" exec="talker" name="driver">
    <remap from="scan" to="/r1/scan"/>
  </node>
</launch>
"""


def _includer(namespaces: list[str]) -> str:
    groups = "".join(f"""  <group>
    <push-ros-namespace namespace="{ns}"/>
    <include file="$(find-pkg-share demo)/launch/driver.launch.xml"/>
  </group>
""" for ns in namespaces)
    return f"<launch>\n{groups}</launch>\n"


def test_the_nav2_namespacing_idioms_are_silent(demo_findings) -> None:
    assert demo_findings({"launch/a.launch.py": NAV2_IDIOM}, "launch/a.launch.py", "T101") == []


def test_identities_the_launch_file_fixes_are_reported(demo_findings) -> None:
    found = demo_findings({"launch/a.launch.py": FIXED}, "launch/a.launch.py", "T101")
    assert [line for line, _ in found] == [12, 14]
    assert found[0][1] == 'remap "cmd_vel" -> "cmd_vel" maps a name to itself'
    assert found[1][1] == 'remap "scan" -> "/robot1/scan" maps a name to itself'


def test_sides_from_launch_arguments_are_silent(demo_findings) -> None:
    assert demo_findings({"launch/a.launch.xml": XML_ARGUMENT}, "launch/a.launch.xml", "T101") == []


def test_a_rule_is_reported_only_when_every_include_makes_it_an_identity(demo_findings) -> None:
    files = {"launch/driver.launch.xml": INCLUDED, "launch/one.launch.xml": _includer(["r1"]),
             "launch/two.launch.xml": _includer(["r1", "r2"])}
    assert [line for line, _ in demo_findings(files, "launch/one.launch.xml", "T101")] == [3]
    assert demo_findings(files, "launch/two.launch.xml", "T101") == []
