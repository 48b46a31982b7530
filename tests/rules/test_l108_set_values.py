"""L108 knows the values a <let> / SetLaunchConfiguration without a condition surely set before a
condition, in execution order: not one set in a scoped group the condition is outside of, by a
conditional <let>, before an include (whose configurations leak out; its own arguments stay set),
or read by an action launch runs later (a timer)."""
from __future__ import annotations

from typing import Any

XML = """<launch>
  <arg name="use_gui" default="true"/>
  <let name="use_gui" value="false"/>
  <log message="a" if="$(var use_gui)"/>
  <let name="mode" value="nav"/>
  <log message="b" if="$(eval &quot;'$(var mode)' == 'slam'&quot;)"/>
  <group>
    <let name="scoped" value="false"/>
    <log message="c" if="$(var scoped)"/>
  </group>
  <log message="d" if="$(var scoped)"/>
  <let name="maybe" value="false" if="$(var use_gui)"/>
  <log message="e" if="$(var maybe)"/>
  <timer period="1.0">
    <log message="f" if="$(var mode)"/>
  </timer>
  <let name="later" value="false"/>
  <include file="$(find-pkg-share demo)/launch/other.launch.xml"/>
  <log message="g" if="$(var later)"/>
</launch>
"""
OTHER = """<launch>
  <let name="later" value="true"/>
</launch>
"""
PY = """from launch import LaunchDescription
from launch.actions import LogInfo, SetLaunchConfiguration
from launch.conditions import LaunchConfigurationEquals


def generate_launch_description():
    return LaunchDescription([
        SetLaunchConfiguration('drive', 'diff_drive'),
        LogInfo(msg='x', condition=LaunchConfigurationEquals('drive', 'ackermann')),
        LogInfo(msg='y', condition=LaunchConfigurationEquals('drive', 'diff_drive')),
    ])
"""


def test_values_set_before_a_condition_decide_it(demo_findings: Any) -> None:
    files = {"launch/a.launch.xml": XML, "launch/other.launch.xml": OTHER}
    found = demo_findings(files, "launch/a.launch.xml", "L108")
    assert [(line, msg.split(";")[0].split(": ", 1)[1]) for line, msg in found] == [
        (4, 'launch configuration "use_gui" is "false" here (set at line 3), so "$(var use_gui)" is false'),
        (6, 'launch configuration "mode" is "nav" here (set at line 5), so '
            '"$(eval "\'$(var mode)\' == \'slam\'")" is false'),
        (9, 'launch configuration "scoped" is "false" here (set at line 8), so "$(var scoped)" is false'),
        (12, 'launch configuration "use_gui" is "false" here (set at line 3), so "$(var use_gui)" is false'),
    ]


def test_launch_configuration_equals_after_a_set(demo_findings: Any) -> None:
    found = demo_findings({"launch/a.launch.py": PY}, "launch/a.launch.py", "L108")
    assert [(line, 'is "diff_drive" here (set at line 8)' in msg) for line, msg in found] == [(9, True)]


def test_a_set_under_a_condition_anywhere_makes_the_value_unknown(demo_findings: Any) -> None:
    """An OpaqueFunction that may run (it has a condition) and sets the configuration: after it,
    the earlier value no longer decides anything."""
    text = PY.replace("        LogInfo(msg='x',", """        OpaqueFunction(function=lambda context: [SetLaunchConfiguration('drive', 'ackermann')],
                       condition=IfCondition(LaunchConfiguration('switch'))),
        LogInfo(msg='x',""").replace(
        "from launch.actions import LogInfo, SetLaunchConfiguration",
        "from launch.actions import LogInfo, OpaqueFunction, SetLaunchConfiguration\n"
        "from launch.conditions import IfCondition\nfrom launch.substitutions import LaunchConfiguration")
    assert demo_findings({"launch/a.launch.py": text}, "launch/a.launch.py", "L108") == []


def test_an_include_argument_holds_in_the_includer_after_it(demo_findings: Any) -> None:
    # IncludeLaunchDescription.execute sets its arguments in the includer's scope; the included
    # file here sets "later" itself, so only "gui" stays known
    xml = """<launch>
  <arg name="gui" default="true" description="a"/>
  <include file="$(find-pkg-share demo)/launch/other.launch.xml">
    <arg name="gui" value="false"/>
    <arg name="later" value="false"/>
  </include>
  <log message="a" if="$(var gui)"/>
  <log message="b" if="$(var later)"/>
</launch>
"""
    other = OTHER.replace("</launch>", '  <arg name="gui" default="true"/>\n  <log message="$(var gui)"/>\n</launch>')
    files = {"launch/a.launch.xml": xml, "launch/other.launch.xml": other}
    found = demo_findings(files, "launch/a.launch.xml", "L108")
    assert [(line, 'is "false" here (set at line 4)' in msg) for line, msg in found] == [(7, True)]
    # a file that includes others may set anything
    nested = other.replace("</launch>", '  <include file="$(find-pkg-share demo)/launch/c.launch.xml"/>\n</launch>')
    files = {**files, "launch/other.launch.xml": nested, "launch/c.launch.xml": "<launch/>\n"}
    assert demo_findings(files, "launch/a.launch.xml", "L108") == []


def test_an_unscoped_group_in_the_included_file_may_set_the_argument(demo_findings: Any) -> None:
    xml = """<launch>
  <include file="$(find-pkg-share demo)/launch/other.launch.xml">
    <arg name="gui" value="false"/>
  </include>
  <log message="a" if="$(var gui)"/>
</launch>
"""
    other = ("from launch import LaunchDescription\nfrom launch.actions import GroupAction\n\n\n"
             "def generate_launch_description():\n"
             "    return LaunchDescription([GroupAction([], scoped=False,\n"
             "                                          launch_configurations={'gui': 'true'})])\n")
    xml = xml.replace("other.launch.xml", "other.launch.py")
    files = {"launch/a.launch.xml": xml, "launch/other.launch.py": other}
    assert demo_findings(files, "launch/a.launch.xml", "L108") == []
