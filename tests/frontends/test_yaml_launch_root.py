"""The body of a YAML launch file's ``launch:`` key must be a list of actions, or a mapping with a
``children`` list (launch_yaml ``Entity.children``); anything else fails loading the file."""
from __future__ import annotations

import pytest

from physai_lint.frontends.yaml_launch import parse_yaml_launch


@pytest.mark.parametrize(("text", "says"), [
    ("launch:\n  node:\n    pkg: demo_nodes_cpp\n    exec: talker\n", "holds a mapping"),
    ("launch:\n  arg:\n    name: a\n  node:\n    pkg: p\n    exec: e\n", "holds a mapping"),
    ("launch:\n", "holds the empty value"),
])
def test_a_launch_body_that_is_no_list_fails_loading(text: str, says: str):
    result = parse_yaml_launch("/w/a.launch.yaml", text)
    assert result.launch is None
    (d,) = result.diagnostics
    assert d.code == "L010" and (d.span.line, d.span.col) == (1, 1) and says in d.message


@pytest.mark.parametrize("text", [
    "launch:\n- node:\n    pkg: demo_nodes_cpp\n    exec: talker\n",
    "launch:\n  children:\n  - node:\n      pkg: demo_nodes_cpp\n      exec: talker\n",
    "launch: []\n",
])
def test_a_list_or_children_is_fine(text: str):
    result = parse_yaml_launch("/w/a.launch.yaml", text)
    assert result.launch is not None and not [d for d in result.diagnostics if d.code in ("L010", "X001")]


YAML_PARAMETERS = """launch:
- arg:
    name: imu_rate
    default: "100.0"
- node:
    pkg: demo_nodes_cpp
    exec: talker
    parameters:
    - name: rate
      value: $(var imu_rate)
    - name: frame_id
      value: imu_link
"""


def test_a_list_under_a_key_the_element_does_not_take_is_reported_once_at_the_key(demo_findings):
    found = demo_findings({"launch/a.launch.yaml": YAML_PARAMETERS}, "launch/a.launch.yaml", "L002")
    assert [(line, msg.split(";")[0]) for line, msg in found] == [(8, 'unknown tag "parameters"')]
    # launch refuses the file: the argument it declares is not "unused"
    assert demo_findings({"launch/a.launch.yaml": YAML_PARAMETERS}, "launch/a.launch.yaml", "L102") == []


@pytest.mark.parametrize(("entry", "text"), [
    ("launch/a.launch.yaml", 'launch:\n  deprecated: "use b.launch.yaml"\n  description: "the talker"\n'
                             "  children:\n  - node:\n      pkg: demo_nodes_cpp\n      exec: talker\n"),
    ("launch/a.launch.xml", '<launch deprecated="use b.launch.xml" author="me">\n'
                            '  <node pkg="demo_nodes_cpp" exec="talker"/>\n</launch>\n'),
])
def test_the_root_reads_deprecated_and_ignores_other_attributes(demo_findings, entry: str, text: str):
    # Parser.parse_description reads "deprecated" and never asserts the root entity was fully
    # parsed (humble-rolling): the humble library loads both files
    assert demo_findings({entry: text}, entry, "L002") == []
    nested = text.replace("<node", '<group deprecated="x">\n  <node').replace("</launch>", "</group>\n</launch>")
    if entry.endswith(".xml"):
        assert [line for line, _ in demo_findings({entry: nested}, entry, "L002")] == [2]
