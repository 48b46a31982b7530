"""S101 through an action that is no node: the resolver walks an event handler's actions as if its
event came, so a TimerAction started only when a node starts, whose completion alone starts that
node, looked started; the plan's cycles are of nodes only. Such a cycle is found from which actions
start at all: those visited outside any handler, then those whose targets start."""
HEAD = """from launch import LaunchDescription
from launch.actions import GroupAction, RegisterEventHandler, TimerAction
from launch.event_handlers import OnExecutionComplete, OnProcessStart
from launch_ros.actions import Node


def generate_launch_description():
    move_group = Node(package='moveit_ros_move_group', executable='move_group')
    spawner = Node(package='controller_manager', executable='spawner', arguments=['arm'])
    delayed = TimerAction(period=3.0, actions=[spawner])
"""

CYCLE = HEAD + """    return LaunchDescription([
        RegisterEventHandler(OnProcessStart(target_action=move_group, on_start=[delayed])),
        RegisterEventHandler(OnExecutionComplete(target_action=delayed, on_completion=[move_group])),
    ])
"""

ROOTED = HEAD + """    return LaunchDescription([
        delayed,
        RegisterEventHandler(OnExecutionComplete(target_action=delayed, on_completion=[move_group])),
    ])
"""

CHAIN = HEAD + """    return LaunchDescription([
        move_group,
        RegisterEventHandler(OnProcessStart(target_action=move_group, on_start=[delayed])),
        RegisterEventHandler(OnExecutionComplete(target_action=delayed, on_completion=[
            Node(package='rviz2', executable='rviz2')])),
    ])
"""

GROUPED = HEAD + """    group = GroupAction([spawner])
    return LaunchDescription([
        RegisterEventHandler(OnProcessStart(target_action=move_group, on_start=[group])),
        RegisterEventHandler(OnExecutionComplete(target_action=group, on_completion=[move_group])),
    ])
"""


def _s101(demo_findings, text: str) -> list[tuple[int, str]]:
    return demo_findings({"launch/a.launch.py": text}, "launch/a.launch.py", "S101")


def test_a_timer_and_a_node_waiting_for_each_other_never_start(demo_findings):
    assert _s101(demo_findings, CYCLE) == [(12, (
        'startup cycle TimerAction (line 10) -> "move_group" -> TimerAction (line 10): TimerAction '
        '(line 10) waits for start of "move_group", "move_group" waits for completion of TimerAction '
        "(line 10); each only starts from another's event handler, so none of them ever starts"))]


def test_a_group_in_the_cycle_is_named_too(demo_findings):
    ((line, message),) = _s101(demo_findings, GROUPED)
    assert line == 13 and message.startswith('startup cycle GroupAction (line 11) -> "move_group"')


def test_a_timer_in_the_description_is_the_root(demo_findings):
    assert _s101(demo_findings, ROOTED) == []


def test_a_chain_from_a_started_node_is_no_cycle(demo_findings):
    assert _s101(demo_findings, CHAIN) == []


LIFECYCLE = """from launch import LaunchDescription
from launch.actions import EmitEvent, RegisterEventHandler
from launch.event_handlers import OnProcessStart
from launch.events import matches_action
from launch_ros.actions import LifecycleNode, Node
from launch_ros.event_handlers import OnStateTransition
from launch_ros.events.lifecycle import ChangeState
from lifecycle_msgs.msg import Transition


def generate_launch_description():
    lidar = LifecycleNode(package='demo', executable='lidar', name='lidar', namespace='')
    relay = Node(package='demo', executable='relay', name='relay')
    configure = EmitEvent(event=ChangeState(lifecycle_node_matcher=matches_action(lidar),
                                            transition_id=Transition.TRANSITION_CONFIGURE))
    activate = EmitEvent(event=ChangeState(lifecycle_node_matcher=matches_action(lidar),
                                           transition_id=Transition.TRANSITION_ACTIVATE))
    return LaunchDescription([
        lidar,
        RegisterEventHandler(OnProcessStart(target_action={first}, on_start=[configure])),
        RegisterEventHandler(OnStateTransition(target_lifecycle_node=lidar, goal_state='inactive',
                                               entities=[activate])),
        RegisterEventHandler(OnStateTransition(target_lifecycle_node=lidar, goal_state='active',
                                               entities=[relay])),{more}
    ])
"""


def test_a_lifecycle_node_configured_only_by_what_its_transition_starts(demo_findings):
    # the CONFIGURE request waits for the relay, which waits for the node to become active: the
    # ACTIVATE request cannot come first (it waits for a transition itself)
    ((line, message),) = _s101(demo_findings, LIFECYCLE.format(first="relay", more=""))
    assert line == 20
    assert message == (
        'startup cycle "/lidar" -> EmitEvent (line 14) -> "/relay" -> "/lidar": "/lidar" changes state only '
        'when EmitEvent (line 14) requests it, EmitEvent (line 14) waits for start of "/relay", "/relay" '
        'waits for a state transition of "/lidar"; the lifecycle node never changes state, so nothing '
        "waiting for its transitions runs")


def test_a_lifecycle_node_configured_when_it_starts_is_no_cycle(demo_findings):
    assert _s101(demo_findings, LIFECYCLE.format(first="lidar", more="")) == []
    # a lifecycle manager may drive it instead of the launch's own requests
    manager = ("\n        Node(package='nav2_lifecycle_manager', executable='lifecycle_manager', "
               "parameters=[{'node_names': ['lidar'], 'autostart': True}]),")
    assert _s101(demo_findings, LIFECYCLE.format(first="relay", more=manager)) == []


def test_an_autostarted_lifecycle_node_brings_itself_up(demo_findings):
    # LifecycleNode(autostart=True) (launch_ros since jazzy) configures and activates itself
    text = LIFECYCLE.format(first="relay", more="").replace("namespace='')", "namespace='', autostart=True)")
    assert "autostart=True" in text
    assert _s101(demo_findings, text) == []


def test_a_change_request_of_unknown_target_may_bring_any_node_up(demo_findings, tmp_path):
    # ChangeState(lifecycle_node_matcher=matches_node_name('/lidar')): no action is named, so the
    # request may configure the node; neither S101 nor the plan may say the relay never starts
    import json

    from physai_lint.api_plan import plan
    from physai_lint.engine import CheckOptions

    text = LIFECYCLE.format(first="relay", more="""
        EmitEvent(event=ChangeState(lifecycle_node_matcher=matches_node_name('/lidar'),
                                    transition_id=Transition.TRANSITION_CONFIGURE)),""").replace(
        "from launch_ros.events.lifecycle import ChangeState",
        "from launch_ros.events.lifecycle import ChangeState, matches_node_name")
    assert _s101(demo_findings, text) == []
    data = json.loads(plan(CheckOptions(paths=[], workspace=str(tmp_path)), "src/demo/launch/a.launch.py",
                           "json", cwd=str(tmp_path)))
    assert not any(v["never_starts"] for v in data["vertices"])
