"""Required attributes (L009) and attribute types (L010) of XML/YAML launch files.

Each case states what the real launch frontend does with the markup (checked against
launch/launch_ros rolling and humble sources): the file fails to parse, or a value is misread.
"""
from __future__ import annotations

import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parents[2]))  # tests run without an install

from physai_lint.frontends.tags import unknown_markup  # noqa: E402
from physai_lint.frontends.xml_launch import parse_xml_launch  # noqa: E402
from physai_lint.frontends.yaml_launch import parse_yaml_launch  # noqa: E402
from physai_lint.model import launch as ir  # noqa: E402

XML = "/ws/src/p/launch/a.launch.xml"
YAML = "/ws/src/p/launch/a.launch.yaml"


def found(text: str) -> list[tuple[str, int, str]]:
    """(code, line, key) of the L002/L009/L010 diagnostics of a launch file."""
    if text.lstrip().startswith("<"):
        result = parse_xml_launch(XML, text)
    else:
        result = parse_yaml_launch(YAML, text)
    return [(d.code, d.span.line, d.key) for d in result.diagnostics
            if d.code in ("L002", "L009", "L010")]


def ir_of(text: str) -> ir.LaunchFile:
    result = parse_yaml_launch(YAML, text) if not text.startswith("<") else \
        parse_xml_launch(XML, text)
    assert result.launch is not None
    return result.launch


# ---- L009: AttributeError / TypeError while the file is parsed --------------------------------
@pytest.mark.parametrize("text, key", [
    ('<launch>\n<node pkg="demo_nodes_cpp" name="t"/>\n</launch>', "node:exec"),
    ("<launch>\n<include/>\n</launch>", "include:file"),
    ('<launch>\n<arg default="1"/>\n</launch>', "arg:name"),
    ('<launch>\n<include file="a.launch.xml"><arg name="x"/></include>\n</launch>',
     "include/arg:value"),
    ('<launch>\n<node pkg="p" exec="e"><remap from="a"/></node>\n</launch>', "remap:to"),
    (('<launch>\n<node_container pkg="rclcpp_components" exec="component_container" name="c"/>'
      "\n</launch>"), "node_container:namespace"),
    (('<launch>\n<node_container pkg="p" exec="e" name="c" namespace="">'
      '<composable_node pkg="p" plugin="P"/></node_container>\n</launch>'), "composable_node:name"),
    ('<launch>\n<load_composable_node target="c"/>\n</launch>', "load:composable_node"),
    ('<launch>\n<node pkg="p" exec="e"><param value="1"/></node>\n</launch>', "param:name|from"),
    ('<launch>\n<node pkg="p" exec="e"><param name="x"/></node>\n</launch>', "param:value"),
    (('<launch>\n<node pkg="p" exec="e"><param name="x"><param value="1"/></param></node>\n'
      "</launch>"), "param:name"),
    ("<launch>\n<timer><log message='a'/></timer>\n</launch>", "timer:period"),
    ("launch:\n- node: {pkg: p, name: t}\n", "node:exec"),
    ("launch:\n- group:\n    scoped: false\n", "group:children"),
    ("launch:\n- set_parameter: {name: use_sim_time}\n", "set_parameter:value"),
])
def test_missing_attribute(text: str, key: str) -> None:
    assert [k for c, _, k in found(text) if c == "L009"] == [key]


def test_a_misspelt_attribute_is_reported_once_by_l002() -> None:
    text = '<launch>\n<node pkg="p" executable="talker"/>\n</launch>'
    assert found(text) == []
    markup = ir_of(text).markup
    assert markup is not None
    assert [(m, h) for _, m, h in unknown_markup(markup)] == [
        ('unknown attribute "executable" on "node"',
         'use "exec" ("executable" is the keyword of the Python action)')]


@pytest.mark.parametrize("text", [
    ('<launch>\n<node pkg="p" exec="e" name="n"><param name="a"><param name="b" value="1"/>'
     "</param><param from=\"/x.yaml\" allow_substs=\"true\"/></node>\n</launch>"),
    ('<launch>\n<node_container pkg="p" exec="e" name="c" namespace="/">'
     '<composable_node pkg="p" plugin="P" name="n"/></node_container>\n</launch>'),
    "launch:\n- group:\n  - node: {pkg: p, exec: e}\n",
    "launch:\n- timer:\n    period: 1.0\n    children:\n    - log: {message: a}\n",
    ("<launch>\n<group><push-ros-namespace namespace='a'/></group>\n<shutdown/>\n<reset/>\n"
     "</launch>"),
])
def test_complete_markup_is_quiet(text: str) -> None:
    assert found(text) == []


def test_conflicting_param_attributes_are_l002() -> None:
    text = ('<launch>\n<node pkg="p" exec="e">\n<param name="a" from="/x.yaml"/>\n'
            '<param name="b" allow_substs="true" value="1"/>\n'
            '<param name="c" value="1"><param name="d" value="2"/></param>\n</node>\n</launch>')
    assert found(text) == [("L002", 3, "param:name+from"), ("L002", 4, "param:allow_substs"),
                           ("L002", 5, "param:value+param")]


def test_a_missing_value_is_unknown_not_empty() -> None:
    """No later rule sees a made-up "" (an <include/> used to be read as the directory ".")."""
    launch = ir_of("<launch>\n<include/>\n</launch>")
    include = launch.actions[0]
    assert isinstance(include, ir.Include)
    assert type(include.path[0]).__name__ == "Unknown"


# ---- L010: YAML does not convert ----------------------------------------------------------------
@pytest.mark.parametrize("text, key", [
    ("launch:\n- arg: {name: rate, default: 10}\n", "arg:default:int"),
    ("launch:\n- arg: {name: sim, default: false}\n", "arg:default:bool"),
    ("launch:\n- arg: {name: sim, default: }\n", "arg:default:NoneType"),
    ("launch:\n- let: {name: x, value: 1.5}\n", "let:value:float"),
    ("launch:\n- include:\n    file: a.launch.xml\n    arg:\n    - {name: a, value: true}\n",
     "arg:value:bool"),
    ("launch:\n- node: {pkg: p, exec: e, respawn: true}\n", "node:respawn:bool"),
    ("launch:\n- node: {pkg: p, exec: e, respawn_delay: 2}\n", "node:respawn_delay:int"),
    ('launch:\n- node: {pkg: p, exec: e, respawn_delay: "2.0"}\n', "node:respawn_delay:str"),
    ("launch:\n- node: {pkg: p, exec: e, respawn_max_retries: 2.5}\n",
     "node:respawn_max_retries:float"),
    ("launch:\n- timer:\n    period: 2\n    children:\n    - log: {message: a}\n",
     "timer:period:int"),
    ("launch:\n- executable: {cmd: [ls, -l]}\n", "executable:cmd:list"),
    ("launch:\n- group:\n    if: true\n    children:\n    - log: {message: a}\n",
     "group:if:bool"),
    ('launch:\n- group:\n    scoped: "false"\n    children:\n    - log: {message: a}\n',
     "group:scoped:truthy"),
    ("launch:\n- executable: {cmd: ls, shell: 1}\n", "executable:shell:int"),
    ("launch:\n- node:\n    pkg: p\n    exec: e\n    remap: {from: a, to: b}\n", "node:remap:map"),
])
def test_yaml_types(text: str, key: str) -> None:
    assert [k for c, _, k in found(text) if c == "L010"] == [key]


def test_yaml_values_launch_accepts() -> None:
    text = ('launch:\n- arg: {name: rate, default: "10"}\n'
            "- node:\n    pkg: p\n    exec: e\n    respawn: 'true'\n    respawn_delay: 1.0\n"
            "    respawn_max_retries: 3\n    emulate_tty: true\n    param:\n"
            "    - {name: a, value: 10}\n    - {name: b, value: [1, 2]}\n"
            "    - {name: c, value: true}\n    - {from: /x.yaml, allow_substs: true}\n"
            "- timer:\n    period: $(var rate)\n    cancel_on_shutdown: 'true'\n    children:\n"
            "    - log: {message: a}\n"
            "- append_env: {name: P, value: /x, prepend: true}\n")
    assert found(text) == []


# ---- L010: XML keeps text that does not convert ----------------------------------------------
@pytest.mark.parametrize("attrs, key", [
    ('respawn_delay="$(var d)"', "node:respawn_delay:str"),
    ('respawn_delay="two"', "node:respawn_delay:str"),
    ('respawn_delay="-1.0"', "node:respawn_delay:negative"),
    ('sigterm_timeout="$(var t)"', "node:sigterm_timeout:str"),
    ('respawn_max_retries="three"', "node:respawn_max_retries:str"),
    ('shell="$(var s)"', "node:shell:truthy"),
    ('emulate_tty="maybe"', "node:emulate_tty:truthy"),
    ('shell="2"', "node:shell:other"),
])
def test_xml_types(attrs: str, key: str) -> None:
    text = f'<launch>\n<node pkg="p" exec="e" {attrs}/>\n</launch>'
    assert [k for c, _, k in found(text) if c == "L010"] == [key]


@pytest.mark.parametrize("attrs", [
    'respawn_delay="2"', 'respawn_delay="0.5"', 'sigkill_timeout="5"', 'respawn_max_retries="3"',
    'shell="true"', 'shell="False"', 'emulate_tty="yes"', 'shell="0"', 'respawn="$(var r)"',
])
def test_xml_values_launch_accepts(attrs: str) -> None:
    assert found(f'<launch>\n<node pkg="p" exec="e" {attrs}/>\n</launch>') == []


def test_xml_timer_period_may_be_a_substitution() -> None:
    assert found('<launch>\n<timer period="$(var d)"><log message="a"/></timer>\n</launch>') == []


# ---- how the IR reads plain-bool attributes ------------------------------------------------------
@pytest.mark.parametrize("text, scoped, forwarding", [
    ('<launch><group scoped="false" forwarding="no"/></launch>', False, False),
    ('<launch><group scoped="$(var x)"/></launch>', True, True),
    ("launch:\n- group: {scoped: false, forwarding: false, children: []}\n", False, False),
    ('launch:\n- group: {scoped: "false", forwarding: "", children: []}\n', True, False),
])
def test_group_flags_as_the_action_sees_them(text: str, scoped: bool, forwarding: bool) -> None:
    group = ir_of(text).actions[0]
    assert isinstance(group, ir.Group)
    assert (group.scoped, group.forwarding) == (scoped, forwarding)


def test_a_yaml_group_written_as_a_list_keeps_its_actions() -> None:
    launch = ir_of("launch:\n- group:\n  - push-ros-namespace: {namespace: r}\n"
                   "  - node: {pkg: p, exec: e, name: n}\n")
    group = launch.actions[0]
    assert isinstance(group, ir.Group)
    assert [type(a).__name__ for a in group.actions] == ["PushNamespace", "NodeAction"]


# ---- P106: YAML list parameter values ----------------------------------------------------------
@pytest.mark.parametrize("value, reported", [
    ("[1, a]", True),  # parse_if_substitutions: {int, str} -> "The result is a non-uniform list"
    ("[1, 2.5]", True),  # is_instance_of_valid_type: 2.5 is not an int -> TypeError
    ("[1, true]", True),  # bool passes as an int in get_attr, then {int, bool}
    ("[[1], [2]]", True),  # a list is not a scalar
    ("[1, $(var x)]", False),  # a substitution adds no type
    ('[a, "1"]', False),
    ("[1.0, 2.5]", False),
    ("[]", False),
])
def test_yaml_list_parameter_values(value: str, reported: bool) -> None:
    text = f"launch:\n- node:\n    pkg: p\n    exec: e\n    param:\n    - name: g\n      value: {value}\n"
    assert [c for c, _, _ in found_all(text)].count("P106") == (1 if reported else 0)


def found_all(text: str) -> list[tuple[str, int, str]]:
    result = parse_yaml_launch(YAML, text)
    return [(d.code, d.span.line, d.key) for d in result.diagnostics]


def test_yaml_mapping_for_a_parameter_value() -> None:
    text = ("launch:\n- node:\n    pkg: p\n    exec: e\n    param:\n    - name: pid\n"
            "      value: {p: 1, i: 2}\n")
    assert found(text) == [("L010", 7, "param:value:dict")]
    markup = ir_of(text).markup
    assert markup is not None and unknown_markup(markup, "yaml") == []


@pytest.mark.parametrize("value, help_", [
    ('"true"', 'write a YAML boolean: scoped: true (the same here, but a quoted "false" is on too)'),
    ('"false"', "write a YAML boolean: scoped: false"),
    ('"maybe"', "write a YAML boolean: scoped: true or scoped: false"),
])
def test_yaml_boolean_help_writes_the_boolean_the_text_means(value: str, help_: str) -> None:
    from physai_lint.frontends.yaml_launch import parse_yaml_launch as parse

    lf = parse("/ws/a.launch.yaml", f"launch:\n- group:\n    scoped: {value}\n    children:\n    - log: {{message: a}}\n")
    assert [d.help for d in lf.diagnostics if d.code == "L010"] == [help_]


# ---- L010: a YAML parameter value of another type than its type: -------------------------------
# Each row was run through launch_ros humble's Node.parse_nested_parameters (launch_yaml 1.0.7):
# get_attr(data_type=...) converts nothing, and ParameterValue rejects a plain str of another type.
@pytest.mark.parametrize("param, type_", [
    ('{name: q, value: "10", type: int}', "int"),  # value='10' is not an instance of int
    ('{name: q, value: "true", type: bool}', "bool"),
    ("{name: q, value: 10, type: float}", "float"),  # an int is not a float
    ("{name: q, value: 10, type: str}", "str"),
    ("{name: q, value: 1.5, type: int}", "int"),
    ('{name: q, value: ["1", "2"], type: list_of_int}', "list_of_int"),  # "Got a list of str"
    ("{name: q, value: [1, 2], type: list_of_float}", "list_of_float"),
    ('{name: q, value: "1,2", type: list_of_int}', "list_of_int"),
    ("{name: q, value: [], type: list_of_int}", "list_of_int"),  # no item type: "a list of str"
])
def test_yaml_parameter_value_of_another_type(param: str, type_: str) -> None:
    text = f"launch:\n- node:\n    pkg: p\n    exec: e\n    param:\n    - {param}\n"
    assert found(text) == [("L010", 6, f"param:q:type:{type_}")]


@pytest.mark.parametrize("param", [
    "{name: q, value: 10, type: int}",
    "{name: q, value: true, type: int}",  # isinstance(True, int)
    '{name: q, value: "10", type: str}',
    '{name: q, value: "10", type: yaml}',
    '{name: q, value: "$(var n)", type: int}',  # converted when evaluated
    "{name: q, value: [1.0, 2.5], type: list_of_float}",
    '{name: q, value: ["a", "b"], type: list_of_str}',
    "{name: q, value: [], type: list_of_str}",
    "{name: q, value: []}",
])
def test_yaml_parameter_value_of_its_type(param: str) -> None:
    text = f"launch:\n- node:\n    pkg: p\n    exec: e\n    param:\n    - {param}\n"
    assert found(text) == []


def test_a_list_of_another_type_than_its_type_is_one_finding() -> None:
    text = ("launch:\n- node:\n    pkg: p\n    exec: e\n    param:\n"
            "    - {name: q, value: [1, 2.0], type: list_of_float}\n")
    assert [(c, k) for c, _, k in found_all(text)] == [("L010", "param:q:type:list_of_float")]


def test_yaml_null_value_is_not_a_string() -> None:
    # launch_yaml's get_attr rejects None ("expected to be of type 'None', got NoneType")
    from physai_lint.model.values import PLit

    launch = ir_of("launch:\n- node:\n    pkg: p\n    exec: e\n    param:\n    - {name: q, value: ~}\n")
    node = launch.actions[0]
    value = node.parameters[0].entries[0].value  # type: ignore[attr-defined]
    assert not (isinstance(value, PLit) and value.value == "~")
