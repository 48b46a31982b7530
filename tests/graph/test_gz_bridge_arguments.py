"""ros_gz's parameter_bridge and create: their topics come from their arguments
(interfaces/arguments.py, after ros_gz_bridge parameter_bridge.cpp :: main and ros_gz_sim create.cpp)."""
from __future__ import annotations

from types import SimpleNamespace
from typing import Any

import pytest

from physai_lint.interfaces.arguments import _bridge, from_arguments


@pytest.mark.parametrize("arg, expected", [
    ("/clock@rosgraph_msgs/msg/Clock[gz.msgs.Clock", ("/clock", "rosgraph_msgs/msg/Clock", "gz_to_ros")),
    ("cmd_vel@geometry_msgs/msg/Twist]gz.msgs.Twist", ("cmd_vel", "geometry_msgs/msg/Twist", "ros_to_gz")),
    ("/chatter@std_msgs/msg/String@gz.msgs.StringMsg", ("/chatter", "std_msgs/msg/String", "both")),
    ("/world/default/create@ros_gz_interfaces/srv/SpawnEntity", ("/world/default/create",
                                                                "ros_gz_interfaces/srv/SpawnEntity", "service")),
    ("@std_msgs/msg/String@gz.msgs.StringMsg", None),  # no name: usage() and exit
    ("/chatter@std_msgs/msg/String", None),  # a topic without a Gazebo type
    ("/x@ros_gz_interfaces/srv/SpawnEntity[gz.msgs.EntityFactory", None),  # a service one way
])
def test_bridge_arguments(arg: str, expected: Any) -> None:
    assert _bridge(arg) == expected


def node(package: str, executable: str, arguments: tuple[Any, ...], sources: tuple[Any, ...] = ()) -> Any:
    return SimpleNamespace(package=package, executable=executable, arguments=arguments, param_sources=list(sources))


def test_ros_arguments_are_not_bridges() -> None:
    iface = from_arguments(None, node("ros_gz_bridge", "parameter_bridge", (
        "odom@nav_msgs/msg/Odometry[gz.msgs.Odometry", "--ros-args", "-r", "odom:=wheel/odom")))
    assert iface is not None and [(e.name, e.type) for e in iface.publishers or []] == [
        ("odom", "nav_msgs/msg/Odometry")] and not iface.subscribers


def test_unknown_arguments_or_a_config_file_leave_the_bridge_unknown() -> None:
    assert from_arguments(None, node("ros_gz_bridge", "parameter_bridge", (None,))) is None
    config = SimpleNamespace(params=(SimpleNamespace(name="config_file"),))
    assert from_arguments(None, node("ros_gz_bridge", "parameter_bridge", (), (config,))) is None
    sim_time = SimpleNamespace(params=(SimpleNamespace(name="use_sim_time"),))
    assert from_arguments(None, node("ros_gz_bridge", "parameter_bridge", (), (sim_time,))) is not None


def test_create_waits_on_its_topic_only_without_a_file() -> None:
    subs = from_arguments(None, node("ros_gz_sim", "create", ("-topic", "robot_description", "-name", "r1")))
    assert subs is not None and [e.name for e in subs.subscribers or []] == ["robot_description"]
    from_file = from_arguments(None, node("ros_gz_sim", "create", ("-file", "/tmp/r.sdf", "-topic", "x")))
    assert from_file is not None and from_file.subscribers == []


LAUNCH = """from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='ros_gz_bridge', executable='parameter_bridge', namespace='robot1',
             arguments=['cmd_vel@geometry_msgs/msg/Twist]gz.msgs.Twist']),
        Node(package='ros_gz_bridge', executable='parameter_bridge', namespace='robot1',
             arguments=['/scan@sensor_msgs/msg/LaserScan[gz.msgs.LaserScan']),
    ])
"""


def test_bridges_in_the_graph(demo_findings: Any) -> None:
    files = {"launch/a.launch.py": LAUNCH}
    t201 = demo_findings(files, "launch/a.launch.py", "T201")
    assert [m.split(" but")[0] for _, m in t201] == ['/robot1/ros_gz_bridge subscribes to "/robot1/cmd_vel"']
    assert [line for line, _ in t201] == [8]  # at the argument that makes the subscription
    n101 = demo_findings(files, "launch/a.launch.py", "N101")
    assert [line for line, _ in n101] == [9]  # both bridges are /robot1/ros_gz_bridge


@pytest.mark.parametrize("arg", ["x@std_msgs/msg/String[", "x@std_msgs/msg/String@gz.msgs.StringMsg@more",
                                 "/s@std_srvs/srv/Trigger@gz.msgs.Empty"])
def test_arguments_the_bridge_refuses(arg: str) -> None:
    assert _bridge(arg) is None


def test_create_reads_param_before_topic_and_double_dash_flags() -> None:
    param = from_arguments(None, node("ros_gz_sim", "create", ("-param", "robot_description", "-topic", "rd")))
    assert param is not None and param.subscribers == []
    dashes = from_arguments(None, node("ros_gz_sim", "create", ("--topic", "rd")))
    assert dashes is not None and [e.name for e in dashes.subscribers or []] == ["rd"]
    by_parameter = SimpleNamespace(params=(SimpleNamespace(name="topic"),))
    assert from_arguments(None, node("ros_gz_sim", "create", (), (by_parameter,))) is None


CLOCK = """from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='ros_gz_bridge', executable='parameter_bridge', namespace='robot1', name='clock',
             arguments=['clock@rosgraph_msgs/msg/Clock[gz.msgs.Clock']),
        Node(package='ros_gz_bridge', executable='parameter_bridge', name='drive',
             parameters=[{'use_sim_time': @SIM@}], remappings=[@REMAP@],
             arguments=['/cmd_vel@geometry_msgs/msg/Twist]gz.msgs.Twist']),
    ])
"""


def _clock_findings(demo_findings: Any, sim: str, remap: str = "") -> list[tuple[int, str]]:
    text = CLOCK.replace("@SIM@", sim).replace("@REMAP@", remap)
    return demo_findings({"launch/a.launch.py": text}, "launch/a.launch.py", "T202")


def test_a_clock_bridged_in_a_namespace_misses_the_sim_time_clock(demo_findings: Any) -> None:
    # rclcpp's time source subscribes to the absolute /clock when use_sim_time is true
    ((line, message),) = _clock_findings(demo_findings, "True")
    assert line == 8
    assert message.startswith('/robot1/clock publishes "/robot1/clock" but nothing subscribes to it '
                              '(did you mean "/clock", which the time source of /drive')


def test_the_sim_time_clock_follows_the_node_s_remaps_and_its_use_sim_time(demo_findings: Any) -> None:
    assert _clock_findings(demo_findings, "False") == []
    assert _clock_findings(demo_findings, "True", "('/clock', '/robot1/clock')") == []
