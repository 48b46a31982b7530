"""launch_testing files (``generate_test_description``, run by ``launch_test``) are resolved like
launch files: the description they return (alone or first of a (description, context) tuple) is
checked, ReadyToTest starts nothing, and their package's <test_depend>s count for U103."""
from __future__ import annotations

from pathlib import Path
from typing import Any

TEST = """import unittest

import launch
import launch_testing.actions
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_test_description({params}):
    talker = Node(package="demo_nodes_cpp", executable="talker",
                  parameters=[{{"rate": LaunchConfiguration("rate")}}])
    checker = Node(package="tf2_ros", executable="static_transform_publisher",
                   arguments=["0", "0", "0", "0", "0", "0", "a", "b"])
    return launch.LaunchDescription([
        talker, checker,
        launch_testing.actions.ReadyToTest(),
    ]), {{"talker": talker}}


class TestTalker(unittest.TestCase):
    def test_runs(self, proc_info, talker):
        proc_info.assertWaitForStartup(process=talker, timeout=5)
"""
PACKAGE_XML = """<package format="3"><name>demo</name><version>0.0.0</version><description>d</description>
<maintainer email="m@example.com">a</maintainer><license>MIT</license>
<exec_depend>demo_nodes_cpp</exec_depend>
<test_depend>tf2_ros</test_depend>
<export><build_type>ament_cmake</build_type></export></package>
"""


def _check(tmp_path: Path, demo_package: Any, name: str, text: str) -> list[Any]:
    from physai_lint.engine import CheckOptions, run_check

    pkg = demo_package({"package.xml": PACKAGE_XML, name: text})
    return run_check(CheckOptions(paths=[str(pkg / name)], workspace=str(tmp_path), cache=False)).findings


def test_the_description_a_launch_test_returns_is_checked(tmp_path: Path, demo_package: Any) -> None:
    found = _check(tmp_path, demo_package, "test/test_talker.test.py", TEST.format(params=""))
    assert [(f.code, f.span.line) for f in found] == [("L101", 11)]


def test_an_old_style_ready_fn_parameter_is_given(tmp_path: Path, demo_package: Any) -> None:
    found = _check(tmp_path, demo_package, "test/test_talker_launch.py", TEST.format(params="ready_fn"))
    assert [(f.code, f.span.line) for f in found] == [("L101", 11)]


def test_a_test_dependency_is_declared_only_for_the_tests(tmp_path: Path, demo_package: Any) -> None:
    text = TEST.format(params="").replace("def generate_test_description():", "def generate_launch_description():")
    text = text.replace("]), {\"talker\": talker}", "])").replace(
        "        launch_testing.actions.ReadyToTest(),\n", "")
    found = _check(tmp_path, demo_package, "launch/talker.launch.py", text)
    assert [(f.code, f.span.line) for f in found] == [("L101", 11), ("U103", 12)]


def test_a_context_that_is_not_a_dict_literal_is_still_the_tests(tmp_path: Path, demo_package: Any) -> None:
    # `return ld, locals()`: launch_testing's loader takes the first of any tuple (_normalize_ld);
    # the context is never launched, so nothing of the description is unknown
    from physai_lint import api
    from physai_lint.engine import CheckOptions

    text = TEST.format(params="").replace("{\"talker\": talker}", "locals()")
    pkg = demo_package({"package.xml": PACKAGE_XML, "test/test_talker.test.py": text})
    entry = str(pkg / "test/test_talker.test.py")
    out = api.plan(CheckOptions(paths=[entry], workspace=str(tmp_path), cache=False), entry, "text")
    assert "2 processes" in out and "Not shown" not in out


def test_a_timeout_decorator_keeps_the_description(tmp_path: Path, demo_package: Any) -> None:
    text = TEST.format(params="").replace(
        "def generate_test_description", "@launch_testing.ready_to_test_action_timeout(10)\ndef generate_test_description")
    found = _check(tmp_path, demo_package, "test/test_talker.test.py", text)
    assert [(f.code, f.span.line) for f in found] == [("L101", 12)]


def test_a_parametrized_description_is_unknown_not_empty(tmp_path: Path, demo_package: Any) -> None:
    from physai_lint import api
    from physai_lint.engine import CheckOptions

    text = TEST.format(params="rate").replace(
        "def generate_test_description", "@launch_testing.parametrize('rate', [1, 2])\ndef generate_test_description")
    pkg = demo_package({"package.xml": PACKAGE_XML, "test/test_talker.test.py": text})
    entry = str(pkg / "test/test_talker.test.py")
    out = api.plan(CheckOptions(paths=[entry], workspace=str(tmp_path), cache=False), entry, "text")
    assert "0 processes" in out and "@launch_testing.parametrize('rate', [1, 2])" in out
