"""L108: LaunchConfigurationEquals of a configuration no launch file declares, sets or passes is
never true (launch's _predicate_func compares the unset configuration instead of raising)."""
from __future__ import annotations

from typing import Any

LAUNCH = """from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, LogInfo
from launch.conditions import LaunchConfigurationEquals, LaunchConfigurationNotEquals


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('mode', default_value='localization', choices=['mapping', 'localization']),
        LogInfo(msg='localizing', condition=LaunchConfigurationEquals(NAME, 'localization')),
        LogInfo(msg='not mapping', condition=LaunchConfigurationNotEquals('slam_mode', 'mapping')),
    ])
"""


def test_a_misspelt_name_is_never_equal(demo_findings: Any) -> None:
    found = demo_findings({"launch/a.launch.py": LAUNCH.replace("NAME", "'slam_mode'")}, "launch/a.launch.py", "L108")
    assert [(line, msg.split(",")[0]) for line, msg in found] == [
        (9, 'LaunchConfigurationEquals(...) compares launch configuration "slam_mode"')]
    assert found[0][1].endswith('did you mean "mode"?')


def test_the_declared_name_is_fine(demo_findings: Any) -> None:
    assert demo_findings({"launch/a.launch.py": LAUNCH.replace("NAME", "'mode'")}, "launch/a.launch.py", "L108") == []


def test_expected_none_asks_whether_it_is_unset(demo_findings: Any) -> None:
    text = LAUNCH.replace("NAME, 'localization'", "'robot_ns', None")
    assert demo_findings({"launch/a.launch.py": text}, "launch/a.launch.py", "L108") == []
