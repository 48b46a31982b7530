"""T102 for a rule an earlier rule of the node shadows: rcl applies the first rule that matches
(``rcl_remap_first_match``), and a SetRemap in scope comes before the node's own remappings on the
command line (SEMANTICS §3), so the node's rule for the same name never applies, whatever topics
the node uses. A rule shared by several nodes is reported only when it is shadowed on each."""
LAUNCH = """from launch import LaunchDescription
from launch.actions import GroupAction
from launch_ros.actions import Node, PushRosNamespace, SetRemap

SHARED = [('cmd_vel', 'cmd_vel_joy')]


def generate_launch_description():
    return LaunchDescription([
        GroupAction([
            PushRosNamespace('robot1'),
            GroupAction([
                SetRemap(src='cmd_vel', dst='{dst}'),
                Node(package='teleop_twist_joy', executable='teleop_node', name='teleop_joy',
                     remappings=SHARED),
            ]),
            Node(package='teleop_twist_keyboard', executable='teleop', name='keys', remappings={other}),
            Node(package='demo', executable='twice', name='twice',
                 remappings=[('odom', 'odom_a'), ('/robot1/odom', 'odom_b'), ('scan', 'x'), ('scan', 'x')]),
        ]),
    ])
"""


def _t102(demo_findings, dst: str = "cmd_vel_teleop", other: str = "[]") -> list[tuple[int, str]]:
    text = LAUNCH.format(dst=dst, other=other)
    return demo_findings({"launch/a.launch.py": text}, "launch/a.launch.py", "T102")


def test_a_set_remap_shadows_the_nodes_own_rule(demo_findings):
    assert _t102(demo_findings) == [
        (5, 'remap "cmd_vel" -> "cmd_vel_joy" never applies to /robot1/teleop_joy: the SetRemap '
             '"cmd_vel" -> "cmd_vel_teleop" (line 13) matches "/robot1/cmd_vel" first, and rcl applies '
             "only the first rule that matches"),
        (19, 'remap "/robot1/odom" -> "odom_b" never applies to /robot1/twice: the rule "odom" -> '
             '"odom_a" (line 19) matches "/robot1/odom" first, and rcl applies only the first rule that '
             "matches"),
    ]


def test_a_shared_rule_that_applies_to_another_node_is_not_reported(demo_findings):
    assert [line for line, _ in _t102(demo_findings, other="SHARED")] == [19]


def test_a_shadowing_rule_with_the_same_effect_is_not_reported(demo_findings):
    assert [line for line, _ in _t102(demo_findings, dst="cmd_vel_joy")] == [19]
