"""L005 on ``from <launch module> import <name>`` that the distro's module does not have (the file
fails to load with ImportError): a class imported from the wrong module, or one a later distro
added. Not inside a try with handlers (a compatibility fallback), not on distros whose exports are
not known (rolling), and not for a newer substitution class the file uses (L114 reports it there)."""
from __future__ import annotations

from pathlib import Path
from typing import Any

from physai_lint.engine import CheckOptions, run_check

LAUNCH = """from launch import LaunchDescription
from launch.substitutions import EqualsSubstitution, LaunchConfiguration
from launch_ros.actions import ComposableNode, Node
from launch_ros.actions import PushROSNamespace
from launch_ros.descriptions import ComposableNode as Component  # noqa: F401

try:
    from launch_ros.actions import SetROSLogDir
except ImportError:
    SetROSLogDir = None


def generate_launch_description():
    return LaunchDescription([
        Node(package='demo_nodes_cpp', executable='talker',
             condition=None if EqualsSubstitution is None else None),
    ])
"""


def _l005(tmp_path: Path, demo_package: Any, distro: str) -> list[tuple[int, str]]:
    pkg = demo_package({"launch/a.launch.py": LAUNCH})
    opts = CheckOptions(paths=[str(pkg / "launch/a.launch.py")], workspace=str(tmp_path), distro=distro,
                        cache=False)
    return sorted((f.span.line, f.message.split(";")[0]) for f in run_check(opts).findings if f.code == "L005")


def test_imports_the_distro_does_not_have(tmp_path: Path, demo_package: Any) -> None:
    assert _l005(tmp_path, demo_package, "humble") == [
        (2, 'launch.substitutions has no "EqualsSubstitution" in humble (jazzy has it)'),
        (3, 'launch_ros.actions has no "ComposableNode" in humble (it is in launch_ros.descriptions)'),
        (4, 'launch_ros.actions has no "PushROSNamespace" in humble (jazzy has it)'),
    ]


def test_jazzy_has_them_but_not_the_misplaced_class(tmp_path: Path, demo_package: Any) -> None:
    assert _l005(tmp_path, demo_package, "jazzy") == [
        (3, 'launch_ros.actions has no "ComposableNode" in jazzy (it is in launch_ros.descriptions)')]


def test_rolling_is_not_checked(tmp_path: Path, demo_package: Any) -> None:
    assert _l005(tmp_path, demo_package, "rolling") == []


STAR = """from launch import LaunchDescription
from launch.actions import *


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('robot', default_value='r1'),
        Node(package='demo_nodes_cpp', executable='talker'),
    ])
"""


def test_a_star_import_of_a_launch_module_binds_only_what_it_exports(demo_findings):
    # launch.actions has DeclareLaunchArgument, not Node (launch_ros.actions): NameError
    found = demo_findings({"launch/a.launch.py": STAR}, "launch/a.launch.py", "L005")
    assert [(line, msg.split(";")[0]) for line, msg in found] == [
        (8, 'name "Node" is used but never imported or defined')]


def test_a_star_import_of_another_module_may_bind_anything(demo_findings):
    text = STAR.replace("from launch.actions import *", "from launch.actions import *\nfrom my_helpers import *")
    assert demo_findings({"launch/a.launch.py": text}, "launch/a.launch.py", "L005") == []


STAR_READ = """from launch import LaunchDescription
from launch.actions import *
from launch.substitutions import *
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('max_tension', default_value='10'),
        Node(package='demo_nodes_cpp', executable='talker', arguments=[LaunchConfiguration('max_tension_n')]),
    ])
"""


def test_classes_a_star_import_binds_are_evaluated(demo_findings):
    # LaunchConfiguration comes from launch.substitutions' star import: the misspelt read is seen
    files = {"launch/a.launch.py": STAR_READ}
    assert [line for line, _ in demo_findings(files, "launch/a.launch.py", "L101")] == [10]
    assert [line for line, _ in demo_findings(files, "launch/a.launch.py", "L102")] == [9]
