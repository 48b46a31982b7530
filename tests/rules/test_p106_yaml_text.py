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
