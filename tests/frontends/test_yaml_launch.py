"""YAML reader: positions, duplicate keys, aliases and syntax errors."""
from __future__ import annotations

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[2]))  # tests run without an install

from physai_lint.frontends.tags import unknown_markup  # noqa: E402
from physai_lint.frontends.yaml_launch import parse_yaml_launch  # noqa: E402
from physai_lint.model import launch as ir  # noqa: E402
from physai_lint.model.span import Span  # noqa: E402
from physai_lint.model.values import LaunchConfig, PLit, PSubst, literal_of  # noqa: E402

F = "/ws/src/p/launch/a.launch.yaml"


def parse(text: str) -> ir.LaunchFile:
    result = parse_yaml_launch(F, text)
    assert result.launch is not None, result.diagnostics
    return result.launch


def test_node_field_spans_and_id() -> None:
    launch = parse("launch:\n- node:\n    pkg: demo\n    exec: 'talker'\n    name: t\n")
    node = launch.actions[0]
    assert isinstance(node, ir.NodeAction) and node.id == "2:3"
    assert node.span_of("package") == Span(F, 3, 10, 3, 14)
    assert node.span_of("executable") == Span(F, 4, 12, 4, 18)


def test_substitution_columns_in_plain_and_quoted_scalars() -> None:
    launch = parse('launch:\n- let: {name: a, value: "x $(var b)"}\n'
                   "- let:\n    name: c\n    value: pre\n      $(env D)\n")
    first, second = launch.actions
    assert isinstance(first, ir.SetLaunchConfiguration)
    assert first.value[1].span == Span(F, 2, 28, 2, 36)
    assert isinstance(second, ir.SetLaunchConfiguration)
    assert second.value[1].span == Span(F, 6, 7, 6, 15)


def test_param_values_keep_yaml_types() -> None:
    """launch_yaml does not convert a value, and parse_if_substitutions keeps a string without
    substitutions as the str it is: only a value with substitutions is YAML-typed at run time."""
    launch = parse("launch:\n- node:\n    exec: x\n    param:\n    - {name: a, value: 3}\n"
                   "    - {name: b, value: [1, 2]}\n    - {name: c, value: '3'}\n"
                   "    - {name: d, value: ['1', '2']}\n    - {name: e, value: '$(var n)'}\n")
    node = launch.actions[0]
    assert isinstance(node, ir.NodeAction)
    values = [p.entries[0].value for p in node.parameters]  # type: ignore[union-attr]
    assert isinstance(values[0], PLit) and values[0].value == 3
    assert isinstance(values[1], PLit) and values[1].value == (1, 2)
    assert isinstance(values[2], PLit) and values[2].value == "3"
    assert isinstance(values[3], PLit) and values[3].value == ("1", "2")
    assert isinstance(values[4], PSubst) and values[4].value_type is None


def test_duplicate_key_is_x006_at_second_occurrence() -> None:
    result = parse_yaml_launch(F, "launch:\n- node:\n    exec: a\n    name: n\n    exec: b\n")
    assert [(d.code, d.span.line, d.span.col) for d in result.diagnostics] == [("X006", 5, 5)]
    node = result.launch.actions[0]  # type: ignore[union-attr]
    assert isinstance(node, ir.NodeAction) and literal_of(node.executable) == "b"


def test_syntax_error_is_x001_with_line_and_column() -> None:
    result = parse_yaml_launch(F, "launch:\n- node:\n    exec: [a\n")
    assert result.launch is None
    assert [d.code for d in result.diagnostics] == ["X001"]
    assert result.diagnostics[0].span.line >= 3


def test_alias_bomb_is_refused_quickly() -> None:
    lines = ["launch:", "- log: {message: &a0 [x, x, x, x, x, x, x, x, x]}"]
    lines += [f"- log: {{message: &a{i} [" + ", ".join([f"*a{i - 1}"] * 9) + "]}" for i in range(1, 10)]
    result = parse_yaml_launch(F, "\n".join(lines) + "\n")
    assert result.launch is None and result.diagnostics[0].code == "X001"
    assert "alias" in result.diagnostics[0].message


def test_aliases_and_merge_keys_are_followed_like_safe_load() -> None:
    """launch_yaml reads the file with yaml.safe_load: aliases repeat the anchored node, a merge key
    (<<) brings the anchored mapping's keys, which the mapping's own keys override."""
    text = ("launch:\n"
            "- node: &base {pkg: demo_nodes_cpp, exec: talker, name: a, namespace: ns}\n"
            "- node:\n    <<: *base\n    name: b\n"
            "- log: &m {message: hi}\n- log: *m\n")
    result = parse_yaml_launch(F, text)
    assert result.launch is not None and not result.diagnostics
    nodes = [a for a in result.launch.actions if isinstance(a, ir.NodeAction)]
    assert [(ir_text(n.name), ir_text(n.namespace), ir_text(n.executable)) for n in nodes] == [
        ("a", "ns", "talker"), ("b", "ns", "talker")]
    assert sum(isinstance(a, ir.Log) for a in result.launch.actions) == 2
    assert unknown_markup(result.launch.markup, "yaml") == []  # type: ignore[arg-type]


def ir_text(value: object) -> str:
    from physai_lint.model.values import literal_of

    return str(literal_of(value))  # type: ignore[arg-type]


def test_root_must_be_launch_mapping() -> None:
    for text in ("- node: {exec: a}\n", "nodes: []\n", ""):
        result = parse_yaml_launch(F, text)
        assert result.launch is None and result.diagnostics[-1].code == "X001"


def test_condition_and_substitution_error() -> None:
    result = parse_yaml_launch(F, "launch:\n- log:\n    message: $(foo)\n    unless: $(var q)\n")
    assert [(d.code, d.span.line, d.span.col) for d in result.diagnostics] == [("L007", 3, 14)]
    log = result.launch.actions[0]  # type: ignore[union-attr]
    assert log.condition is not None and log.condition.kind == "unless"
    assert isinstance(log.condition.value[0], LaunchConfig)


def test_unknown_keys_reported_by_tags_table() -> None:
    launch = parse("launch:\n- node:\n    exec: a\n    node-name: x\n    namespce: y\n")
    found = [(s.line, hint) for s, _, hint in unknown_markup(launch.markup)]  # type: ignore[arg-type]
    assert found[0][0] == 4 and found[1] == (5, "namespace")
