"""ros2_control_node's bundled declaration: the name its code gives the controller manager, the one
parameter whose type every distro enforces, and the controllers' endpoints known only at run time."""
from __future__ import annotations

LAUNCH = """from launch import LaunchDescription
from launch.substitutions import PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    ctrl = PathJoinSubstitution([FindPackageShare("demo"), "config", "controllers.yaml"])
    return LaunchDescription([
        Node(package="robot_state_publisher", executable="robot_state_publisher",
             parameters=[{"robot_description": "<robot name='r'/>"}]),
        Node(package="tf2_ros", executable="static_transform_publisher",
             arguments=["0", "0", "0", "0", "0", "0", "map", "odom"]),
        Node(package="controller_manager", executable="ros2_control_node", parameters=[ctrl]),
    ])
"""
CONTROLLERS = """controller_manager:
  ros__parameters:
    update_rate: 100.0
    arm_controller:
      type: joint_trajectory_controller/JointTrajectoryController
arm_controller:
  ros__parameters:
    joints: [j1]
"""


def _files(controllers: str = CONTROLLERS) -> dict[str, str]:
    return {"launch/bot.launch.py": LAUNCH, "config/controllers.yaml": controllers}


def test_an_unnamed_ros2_control_node_is_the_controller_manager(demo_graph):
    nodes = demo_graph(_files(), "launch/bot.launch.py")
    cm = nodes["controller_manager"]
    assert cm["fqn"] == "/controller_manager"
    assert cm["executable"] == "ros2_control_node"
    assert cm["parameters"]["update_rate"] == 100.0


def test_a_double_update_rate_is_a_type_mismatch(demo_findings):
    (finding,) = demo_findings(_files(), "launch/bot.launch.py", "P105")
    assert finding[0] == 3
    assert finding[1].startswith('parameter "update_rate" of /controller_manager is declared integer')


def test_an_integer_update_rate_and_the_controllers_keys_are_fine(demo_findings):
    text = CONTROLLERS.replace("100.0", "100")
    for code in ("P105", "P103", "P109"):
        assert demo_findings(_files(text), "launch/bot.launch.py", code) == []


def test_controllers_may_publish_what_the_other_nodes_need(demo_findings):
    # robot_state_publisher reads joint_states, which a joint_state_broadcaster loaded into the
    # controller manager publishes: the controller manager is no longer of unknown interface, and
    # still no topic rule may call that subscription dangling
    assert demo_findings(_files(), "launch/bot.launch.py", "T201") == []


def test_the_bundled_declaration_keeps_its_run_time_endpoints():
    from physai_lint.interfaces.store import load_bundled, merge

    iface = merge([load_bundled("humble")[("controller_manager", "ros2_control_node")]])
    assert iface is not None and iface.node_name == "controller_manager"
    assert {kind for kind, _ in iface.unnamed} == {
        "publishers", "subscribers", "services", "clients", "action_servers", "action_clients"}
