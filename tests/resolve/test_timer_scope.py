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
