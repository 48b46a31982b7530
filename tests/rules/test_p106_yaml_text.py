"""P106 on list-looking text YAML cannot read (``value="[*]"``, rosapi's globs): a literal XML or
YAML launch attribute stays the string it is (launch's get_attr keeps text YAML rejects), while
a substituted value is read with YAML rules and fails, which the message says as it is."""
from __future__ import annotations

XML = """<launch>
  <arg name="g" default="[*]"/>
  <node pkg="rosapi" exec="rosapi_node">
    <param name="topics_glob" value="[*]"/>
    <param name="services_glob" value="$(var g)"/>
    <param name="mixed" value="[1, 'a']"/>
  </node>
</launch>
"""
YAML = """launch:
- node:
    pkg: rosapi
    exec: rosapi_node
    param:
    - {name: topics_glob, value: "[*]"}
"""


def test_literal_text_is_a_string_and_substituted_text_fails(demo_findings):
    found = demo_findings({"launch/a.launch.xml": XML}, "launch/a.launch.xml", "P106")
    assert [(line, message.split(";")[0]) for line, message in found] == [
        (5, ('parameter "services_glob" value "[*]" is not valid YAML (did not find expected alphabetic or '
             'numeric character)')),
        (6, 'parameter "mixed" value "[1, \'a\']" is a list with items of different types'),
    ]
    assert demo_findings({"launch/a.launch.yaml": YAML}, "launch/a.launch.yaml", "P106") == []


def test_a_literal_xml_list_of_mappings_fails_in_get_attr_and_says_so(demo_findings):
    # launch_xml's Entity.get_attr coerces the literal with YAML rules (no type): a list whose
    # items are mappings, or scalars of two types, is no allowed type and raises TypeError there;
    # the same text through a substitution passes get_attr and fails later, in launch_ros
    xml = """<launch>
  <arg name="o" default="[1, 2.5]"/>
  <node pkg="demo_nodes_cpp" exec="talker" name="origin">
    <param name="origins" value="[{name: a, lat: 1.0}, {name: b, lat: 2.0}]"/>
    <param name="mixed" value="[1, 2.5]"/>
    <param name="substituted" value="$(var o)"/>
  </node>
</launch>
"""
    found = demo_findings({"launch/a.launch.xml": xml}, "launch/a.launch.xml", "P106")
    assert [(line, "reading the attribute with TypeError" in message) for line, message in found] == [
        (4, True), (5, True), (6, False)]
    assert "items that are not scalars of one type" in found[0][1]
