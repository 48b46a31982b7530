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
