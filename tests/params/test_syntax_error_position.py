"""A YAML syntax error that runs into the end of the file (an unterminated quote or bracket) is
reported where the unclosed thing starts, not at the end of the file (libyaml's context mark)."""
from __future__ import annotations

from physai_lint.frontends.yaml_launch import parse_yaml_launch
from physai_lint.params.loader import load_param_file

PARAMS = 'gps_driver:\n  ros__parameters:\n    port: "/dev/ttyACM0\n    baud: 115200\n    rate: 10.0\n'


def test_an_unterminated_quote_in_a_parameter_file() -> None:
    model = load_param_file("/w/gps.yaml", PARAMS)
    (d,) = [d for d in model.diagnostics if d.code == "X001"]
    assert (d.span.line, d.span.col) == (3, 11)


def test_an_unterminated_quote_in_a_yaml_launch_file() -> None:
    result = parse_yaml_launch("/w/a.launch.yaml", 'launch:\n- log: {message: "hi}\n- log: {message: b}\n')
    (d,) = result.diagnostics
    assert d.code == "X001" and d.span.line == 2


def test_a_value_the_scanner_folded_up_to_the_error_is_not_given_to_the_node() -> None:
    # "zeta: 0.0" then an over-indented "use_mag: false": libyaml emits the scalar "0.0 use_mag"
    # before it finds the ":", a value neither rcl nor PyYAML ever gives the node
    text = "imu:\n  ros__parameters:\n    gain: 0.1\n    zeta: 0.0\n     use_mag: false\n"
    model = load_param_file("/w/imu.yaml", text)
    assert [d.span.line for d in model.diagnostics if d.code == "X001"] == [5]
    assert [p.name for b in model.blocks for p in b.params] == ["gain"]
    assert not any(op[0] == "set" and op[-1].name == "zeta" for op in model.ops)
