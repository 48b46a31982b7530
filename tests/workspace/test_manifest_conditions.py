"""REP 149 ``condition`` attributes: the simple forms are evaluated without catkin_pkg's pyparsing
grammar, and must give exactly what catkin_pkg gives; every other form is left to catkin_pkg."""
from __future__ import annotations

import random
import subprocess
import sys

import pytest
from catkin_pkg.condition import evaluate_condition

from physai_lint.workspace.package_xml import (
    _evaluate_condition,
    can_hold,
    parse_manifest,
    simple_condition,
)

# catkin_pkg.condition builds its grammar with pyparsing names deprecated since pyparsing 3
pytestmark = pytest.mark.filterwarnings("ignore::DeprecationWarning")

CONTEXT = {"ROS_VERSION": "2", "ROS_DISTRO": "jazzy", "ROS_PYTHON_VERSION": "3"}

SIMPLE = [
    "$ROS_VERSION == 2",
    "$ROS_VERSION == 1",
    "$ROS_VERSION==2",
    "  $ROS_VERSION   !=   1  ",
    "$ROS_DISTRO == humble or $ROS_DISTRO == jazzy or $ROS_DISTRO == kilted",
    "$ROS_DISTRO != humble and $ROS_DISTRO != jazzy and $ROS_DISTRO != kilted",
    "$ROS_VERSION == 1 or $ROS_VERSION == 2 and $ROS_DISTRO == humble",  # and binds tighter
    "$ROS_VERSION == 2 and $ROS_DISTRO == humble or $ROS_PYTHON_VERSION == 3",
    "$ROS_DISTRO >= iron",
    "$ROS_DISTRO < iron",
    "$ROS_PYTHON_VERSION > 2",
    "$ROS_PYTHON_VERSION <= 10",  # strings: "3" > "10"
    "$UNSET == $ALSO_UNSET",
    "$ENABLE_AGNOCAST == 1",
    "2 == $ROS_VERSION",
    "a-b == a-b",
    "$ROS_DISTRO == android",
    "$ROS_DISTRO == or",
]

NOT_SIMPLE = [
    '$ROS_DISTRO == "jazzy"',
    "$ROS_DISTRO == 'jazzy'",
    "($ROS_VERSION == 2)",
    "$ROS_VERSION == 2 and ($ROS_DISTRO == jazzy or $ROS_DISTRO == rolling)",
    "$ROS_VERSION == 2.0",
    "$ROS_VERSION = 2",
    "$ROS_VERSION == 2 and$ROS_DISTRO == jazzy",
    "$ROS_VERSION == 2 AND $ROS_DISTRO == jazzy",
    "$ROS_VERSION == 2 or",
    "$ == 2",
    "$UNSET == ",
    "",
]


@pytest.mark.parametrize("condition", SIMPLE)
def test_simple_forms_match_catkin_pkg(condition: str) -> None:
    expected = _catkin(condition)
    got = simple_condition(condition, CONTEXT)
    if got is not None:
        assert got is expected, condition
    assert _evaluate_condition(condition, CONTEXT) == expected


@pytest.mark.parametrize("condition", NOT_SIMPLE)
def test_other_forms_are_left_to_catkin_pkg(condition: str) -> None:
    assert simple_condition(condition, CONTEXT) is None
    expected = _catkin(condition)
    if isinstance(expected, ValueError):
        with pytest.raises(ValueError):
            _evaluate_condition(condition, CONTEXT)
    else:
        assert _evaluate_condition(condition, CONTEXT) == expected


def test_random_conditions_match_catkin_pkg() -> None:
    """Conditions built from the grammar's pieces, spaced and joined at random: wherever the fast
    path answers, catkin_pkg answers the same."""
    rng = random.Random(149)
    terms = ["$ROS_VERSION", "$ROS_DISTRO", "$NOPE", "2", "1", "jazzy", "humble", "a-b", "and", "or",
             "x_1", "$ROS_PYTHON_VERSION", "3", "10"]
    ops = ["==", "!=", ">=", ">", "<=", "<"]
    answered = 0
    for _ in range(600):
        parts = []
        for k in range(rng.randint(1, 4)):
            if k:
                parts.append(rng.choice([" and ", " or ", "  or\t", " and"]))
            parts.append(rng.choice(terms) + rng.choice(["", " ", "  "]) + rng.choice(ops)
                         + rng.choice(["", " "]) + rng.choice(terms))
        condition = rng.choice(["", " "]) + "".join(parts) + rng.choice(["", " "])
        got = simple_condition(condition, CONTEXT)
        if got is None:
            continue
        answered += 1
        assert got is _catkin(condition), condition
    assert answered > 300


def test_a_manifest_with_a_simple_condition_does_not_import_pyparsing(tmp_path) -> None:
    manifest = tmp_path / "package.xml"
    manifest.write_text(
        '<?xml version="1.0"?>\n<package format="3">\n  <name>demo</name>\n  <version>0.1.0</version>\n'
        "  <description>d</description>\n  <maintainer email=\"dev@example.com\">a</maintainer>\n"
        "  <license>MIT</license>\n"
        '  <exec_depend condition="$ROS_VERSION == 1">rospy</exec_depend>\n'
        '  <exec_depend condition="$ROS_VERSION == 2">rclpy</exec_depend>\n'
        "</package>\n")
    code = ("import sys\n"
            "from physai_lint.workspace.package_xml import parse_manifest\n"
            f"info = parse_manifest(open({str(manifest)!r}).read(), 'package.xml', 'jazzy')\n"
            "print(sorted(info.exec_depends), 'pyparsing' in sys.modules)\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert out.split() == ["['rclpy']", "False"]


def _catkin(condition: str) -> bool | ValueError:
    try:
        return bool(evaluate_condition(condition, CONTEXT))
    except ValueError as exc:
        return exc


@pytest.mark.parametrize(("condition", "holds"), [
    (None, True),
    ("$ROS_VERSION == 1", False),
    ("$ROS_VERSION == 2", True),
    ("$HUSARION_ROS_BUILD_TYPE == simulation", True),  # set by whoever builds: either way
    ("$HUSARION_ROS_BUILD_TYPE == hardware or $ROS_VERSION == 1", True),
    ("$ROS_VERSION == 1 and $BUILD_TYPE == simulation", False),  # false whatever BUILD_TYPE is
    ("$ROS_DISTRO == humble and $BUILD_TYPE != hardware", False),  # jazzy here
    ("$ROS_DISTRO == jazzy and $BUILD_TYPE != hardware", True),
    ("($BUILD_TYPE == 'sim')", True),  # not the simple form: it may hold
])
def test_a_dependency_counts_when_its_condition_can_hold(condition, holds):
    assert can_hold(condition, CONTEXT) is holds


def test_a_dependency_on_a_build_variable_declares_the_package(tmp_path):
    text = """<?xml version="1.0"?>
<package format="3">
  <name>demo</name><version>0.0.1</version><description>d</description>
  <maintainer email="dev@example.com">dev</maintainer><license>MIT</license>
  <exec_depend condition="$BUILD_TYPE == simulation">gz_ros2_control</exec_depend>
  <exec_depend condition="$ROS_VERSION == 1">roslaunch</exec_depend>
</package>
"""
    assert set(parse_manifest(text, "package.xml", "humble").exec_depends) == {"gz_ros2_control"}
