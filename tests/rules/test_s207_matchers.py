"""S207: which ChangeState matchers reach a LifecycleNode (launch_ros ``matches_node_name`` compares
'/' + name with the full name; only ``LifecycleNode`` actions handle ChangeState)."""
from __future__ import annotations

from typing import Any

HEAD = """import lifecycle_msgs.msg
from launch import LaunchDescription
from launch.actions import EmitEvent, DeclareLaunchArgument
from launch.events import matches_action
from launch.substitutions import EnvironmentVariable, LaunchConfiguration
from launch_ros.actions import LifecycleNode, Node
from launch_ros.events.lifecycle import ChangeState, matches_node_name


def configure(matcher):
    return EmitEvent(event=ChangeState(lifecycle_node_matcher=matcher,
                                       transition_id=lifecycle_msgs.msg.Transition.TRANSITION_CONFIGURE))


def generate_launch_description():
    lidar = LifecycleNode(package='demo', executable='lidar', name='lidar', namespace=@NS@)
    plain = Node(package='demo', executable='imu', name='imu')
    return LaunchDescription([
        DeclareLaunchArgument('who', default_value='/lidar'),
        lidar,
        plain,
        configure(@MATCHER@),
    ])
"""


def run(demo_findings: Any, matcher: str, ns: str = "'sensors'") -> list[str]:
    text = HEAD.replace("@MATCHER@", matcher).replace("@NS@", ns)
    return [m for _, m in demo_findings({"launch/a.launch.py": text}, "launch/a.launch.py", "S207")]


def test_a_relative_name_is_compared_without_the_namespace(demo_findings: Any) -> None:
    (msg,) = run(demo_findings, "matches_node_name(node_name='lidar')")
    assert '"/lidar"' in msg and 'did you mean "/sensors/lidar"?' in msg


def test_the_full_name_matches(demo_findings: Any) -> None:
    assert run(demo_findings, "matches_node_name('/sensors/lidar')") == []
    assert run(demo_findings, "matches_node_name('lidar')", ns="''") == []


def test_a_name_of_a_plain_node_is_named_as_such(demo_findings: Any) -> None:
    (msg,) = run(demo_findings, "matches_node_name('imu')")
    assert "/imu is a node action, not a LifecycleNode" in msg


def test_matches_action_on_a_plain_node(demo_findings: Any) -> None:
    (msg,) = run(demo_findings, "matches_action(plain)")
    assert "at a Node action (/imu)" in msg
    assert run(demo_findings, "matches_action(lidar)") == []


def test_matchers_not_known_statically_stay_silent(demo_findings: Any) -> None:
    assert run(demo_findings, "lambda action: True") == []
    assert run(demo_findings, "matches_node_name(LaunchConfiguration('who'))") == []


def test_a_lifecycle_node_whose_name_is_unknown_may_be_the_one(demo_findings: Any) -> None:
    assert run(demo_findings, "matches_node_name('camera')", ns="EnvironmentVariable('ROBOT_NS')") == []


INCLUDER = """from launch import LaunchDescription
from launch.actions import GroupAction, IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch_ros.actions import PushRosNamespace


def generate_launch_description():
    return LaunchDescription([GroupAction([
        PushRosNamespace('robot1'),
        IncludeLaunchDescription(PythonLaunchDescriptionSource(
            '/ws/install/demo/share/demo/launch/a.launch.py'.replace('/ws/install/demo/share/demo', THIS))),
    ])])
"""


def test_a_namespace_pushed_by_the_includer_is_not_added_either(demo_findings: Any) -> None:
    child = HEAD.replace("@MATCHER@", "matches_node_name('/lidar')").replace("@NS@", "''")
    parent = INCLUDER.replace(
        "'/ws/install/demo/share/demo/launch/a.launch.py'.replace('/ws/install/demo/share/demo', THIS)",
        "[ThisLaunchFileDir(), '/a.launch.py']").replace(
        "from launch.launch_description_sources", "from launch.substitutions import ThisLaunchFileDir\n"
        "from launch.launch_description_sources")
    found = demo_findings({"launch/a.launch.py": child, "launch/top.launch.py": parent}, "launch/top.launch.py", "S207")
    assert [m.split(":")[0] for _, m in found] == [
        "ChangeState's matches_node_name('/lidar') compares with the full name \"/lidar\" (a namespace of the "
        "node, of its file or pushed by an including file is not added), and no LifecycleNode of this launch "
        "has that name"]


def test_a_helper_called_with_two_wrong_names_reports_each(demo_findings: Any) -> None:
    text = HEAD.replace("@MATCHER@", "matches_node_name(NAME)").replace("@NS@", "'sensors'").replace(
        "        configure(matches_node_name(NAME)),",
        "        configure(matches_node_name('lidar')),\n        configure(matches_node_name('/camera')),")
    found = demo_findings({"launch/a.launch.py": text}, "launch/a.launch.py", "S207")
    assert sorted(m.split(" compares")[0] for _, m in found) == [
        "ChangeState's matches_node_name('/camera')", "ChangeState's matches_node_name('lidar')"]
