"""XML reader: positions, safety (no DTD, no entity expansion) and parse errors."""
from __future__ import annotations

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[2]))  # tests run without an install

from physai_lint.frontends.tags import unknown_markup  # noqa: E402
from physai_lint.frontends.xml_launch import parse_xml_launch  # noqa: E402
from physai_lint.model import launch as ir  # noqa: E402
from physai_lint.model.span import Span  # noqa: E402
from physai_lint.model.values import LaunchConfig, PSubst, Text, literal_of  # noqa: E402

F = "/ws/src/p/launch/a.launch.xml"


def parse(text: str) -> ir.LaunchFile:
    result = parse_xml_launch(F, text)
    assert result.launch is not None, result.diagnostics
    return result.launch


def test_node_field_spans_point_at_attribute_values() -> None:
    launch = parse('<launch>\n  <node pkg="demo" exec="talker" name="t" namespace="/r"/>\n</launch>')
    node = launch.actions[0]
    assert isinstance(node, ir.NodeAction) and node.id == "2:3"
    assert node.span == Span(F, 2, 3, 2, 8)
    assert node.span_of("package") == Span(F, 2, 14, 2, 18)
    assert node.span_of("executable") == Span(F, 2, 26, 2, 32)
    assert node.span_of("name") == Span(F, 2, 40, 2, 41)
    assert node.span_of("namespace") == Span(F, 2, 54, 2, 56)


def test_entity_references_keep_columns() -> None:
    launch = parse('<launch><log message="a &amp;&lt; $(var x)"/></launch>')
    log = launch.actions[0]
    assert isinstance(log, ir.Log)
    assert log.message[0] == Text("a &< ", Span(F, 1, 23, 1, 35))
    assert isinstance(log.message[1], LaunchConfig)
    assert log.message[1].span == Span(F, 1, 35, 1, 43)


def test_multiline_attribute_substitution_positions() -> None:
    text = '<launch>\n  <let name="x"\n       value="a\n   $(var y) $(env Z)"/>\n</launch>'
    let = parse(text).actions[0]
    assert isinstance(let, ir.SetLaunchConfiguration)
    assert let.value[1].span == Span(F, 4, 4, 4, 12)
    assert let.value[3].span == Span(F, 4, 13, 4, 21)


def test_substitution_error_in_attribute_is_l007_at_exact_position() -> None:
    result = parse_xml_launch(F, '<launch>\n  <node pkg="$(find-pkg demo)" exec="x"/>\n</launch>')
    assert [(d.code, d.span.line, d.span.col) for d in result.diagnostics] == [("L007", 2, 14)]
    assert result.launch is not None


def test_if_and_unless_both_given() -> None:
    result = parse_xml_launch(F, '<launch><log message="m" if="1" unless="0"/></launch>')
    assert [d.code for d in result.diagnostics] == ["L002"]
    assert result.launch is not None
    cond = result.launch.actions[0].condition
    assert cond is not None and cond.kind == "if" and literal_of(cond.value) == "1"


def test_params_one_dict_per_param_tag_and_types() -> None:
    launch = parse('<launch><node exec="x"><param name="a" value="1"/>'
                   '<param name="b" value="x,y" value-sep="," type="str"/></node></launch>')
    node = launch.actions[0]
    assert isinstance(node, ir.NodeAction)
    assert len(node.parameters) == 2
    b = node.parameters[1]
    assert isinstance(b, ir.ParamDict) and b.entries[0].name == "b"
    assert b.entries[0].value == PSubst(b.entries[0].value.value, "str",  # type: ignore[union-attr]
                                        Span(F, 1, 74, 1, 77), ",")


def test_malformed_xml_is_x001_with_position() -> None:
    result = parse_xml_launch(F, "<launch>\n  <node pkg='a'>\n</launch>")
    assert result.launch is None
    assert [(d.code, d.span.line) for d in result.diagnostics] == [("X001", 3)]


def test_duplicate_attribute_is_x006_at_second_occurrence() -> None:
    result = parse_xml_launch(F, '<launch>\n  <node exec="a" name="n" exec="b"/>\n</launch>')
    assert result.launch is None
    assert [(d.code, d.span) for d in result.diagnostics] == [("X006", Span(F, 2, 27, 2, 31))]


def test_root_must_be_launch() -> None:
    result = parse_xml_launch(F, "<robot/>")
    assert result.launch is None and result.diagnostics[0].code == "X001"


def test_billion_laughs_is_refused_not_expanded() -> None:
    lol = "".join(f'<!ENTITY l{i} "{("&l" + str(i - 1) + ";") * 10}">' for i in range(1, 10))
    text = f'<?xml version="1.0"?><!DOCTYPE launch [<!ENTITY l0 "lol">{lol}]>' \
           '<launch><log message="&l9;"/></launch>'
    result = parse_xml_launch(F, text)
    assert result.launch is None
    assert [d.code for d in result.diagnostics] == ["X001"]
    assert "DOCTYPE" in result.diagnostics[0].message


def test_external_entity_is_refused() -> None:
    text = '<!DOCTYPE launch [<!ENTITY x SYSTEM "file:///etc/passwd">]>' \
           '<launch><log message="&x;"/></launch>'
    result = parse_xml_launch(F, text)
    assert result.launch is None and result.diagnostics[0].code == "X001"


def test_undefined_entity_is_a_parse_error() -> None:
    result = parse_xml_launch(F, '<launch><log message="&x;"/></launch>')
    assert result.launch is None and result.diagnostics[0].code == "X001"


def test_non_ascii_before_a_substitution_keeps_character_columns() -> None:
    launch = parse('<launch><log message="é—$(var x)"/></launch>')
    log = launch.actions[0]
    assert isinstance(log, ir.Log) and log.message[1].span == Span(F, 1, 25, 1, 33)


def test_unknown_markup_flags_ros1_and_typos() -> None:
    launch = parse('<launch>\n<node exec="a" ns="x"/>\n<arg name="a" descrption="d"/>\n'
                   "<group ns='r'/>\n<nodee exec='a'/>\n</launch>")
    found = {(s.line, msg, hint) for s, msg, hint in unknown_markup(launch.markup)}  # type: ignore[arg-type]
    assert (3, 'unknown attribute "descrption" on "arg"', "description") in found
    assert (5, 'unknown tag "nodee"', "node") in found
    assert any(line == 2 and '"ns"' in msg for line, msg, _ in found)
    assert any(line == 4 and '"ns"' in msg for line, msg, _ in found)
    assert isinstance(launch.actions[-1], ir.OpaqueAction)


def test_executable_cmd_is_split_on_whitespace() -> None:
    proc = parse('<launch><executable cmd="ros2  run $(var p) x"/></launch>').actions[0]
    assert isinstance(proc, ir.ExecuteProcess) and proc.cmd is not None
    assert [literal_of(v) for v in proc.cmd] == ["ros2", "run", None, "x"]
