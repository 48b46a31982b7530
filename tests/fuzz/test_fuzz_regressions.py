"""Inputs the fuzzer found crashing physai-lint, minimised by hand; each must now be a finding."""
from __future__ import annotations

import fuzz_harness as fh
import pytest

from physai_lint.frontends.xml_launch import parse_xml_launch
from physai_lint.frontends.yaml_launch import parse_yaml_launch


def test_unterminated_substitution_in_a_condition_is_l007_not_indexerror() -> None:
    # IndexError in substitutions._Ctx.span: the error position was one past the attribute's end.
    res = parse_xml_launch("/ws/a.launch.xml", '<launch>\n  <set_parameter if="$(" name="a" value="1"/>\n</launch>\n')
    assert [(d.code, d.span.line) for d in res.diagnostics] == [("L007", 2)]
    res = parse_yaml_launch("/ws/a.launch.yaml", 'launch:\n- set_parameter: {if: "$(", name: a, value: "1"}\n')
    assert [(d.code, d.span.line) for d in res.diagnostics] == [("L007", 2)]


def test_next_line_character_in_a_plain_scalar_is_positioned_not_indexerror() -> None:
    # IndexError in yaml_launch positions(): U+0085 (NEL) is a line break to libyaml, so the
    # scalar's end mark ran past the text (minimised from a fuzzer input).
    res = parse_yaml_launch("/ws/a.launch.yaml", "launch:\n    e: L\x85     \n    n:\n    v: {e: 0}\n")
    assert all(d.code != "X003" for d in res.diagnostics)


REGRESSIONS = {
    "yaml": ["launch:\n- append_env:\n    name: 'L\x85      '\n    children:\n    - unset_env: {name: '0'}\n".encode(),
             "launch:\n    e: L\x85     \n    n:\n    v: {e: 0}\n".encode()],
    "xml": [b'<launch>\n  <set_parameter if="$(" unless="1.5" value="$(command \'ls\')"/>\n</launch>\n'],
}


@pytest.mark.parametrize(("fmt", "data"), [(f, d) for f, ds in REGRESSIONS.items() for d in ds])
def test_regression_through_the_pipeline(fmt: str, data: bytes) -> None:
    runner = fh.Runner()
    try:
        runner.run(fmt, data)
    finally:
        runner.close()
