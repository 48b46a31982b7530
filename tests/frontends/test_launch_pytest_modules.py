"""L006 missing-generate-launch-description: a launch_pytest module (run by pytest, its
description given by a ``@launch_pytest.fixture``) is no launch file, whatever its name."""

MODULE = """
import launch
{imports}
import pytest
from launch_ros.actions import Node


@{fixture}
def talker_description():
    return launch.LaunchDescription([Node(package="demo_nodes_cpp", executable="talker")])


@pytest.mark.launch(fixture=talker_description)
def test_talker_starts():
    assert True
"""


def _l006(demo_findings, imports: str, fixture: str) -> list[str]:
    files = {"test/test_talker.launch.py": MODULE.format(imports=imports, fixture=fixture)}
    return ["L006" for _ in demo_findings(files, "test/test_talker.launch.py", "L006")]


def test_a_launch_pytest_module_is_not_reported(demo_findings):
    assert _l006(demo_findings, "import launch_pytest", "launch_pytest.fixture") == []
    assert _l006(demo_findings, "from launch_pytest import fixture", "fixture") == []


def test_a_module_without_it_still_is(demo_findings):
    assert _l006(demo_findings, "", "pytest.fixture") == ["L006"]
