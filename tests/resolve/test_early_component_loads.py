"""S203 for LoadComposableNodes(target_container=<container action>) run before that action has
executed: LoadComposableNodes.execute reads the container's node_name, which raises
RuntimeError("cannot access 'node_name' before executing action") until the container action
has run; the launch ends. In the synchronous first pass only an action visited before it has."""
LAUNCH = """from launch import LaunchDescription
from launch.actions import RegisterEventHandler, TimerAction
from launch.conditions import IfCondition
from launch.event_handlers import OnProcessStart
from launch_ros.actions import ComposableNodeContainer, LoadComposableNodes, Node
from launch_ros.descriptions import ComposableNode


def generate_launch_description():
    camera = Node(package='demo', executable='camera')
    container = ComposableNodeContainer(name='box', namespace='', package='rclcpp_components',
                                        executable='component_container'{cond})
    load = LoadComposableNodes(target_container=container, composable_node_descriptions=[
        ComposableNode(package='demo', plugin='demo::Cloud', name='cloud')])
    return LaunchDescription([{order}])
"""


def _s203(demo_findings, order: str, cond: str = "") -> list[tuple[int, str]]:
    text = LAUNCH.format(order=order, cond=cond)
    return demo_findings({"launch/a.launch.py": text}, "launch/a.launch.py", "S203")


def test_a_container_started_from_a_handler_runs_after_the_load(demo_findings):
    order = "camera, RegisterEventHandler(OnProcessStart(target_action=camera, on_start=[container])), load"
    assert _s203(demo_findings, order) == [(13, (
        "LoadComposableNodes targets the ComposableNodeContainer action at line 11, which only runs "
        "later (from an event handler or a timer): LoadComposableNodes.execute reads the container's "
        "node_name before it has executed and raises RuntimeError(\"cannot access 'node_name' before "
        "executing action\"), which ends the launch"))]


def test_a_container_in_a_timer_runs_after_the_load(demo_findings):
    assert [line for line, _ in _s203(demo_findings, "TimerAction(period=1.0, actions=[container]), load")] == [13]


def test_a_container_after_the_load_in_the_description(demo_findings):
    ((line, message),) = _s203(demo_findings, "load, container")
    assert line == 13 and message.startswith(
        "LoadComposableNodes targets the ComposableNodeContainer action at line 11, which comes after "
        "it in the launch description:")


def test_a_container_never_added(demo_findings):
    ((line, message),) = _s203(demo_findings, "load")
    assert line == 13 and message.startswith(
        "LoadComposableNodes targets a ComposableNodeContainer action that is never added to the launch "
        "description:")


def test_a_disabled_container(demo_findings):
    ((_, message),) = _s203(demo_findings, "container, load", cond=", condition=IfCondition('false')")
    assert "which is disabled by its condition:" in message


def test_a_container_before_the_load_is_fine(demo_findings):
    assert _s203(demo_findings, "container, load") == []
    # both from the same handler, the container first
    order = "camera, RegisterEventHandler(OnProcessStart(target_action=camera, on_start=[container, load]))"
    assert _s203(demo_findings, order) == []
