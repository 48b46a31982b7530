"""S102 handler-never-fires: a handler registered under the same condition as its target is not
registered when the target is disabled (nav2_bringup's rviz_launch.py), so it is no finding; one
registered unconditionally for a disabled target still is."""
LAUNCH = """
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, EmitEvent, RegisterEventHandler
from launch.conditions import UnlessCondition
from launch.event_handlers import OnProcessExit
from launch.events import Shutdown
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    use_ns = LaunchConfiguration("use_namespace")
    talker = Node(package="demo_nodes_cpp", executable="talker", condition=UnlessCondition(use_ns))
    on_exit = RegisterEventHandler(
        {condition}event_handler=OnProcessExit(target_action=talker,
                                               on_exit=EmitEvent(event=Shutdown(reason="talker exited"))))
    return LaunchDescription([DeclareLaunchArgument("use_namespace", default_value="true"), talker, on_exit])
"""


def _s102(demo_findings, condition: str) -> list[str]:
    return ["S102" for _ in demo_findings({"launch/a.launch.py": LAUNCH.format(condition=condition)},
                                          "launch/a.launch.py", "S102")]


def test_a_handler_under_its_targets_condition_is_not_reported(demo_findings):
    assert _s102(demo_findings, "condition=UnlessCondition(use_ns), ") == []


def test_an_unconditional_handler_of_a_disabled_target_is(demo_findings):
    assert _s102(demo_findings, "") == ["S102"]
