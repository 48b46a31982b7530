"""L104 (missing-required-argument) on the entry file: a run that gives NAME:=VALUE arguments
describes one invocation, and a required argument of the launched file missing from them fails
it; a run without arguments leaves the entry's required arguments alone."""
from __future__ import annotations

from pathlib import Path

from physai_lint.engine import CheckOptions, run_check

LAUNCH = """
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, LogInfo
from launch.conditions import IfCondition
from launch.substitutions import LaunchConfiguration


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('map', description='map file'),
        DeclareLaunchArgument('use_sim_time', default_value='false'),
        DeclareLaunchArgument('robot', condition=IfCondition('false')),
        LogInfo(msg=LaunchConfiguration('map')),
    ])
"""


def _l104(tmp_path: Path, demo_package, **args: str) -> list[tuple[int, str]]:
    path = demo_package({"launch/a.launch.py": LAUNCH}) / "launch/a.launch.py"
    opts = CheckOptions(paths=[str(path)], workspace=str(tmp_path), cache=False, launch_args=args)
    return [(f.span.line, f.message) for f in run_check(opts).findings if f.code == "L104"]


def test_a_run_with_arguments_must_give_the_required_ones(tmp_path, demo_package) -> None:
    [(line, message)] = _l104(tmp_path, demo_package, use_sim_time="true")
    assert line == 10
    assert message.startswith('required argument "map" of the launched file is not among the '
                              "arguments of the run (given: use_sim_time)")


def test_a_run_giving_it_or_giving_nothing_is_silent(tmp_path, demo_package) -> None:
    assert _l104(tmp_path, demo_package, map="/maps/a.yaml") == []
    assert _l104(tmp_path, demo_package) == []
