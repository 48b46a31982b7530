"""L109: a refused condition value is reported where the condition is written (the
LaunchConfiguration it reads may be made lines before, and used elsewhere too); the boolean
substitutions type their operands with yaml.safe_load (type_utils.coerce_to_type), not like
IfCondition."""
from __future__ import annotations

from typing import Any

LAUNCH = """from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, LogInfo
from launch.conditions import IfCondition
from launch.substitutions import LaunchConfiguration, NotSubstitution
from launch_ros.actions import PushRosNamespace


def generate_launch_description():
    flag = LaunchConfiguration('flag')
    return LaunchDescription([
        DeclareLaunchArgument('flag', default_value='VALUE'),
        PushRosNamespace(namespace='robot', condition=IfCondition(CONDITION)),
        LogInfo(msg=flag),
    ])
"""


def run(demo_findings: Any, value: str, condition: str) -> list[tuple[int, str]]:
    text = LAUNCH.replace("VALUE", value).replace("CONDITION", condition)
    return demo_findings({"launch/a.launch.py": text}, "launch/a.launch.py", "L109")


def test_reported_at_the_condition_not_where_the_configuration_is_made(demo_findings: Any) -> None:
    assert [line for line, _ in run(demo_findings, "", "flag")] == [12]


def test_boolean_substitutions_take_yaml_booleans(demo_findings: Any) -> None:
    assert run(demo_findings, "yes", "NotSubstitution(flag)") == []  # YAML's true
    assert run(demo_findings, "1", "flag") == []  # IfCondition's true
    (line, msg), = run(demo_findings, "1", "NotSubstitution(flag)")
    assert line == 12 and msg.startswith('NotSubstitution ($(not)) gets "1", which is not a YAML boolean')


RESPAWN = """from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, ExecuteProcess
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    use_respawn = LaunchConfiguration('use_respawn')
    return LaunchDescription([
        DeclareLaunchArgument('use_respawn', default_value='VALUE'),
        Node(package='demo', executable='driver', name='driver',
             respawn=use_respawn),
        ExecuteProcess(cmd=['sleep', '1'], respawn=use_respawn),
    ])
"""

RESPAWN_XML = """<launch>
  <arg name="use_respawn" default="VALUE"/>
  <node pkg="demo" exec="driver" name="driver" respawn="$(var use_respawn)"/>
  <executable cmd="sleep 1" respawn="$(var use_respawn)"/>
</launch>
"""


def test_respawn_takes_a_yaml_boolean_when_the_process_starts(demo_findings: Any) -> None:
    # ExecuteLocal: perform_typed_substitution(context, respawn, bool) -> ValueError for '0' / '1'
    for value, lines in (("0", [12, 13]), ("1", [12, 13]), ("maybe", [12, 13]), ("", [12, 13]),
                         ("true", []), ("False", []), ("yes", [])):
        found = demo_findings({"launch/a.launch.py": RESPAWN.replace("VALUE", value)}, "launch/a.launch.py", "L109")
        assert [line for line, _ in found] == lines, value
        xml = demo_findings({"launch/a.launch.xml": RESPAWN_XML.replace("VALUE", value)}, "launch/a.launch.xml",
                            "L109")
        assert [line for line, _ in xml] == [line - 9 for line in lines], value
    (_, msg), _ = demo_findings({"launch/a.launch.py": RESPAWN.replace("VALUE", "0")}, "launch/a.launch.py", "L109")
    assert msg.startswith('respawn gets "0", which is not a YAML boolean (true/false, yes/no, on/off); launch types '
                          "it with yaml.safe_load when it starts the process")


def test_a_respawn_bool_literal_is_typed_already(demo_findings: Any) -> None:
    text = RESPAWN.replace("respawn=use_respawn", "respawn=True").replace("VALUE", "0")
    assert demo_findings({"launch/a.launch.py": text}, "launch/a.launch.py", "L109") == []



def test_a_respawn_string_literal_fails_when_the_action_is_built(demo_findings: Any) -> None:
    # normalize_typed_substitution: a str is a scalar, and not a bool -> TypeError in Node()
    text = RESPAWN.replace("respawn=use_respawn),", "respawn='true'),").replace("VALUE", "true")
    assert demo_findings({"launch/a.launch.py": text}, "launch/a.launch.py", "L109") == []
    found = demo_findings({"launch/a.launch.py": text}, "launch/a.launch.py", "L008")
    assert [line for line, _ in found] == [12, 13]  # the Node and the ExecuteProcess
    assert found[0][1].startswith("Node(respawn=...) is given 'true', a string: launch accepts only a bool or "
                              "substitutions there (normalize_typed_substitution)")
