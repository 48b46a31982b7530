"""P112: which received values are typing traps (checks/param_typing.py)."""
from __future__ import annotations

import pytest

from physai_lint.checks.param_typing import _problem
from physai_lint.params.typing import rcl_type_scalar


@pytest.mark.parametrize("text", ["017", "033422070453", "0483", "y", "N", "null", "~", "1_000"])
def test_traps_in_a_params_file(text: str) -> None:
    kind, value = rcl_type_scalar(text)
    assert _problem(text, False, "file", kind, value, None) is not None


@pytest.mark.parametrize("text", ["true", "on", "yes", "1e3", ".5", "0x10", "1.0e+3", "0", "10",
                                  "nan", "map", "0.5"])
def test_ordinary_values_are_silent(text: str) -> None:
    kind, value = rcl_type_scalar(text)
    assert _problem(text, False, "file", kind, value, None) is None


def test_quoted_and_declared() -> None:
    assert _problem("0483", True, "file", "string", "0483", None) is None
    assert _problem("0483", False, "file", "double", 483.0, "double") is None  # declaration accepts it
    assert _problem("017", False, "file", "integer", 15, "integer") is not None  # octal, not 17
    assert _problem("y", False, "file", "bool", True, "bool") is None


def test_composable_and_python_values() -> None:
    assert _problem("1e3", False, "file", "string", "1e3", None) is not None  # PyYAML keeps a string
    assert _problem("0483", True, "python", "double", 483.0, None) is not None
    assert _problem("10", True, "python", "string", "10", None) is None


def test_values_of_a_dict_comprehension_keep_their_own_text(demo_findings) -> None:
    # the entries of a dict comprehension share one span: each value is judged by its own text,
    # not by the last string written at that span ('1e3' is a real trap; '20435008' is not, as
    # launch_ros yaml.dumps a str quoted when PyYAML would read it as a number; 'camera' is not)
    launch = (
        "from launch import LaunchDescription\n"
        "from launch_ros.actions import Node\n\n"
        "def generate_launch_description():\n"
        "    params = {k: v for k, v in [('queue_size', 1), ('serial', '20435008'), ('rate', '1e3'),\n"
        "                                ('frame_id', 'camera')]}\n"
        "    return LaunchDescription([Node(package='demo_nodes_cpp', executable='talker', name='cam',\n"
        "                                   parameters=[params])])\n")
    found = demo_findings({"launch/cam.launch.py": launch}, "launch/cam.launch.py", "P112")
    assert [(line, msg.split(":")[0]) for line, msg in found] == [(8, 'parameter "rate" of /cam')]
    assert "the Python string '1e3' reaches the node as 1000.0" in found[0][1]
