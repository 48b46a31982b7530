"""L101 and the entry's required arguments: ``ros2 launch`` refuses to run the file unless each
unconditional argument without a default is given, so reading one before its declaration is not
"undefined" in any run that gets that far. An optional one read early still is."""
from __future__ import annotations

from typing import Any

LAUNCH = """from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, LogInfo
from launch.substitutions import LaunchConfiguration


def generate_launch_description():
    return LaunchDescription([
        LogInfo(msg=LaunchConfiguration('map_file')),
        LogInfo(msg=LaunchConfiguration('rate')),
        DeclareLaunchArgument('map_file'),
        DeclareLaunchArgument('rate', default_value='10'),
    ])
"""


def test_a_required_argument_of_the_entry_is_set_before_its_declaration(demo_findings: Any) -> None:
    found = demo_findings({"launch/a.launch.py": LAUNCH}, "launch/a.launch.py", "L101")
    assert [(line, m.split(" ")[2]) for line, m in found] == [(9, '"rate"')]
