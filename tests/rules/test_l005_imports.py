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
        (2, 'launch.substitutions has no "EqualsSubstitution" in humble (it was added in jazzy)'),
        (3, 'launch_ros.actions has no "ComposableNode" in humble (it is in launch_ros.descriptions)'),
        (4, 'launch_ros.actions has no "PushROSNamespace" in humble (it was added in jazzy)'),
    ]


def test_jazzy_has_them_but_not_the_misplaced_class(tmp_path: Path, demo_package: Any) -> None:
    assert _l005(tmp_path, demo_package, "jazzy") == [
        (3, 'launch_ros.actions has no "ComposableNode" in jazzy (it is in launch_ros.descriptions)')]


def test_rolling_is_not_checked(tmp_path: Path, demo_package: Any) -> None:
    assert _l005(tmp_path, demo_package, "rolling") == []
