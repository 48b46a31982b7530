"""L110: what an action started by a timer or an event handler loses of its group's scope."""
from __future__ import annotations

LAUNCH = """
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, GroupAction, RegisterEventHandler
from launch.event_handlers import OnProcessExit
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node, PushRosNamespace


def generate_launch_description():
    ns = LaunchConfiguration('namespace')
    first = Node(package='demo_nodes_cpp', executable='talker', name='first')
    second = Node(package='demo_nodes_cpp', executable='listener', name='second', NS_KW)
    return LaunchDescription([
        DeclareLaunchArgument('namespace', default_value='DEFAULT'),
        GroupAction([
            PushRosNamespace(ns),
            first,
            RegisterEventHandler(OnProcessExit(target_action=first, on_exit=[second])),
        ]),
    ])
"""


def _l110(demo_findings, default: str, own_namespace: bool) -> list[str]:
    text = LAUNCH.replace("DEFAULT", default).replace(", NS_KW", ", namespace=ns" if own_namespace else "")
    return [msg for _, msg in demo_findings({"launch/a.launch.py": text}, "launch/a.launch.py", "L110")]


def test_a_pushed_namespace_is_lost_by_a_handler_started_node(demo_findings):
    (msg,) = _l110(demo_findings, "robot1", own_namespace=False)
    assert 'loses namespace "/robot1"' in msg


def test_the_root_namespace_is_nothing_to_lose(demo_findings):
    # PushRosNamespace('') pushes "/" (make_namespace_absolute('')): the node runs in "/" anyway
    assert _l110(demo_findings, "", own_namespace=False) == []


def test_a_node_that_names_the_namespace_itself_loses_nothing(demo_findings):
    # create3_sim: "Namespace is not pushed when used in EventHandler", so the node passes it
    assert _l110(demo_findings, "robot1", own_namespace=True) == []


# TimerAction.execute only schedules _wait_to_fire_event, which performs the period once the whole
# description has been visited: with the launch configurations left at the top by then.
FLEET = """<launch>
  <group>
    <include file="$(dirname)/robot.launch.xml"/>
  </group>
</launch>
"""

ROBOT = """<launch>
  <arg name="delay" default="4.0"/>
  <timer period="$(var delay)">
    <node pkg="rviz2" exec="rviz2" name="rviz"/>
  </timer>
</launch>
"""

LATE = """<launch>
  <timer period="$(var delay)">
    <node pkg="rviz2" exec="rviz2" name="rviz"/>
  </timer>
  <arg name="delay" default="4.0"/>
</launch>
"""


def test_a_timer_period_read_in_a_group_is_performed_after_the_group(demo_findings):
    files = {"launch/fleet.launch.xml": FLEET, "launch/robot.launch.xml": ROBOT}
    (found,) = demo_findings(files, "launch/fleet.launch.xml", "L101")
    assert found[0] == 3 and found[1].startswith(
        'launch configuration "delay" is not set when the TimerAction performs its period; '
        "TimerAction._wait_to_fire_event performs it once the whole launch description has been visited")
    # the same file launched alone keeps its argument at the top: nothing to report
    assert demo_findings(files, "launch/robot.launch.xml", "L101") == []


def test_a_timer_period_may_read_an_argument_declared_after_the_timer(demo_findings):
    assert demo_findings({"launch/a.launch.xml": LATE}, "launch/a.launch.xml", "L101") == []


def test_the_period_still_delays_the_timer_actions(tmp_path, demo_package):
    import json

    from physai_lint import api
    from physai_lint.engine import CheckOptions

    path = str(demo_package({"launch/a.launch.xml": LATE}) / "launch/a.launch.xml")
    opts = CheckOptions(paths=[path], launch_args={"delay": "2.5"}, workspace=str(tmp_path))
    nodes = json.loads(api.plan(opts, path, "json"))["vertices"]
    assert [(n["fqn"], n["delay"]) for n in nodes] == [("/rviz", 2.5)]
