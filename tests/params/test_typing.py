import json
import math
from pathlib import Path

import pytest

from physai_lint.params.typing import (
    launch_dump_retype, pyyaml_kind, pyyaml_scalar, pyyaml_type, rcl_type_scalar,
)

CASES = json.loads((Path(__file__).parent / "data" / "ros2-param-scalar-typing.json").read_text())["cases"]


@pytest.mark.parametrize("case", CASES, ids=[c["scalar"] for c in CASES])
def test_rcl_column(case):
    kind, _ = rcl_type_scalar(case["scalar"], False, None, "humble")
    assert kind == case["rcl_yaml_param_parser"]


@pytest.mark.parametrize("case", CASES, ids=[c["scalar"] for c in CASES])
def test_pyyaml_column(case):
    assert pyyaml_kind(pyyaml_type(case["scalar"])) == case["pyyaml_safe_load"]


@pytest.mark.parametrize("text,kind,value", [
    ("017", "integer", 15), ("0x1F", "integer", 31), ("+1", "integer", 1), ("08", "double", 8.0),
    ("1e3", "double", 1000.0), ("1.", "double", 1.0), (".5", "double", 0.5),
    ("0x1p3", "double", 8.0), ("1e999", "string", "1e999"), ("1e-999", "string", "1e-999"),
    ("9223372036854775808", "double", 9223372036854775808.0),
    ("-9223372036854775808", "integer", -9223372036854775808),
    ("0x", "string", "0x"), ("1_000", "string", "1_000"), ("", "string", ""),
    ("1e", "string", "1e"), ("infinity", "double", math.inf), ("-inf", "double", -math.inf),
])
def test_rcl_specifics(text, kind, value):
    k, v = rcl_type_scalar(text, False, None, "humble")
    assert k == kind
    assert v == value


def test_nan_and_quotes_and_tags():
    assert math.isnan(rcl_type_scalar("nan", False, None, "humble")[1])
    assert math.isnan(rcl_type_scalar(".NaN", False, None, "humble")[1])
    assert rcl_type_scalar("5", True, None, "humble") == ("string", "5")
    assert rcl_type_scalar("true", True, None, "humble") == ("string", "true")
    str_tag = "tag:yaml.org,2002:str"
    assert rcl_type_scalar("5", False, str_tag, "humble") == ("integer", 5)
    assert rcl_type_scalar("5", False, str_tag, "jazzy") == ("string", "5")
    assert rcl_type_scalar("1", False, "tag:yaml.org,2002:float", "jazzy") == ("integer", 1)


def test_pyyaml_helpers():
    assert pyyaml_type("[1, 2]") == [1, 2]
    assert pyyaml_type("") == ""
    assert pyyaml_type("a: [") == "a: ["
    assert pyyaml_type("&a [*a]") == "&a [*a]"
    assert pyyaml_scalar("1e3", False, None) == "1e3"
    assert pyyaml_scalar("y", False, None) == "y"
    assert pyyaml_scalar("5", True, None) == "5"
    assert launch_dump_retype("1e3") == ("double", 1000.0)
    assert launch_dump_retype("true") == ("string", "true")  # PyYAML quotes it when dumping
    assert launch_dump_retype("y") == ("bool", True)  # dumped plain, rcl reads a bool
