"""L006 missing-generate-launch-description: a launch_pytest module (run by pytest, its
description given by a ``@launch_pytest.fixture``) is no launch file, whatever its name."""
from physai_lint.engine import CheckOptions, run_check

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


def _l006(tmp_path, demo_package, imports: str, fixture: str) -> list[str]:
    pkg = demo_package({"test/test_talker.launch.py": MODULE.format(imports=imports, fixture=fixture)})
    report = run_check(CheckOptions(paths=[str(pkg / "test/test_talker.launch.py")], workspace=str(tmp_path),
                                    select=("L006",)), cwd=str(tmp_path))
    return [f.code for f in report.findings]


def test_a_launch_pytest_module_is_not_reported(tmp_path, demo_package):
    assert _l006(tmp_path, demo_package, "import launch_pytest", "launch_pytest.fixture") == []
    assert _l006(tmp_path, demo_package, "from launch_pytest import fixture", "fixture") == []


def test_a_module_without_it_still_is(tmp_path, demo_package):
    assert _l006(tmp_path, demo_package, "", "pytest.fixture") == ["L006"]
