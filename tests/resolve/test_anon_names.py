"""``$(anon ID)`` / ``AnonName(ID)``: AnonName.perform generates the name for ID once and keeps it in
``launch_configurations['anon']``, a dict made where it is first needed. A scope pushed later
copies the configurations shallowly and shares that dict; one made inside a scope is dropped with
it. Two nodes named ``$(anon rviz)`` that share the dict get the same name (N101)."""
from __future__ import annotations

XML = """<launch>
  <node pkg="rviz2" exec="rviz2" name="$(anon rviz)"/>
  <node pkg="rviz2" exec="rviz2" name="$(anon rviz)"/>
  <node pkg="rviz2" exec="rviz2" name="$(anon other)"/>
  <group>
    <node pkg="rviz2" exec="rviz2" name="$(anon rviz)"/>
    <node pkg="rviz2" exec="rviz2" name="$(anon inner)"/>
  </group>
  <group>
    <node pkg="rviz2" exec="rviz2" name="$(anon inner)"/>
  </group>
  <group>
    <push-ros-namespace namespace="side"/>
    <node pkg="rviz2" exec="rviz2" name="$(anon rviz)"/>
  </group>
</launch>
"""


SCOPED = """<launch>
  <group>
    <node pkg="rviz2" exec="rviz2" name="$(anon a)"/>
  </group>
  <group>
    <node pkg="rviz2" exec="rviz2" name="$(anon a)"/>
  </group>
</launch>
"""


def test_anon_names_shared_where_launch_shares_them(demo_findings):
    # (names as the humble launch library gives them, with launch 1.0.7 / launch_ros 0.19.8)
    found = demo_findings({"launch/a.launch.xml": XML}, "launch/a.launch.xml", "N101")
    # line 3: the second at the top; line 6: a scope pushed after the dict was made shares it,
    # and adds "inner" to it, which the next group sees (line 10); /side is another namespace
    assert [line for line, _ in found] == [3, 6, 10]
    assert found[0][1].startswith('node "/$(anon rviz)" is launched twice (also at line 2): AnonName makes '
                                  'the name for "rviz" once')


def test_anon_dict_made_inside_a_scope_is_dropped_with_it(demo_findings):
    assert demo_findings({"launch/a.launch.xml": SCOPED}, "launch/a.launch.xml", "N101") == []
