"""S102 for an OnStateTransition that no TransitionEvent matches: it compares the event's state
labels with start_state/goal_state, and rcl_lifecycle publishes one event per step of its state
machine (a primary state to a transition state, then to the state the transition ends in)."""
import pytest

LAUNCH = """import launch
from launch import LaunchDescription
from launch.actions import LogInfo, RegisterEventHandler
from launch_ros.actions import LifecycleNode
from launch_ros.event_handlers import OnStateTransition


def generate_launch_description():
    talker = LifecycleNode(package='lifecycle', executable='lifecycle_talker', name='lc_talker',
                           namespace='')
    return LaunchDescription([
        RegisterEventHandler(OnStateTransition(target_lifecycle_node=talker, {states},
                                               entities=[LogInfo(msg='now')])),
        talker,
    ])
"""


def _s102(demo_findings, states: str) -> list[tuple[int, str]]:
    text = LAUNCH.format(states=states)
    return demo_findings({"launch/a.launch.py": text}, "launch/a.launch.py", "S102")


def test_a_primary_to_primary_pair_never_matches(demo_findings):
    assert _s102(demo_findings, "start_state='unconfigured', goal_state='inactive'") == [(12, (
        'this event handler never fires: no TransitionEvent goes from "unconfigured" to "inactive" '
        '(it passes through "configuring": "unconfigured" -> "configuring", then "configuring" -> '
        '"inactive"), so its actions never run'))]


def test_a_state_that_is_no_label_never_matches(demo_findings):
    ((_, message),) = _s102(demo_findings, "goal_state='configured'")
    assert message.startswith('this event handler never fires: its goal_state "configured" is no '
                              "lifecycle state label (they are activating, active, cleaningup,")


@pytest.mark.parametrize("states", [
    "goal_state='inactive'",
    "start_state='configuring', goal_state='inactive'",
    "start_state='inactive', goal_state='activating'",
    "start_state='errorprocessing', goal_state='unconfigured'",
    "start_state='unconfigured'",
    "start_state='unconfigured', goal_state='inactive', matcher=lambda e: True",
])
def test_steps_of_the_state_machine_match(demo_findings, states):
    assert _s102(demo_findings, states) == []
