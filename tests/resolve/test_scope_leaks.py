"""L111 scoped-group-leak: a SetRemap/SetParameter inside a scoped group appends to the list an
outer scope created (``GroupAction`` copies the configurations shallowly). It is reported when a
node launched after the group receives it and it changes what that node gets."""
from physai_lint.engine import CheckOptions, run_check

PKG = "demo_nodes_cpp"


def _leaks(tmp_path, demo_package, body: str, **more: str) -> list[tuple[int, str, list[int]]]:
    """(line, message, related lines) of the L111 findings of ``<launch>body</launch>``, with
    ``more`` launch files (name -> text) beside it."""
    files = {"launch/main.launch.xml": f"<launch>\n{body}\n</launch>\n",
             **{f"launch/{name}.launch.xml": text for name, text in more.items()}}
    path = demo_package(files) / "launch/main.launch.xml"
    report = run_check(CheckOptions(paths=[str(path)], workspace=str(tmp_path), select=("L111",)),
                       cwd=str(tmp_path))
    return [(f.span.line, f.message, [r.span.line for r in f.related]) for f in report.findings]


def test_a_leak_reaching_a_node_after_the_group_names_that_node(tmp_path, demo_package):
    found = _leaks(tmp_path, demo_package, f"""\
  <set_parameter name="use_sim_time" value="false"/>
  <group>
    <set_parameter name="use_sim_time" value="true"/>
    <node pkg="{PKG}" exec="listener" name="inner"/>
  </group>
  <node pkg="{PKG}" exec="talker" name="after"/>""")
    assert len(found) == 1
    line, message, related = found[0]
    assert line == 4 and related == [2, 7]
    assert 'parameter "use_sim_time"' in message and 'to node "/after"' in message


def test_a_leak_with_no_node_after_the_group_is_not_reported(tmp_path, demo_package):
    assert _leaks(tmp_path, demo_package, f"""\
  <set_parameter name="use_sim_time" value="false"/>
  <node pkg="{PKG}" exec="talker" name="before"/>
  <group>
    <set_parameter name="use_sim_time" value="true"/>
    <node pkg="{PKG}" exec="listener" name="inner"/>
  </group>""") == []


def test_a_leak_reaches_the_nodes_of_a_later_sibling_group(tmp_path, demo_package):
    found = _leaks(tmp_path, demo_package, f"""\
  <set_remap from="chatter" to="chatter_top"/>
  <group>
    <set_remap from="rosout_agg" to="agg_a"/>
    <node pkg="{PKG}" exec="listener" name="a"/>
  </group>
  <group>
    <node pkg="{PKG}" exec="talker" name="b"/>
  </group>""")
    assert [(line, related) for line, _, related in found] == [(4, [2, 8])]
    assert 'remap "rosout_agg:=agg_a"' in found[0][1] and 'node "/b"' in found[0][1]


def test_a_leak_that_sets_the_value_the_nodes_already_get_changes_nothing(tmp_path, demo_package):
    # The multi-robot pattern: every included robot sets use_sim_time as the top level did.
    assert _leaks(tmp_path, demo_package, f"""\
  <arg name="sim" default="true"/>
  <set_parameter name="use_sim_time" value="true"/>
  <group>
    <set_parameter name="use_sim_time" value="$(var sim)"/>
    <node pkg="{PKG}" exec="listener" name="robot1"/>
  </group>
  <group>
    <set_parameter name="use_sim_time" value="True"/>
    <node pkg="{PKG}" exec="listener" name="robot2"/>
  </group>
  <node pkg="{PKG}" exec="talker" name="after"/>""") == []


def test_a_leak_overridden_before_the_next_node_changes_nothing(tmp_path, demo_package):
    assert _leaks(tmp_path, demo_package, f"""\
  <set_parameter name="rate" value="1.0"/>
  <group>
    <set_parameter name="rate" value="5.0"/>
    <node pkg="{PKG}" exec="listener" name="inner"/>
  </group>
  <set_parameter name="rate" value="2.0"/>
  <node pkg="{PKG}" exec="talker" name="after"/>""") == []


def test_a_leaked_value_of_another_type_is_a_change(tmp_path, demo_package):
    found = _leaks(tmp_path, demo_package, f"""\
  <set_parameter name="rate" value="1"/>
  <group>
    <set_parameter name="rate" value="1.0"/>
  </group>
  <node pkg="{PKG}" exec="talker" name="after"/>""")
    assert [line for line, _, _ in found] == [4]


def test_two_groups_leaking_the_same_value_still_change_the_outer_one(tmp_path, demo_package):
    found = _leaks(tmp_path, demo_package, f"""\
  <set_parameter name="mode" value="outer"/>
  <group>
    <set_parameter name="mode" value="inner"/>
  </group>
  <group>
    <set_parameter name="mode" value="inner"/>
  </group>
  <node pkg="{PKG}" exec="talker" name="after"/>""")
    assert [line for line, _, _ in found] == [7]


def test_a_leaked_remap_behind_an_earlier_rule_for_the_same_name_changes_nothing(tmp_path, demo_package):
    # rcl applies the first rule that matches a name
    assert _leaks(tmp_path, demo_package, f"""\
  <set_remap from="chatter" to="chatter_top"/>
  <group>
    <set_remap from="chatter" to="chatter_inner"/>
    <node pkg="{PKG}" exec="listener" name="inner"/>
  </group>
  <node pkg="{PKG}" exec="talker" name="after"/>""") == []


def test_a_group_that_creates_the_list_does_not_leak(tmp_path, demo_package):
    assert _leaks(tmp_path, demo_package, f"""\
  <group>
    <set_remap from="chatter" to="chatter_inner"/>
    <node pkg="{PKG}" exec="listener" name="inner"/>
  </group>
  <node pkg="{PKG}" exec="talker" name="after"/>""") == []


def test_a_leak_from_a_nested_group_reaches_a_node_of_the_enclosing_group(tmp_path, demo_package):
    found = _leaks(tmp_path, demo_package, f"""\
  <set_parameter name="mode" value="outer"/>
  <group>
    <group>
      <set_parameter name="mode" value="inner"/>
    </group>
    <node pkg="{PKG}" exec="talker" name="x"/>
  </group>""")
    assert [(line, related) for line, _, related in found] == [(5, [2, 7])]


def test_a_leaked_value_is_the_one_the_action_saw(tmp_path, demo_package):
    # SetParameter.execute evaluates the value when it runs: "false" here, whatever sim is later
    found = _leaks(tmp_path, demo_package, f"""\
  <arg name="sim" default="true"/>
  <set_parameter name="use_sim_time" value="true"/>
  <group>
    <let name="sim" value="false"/>
    <set_parameter name="use_sim_time" value="$(var sim)"/>
  </group>
  <node pkg="{PKG}" exec="talker" name="after"/>""")
    assert [line for line, _, _ in found] == [6]


def test_a_leaked_parameter_file_is_a_change(tmp_path, demo_package):
    found = _leaks(tmp_path, demo_package, f"""\
  <set_parameter name="use_sim_time" value="true"/>
  <group>
    <set_parameters_from_file filename="$(find-pkg-share demo)/config/a.yaml"/>
  </group>
  <node pkg="{PKG}" exec="talker" name="after"/>""")
    assert [(line, message.split(" inside")[0]) for line, message, _ in found] == [(4, "parameter file")]


def test_a_node_setting_the_parameter_itself_gets_nothing_from_the_leak(tmp_path, demo_package):
    assert _leaks(tmp_path, demo_package, f"""\
  <set_parameter name="rate" value="1.0"/>
  <group>
    <set_parameter name="rate" value="5.0"/>
  </group>
  <node pkg="{PKG}" exec="talker" name="after">
    <param name="rate" value="2.0"/>
  </node>""") == []


def test_every_node_reached_through_includes_is_named(tmp_path, demo_package):
    robot = f"""<launch>
  <node pkg="{PKG}" exec="talker" name="t"/>
</launch>
"""
    found = _leaks(tmp_path, demo_package, """\
  <set_remap from="chatter" to="chatter_top"/>
  <group>
    <set_remap from="rosout_agg" to="agg_inner"/>
  </group>
  <group><push_ros_namespace namespace="r1"/><include file="$(find-pkg-share demo)/launch/robot.launch.xml"/></group>
  <group><push_ros_namespace namespace="r2"/><include file="$(find-pkg-share demo)/launch/robot.launch.xml"/></group>""",
                   robot=robot)
    assert len(found) == 1
    assert 'to node "/r1/t", node "/r2/t":' in found[0][1]
    assert found[0][2] == [2, 2]  # the outer action, the one node
