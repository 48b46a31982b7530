"""S204: a spawner (or ``ros2 control load_controller``) loads a controller whose ``<name>.type``
the controller manager's parameters do not give."""
from __future__ import annotations

from typing import Any

CONTROLLERS = """controller_manager:
  ros__parameters:
    update_rate: 100
    joint_state_broadcaster:
      type: joint_state_broadcaster/JointStateBroadcaster
    arm_controler:
      type: joint_trajectory_controller/JointTrajectoryController
"""

HEAD = """from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, ExecuteProcess, GroupAction
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution
from launch_ros.actions import Node, PushRosNamespace
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    controllers = PathJoinSubstitution([FindPackageShare('demo'), 'config', 'controllers.yaml'])
    manager = Node(package='controller_manager', executable='ros2_control_node', parameters=[controllers])
    return LaunchDescription([
        manager,
"""


def _check(demo_findings: Any, body: str, head: str = HEAD, controllers: str = CONTROLLERS
           ) -> list[tuple[int, str]]:
    files = {"launch/a.launch.py": head + body + "    ])\n", "config/controllers.yaml": controllers}
    return demo_findings(files, "launch/a.launch.py", "S204")


def test_a_controller_the_manager_has_no_type_for_is_reported_with_the_configured_ones(demo_findings: Any):
    found = _check(demo_findings, """        Node(package='controller_manager', executable='spawner',
             arguments=['joint_state_broadcaster', 'arm_controller', '--controller-manager', '/controller_manager']),
""")
    assert found == [(14, 'spawner loads controller "arm_controller" but controller manager /controller_manager '
                          'has no parameter "arm_controller.type", so loading fails ("The \'type\' param was '
                          'not defined for \'arm_controller\'"); it configures arm_controler, '
                          'joint_state_broadcaster: did you mean "arm_controler"?')]


def test_load_controller_commands_are_checked_against_the_root_manager(demo_findings: Any):
    found = _check(demo_findings, """        ExecuteProcess(cmd=['ros2', 'control', 'load_controller', '--set-state', 'active', 'gripper']),
        ExecuteProcess(cmd=['ros2', 'control', 'load_controller', 'joint_state_broadcaster']),
""")
    assert [m.split(" but")[0] for _, m in found] == ['ros2 control load_controller loads controller "gripper"']


def test_a_type_given_another_way_silences_it(demo_findings: Any):
    assert _check(demo_findings, """        Node(package='controller_manager', executable='spawner',
             arguments=['gripper', '--controller-type', 'position_controllers/GripperActionController']),
        Node(package='controller_manager', executable='spawner',
             arguments=['gripper2', '-p', PathJoinSubstitution([FindPackageShare('demo'), 'config', 'g.yaml'])]),
        Node(package='controller_manager', executable='spawner', arguments=['gripper3'],
             parameters=[controllers]),
        Node(package='controller_manager', executable='spawner', arguments=['gripper4'],
             parameters=[{'type': 'position_controllers/GripperActionController'}]),
        Node(package='controller_manager', executable='spawner',
             arguments=['gripper5', '--ros-args', '--params-file', '/tmp/g.yaml']),
""") == []


def test_spawner_parameters_without_a_type_do_not_give_one(demo_findings: Any):
    found = _check(demo_findings, """        Node(package='controller_manager', executable='spawner', arguments=['gripper'],
             parameters=[{'use_sim_time': True}]),
""")
    assert [m.split(" but")[0] for _, m in found] == ['spawner loads controller "gripper"']


def test_a_relative_manager_name_is_the_spawners_namespace(demo_findings: Any):
    body = """        Node(package='controller_manager', executable='spawner', arguments=['arm_controler']),
        GroupAction([PushRosNamespace('robot1'),
                     Node(package='controller_manager', executable='ros2_control_node',
                          parameters=[{'joint_state_broadcaster.type': 'joint_state_broadcaster/JointStateBroadcaster'}]),
                     Node(package='controller_manager', executable='spawner',
                          arguments=['joint_state_broadcaster', 'arm_controler'])]),
"""
    found = _check(demo_findings, body)
    assert [m.split(" has no")[0] for _, m in found] == [
        'spawner loads controller "arm_controler" but controller manager /robot1/controller_manager']


def test_unknown_manager_parameters_or_managers_elsewhere_say_nothing(demo_findings: Any):
    spawn = """        Node(package='controller_manager', executable='spawner', arguments=['gripper']),
"""
    from_arg = HEAD.replace("parameters=[controllers]", "parameters=[LaunchConfiguration('controllers')]")
    assert _check(demo_findings, "        DeclareLaunchArgument('controllers'),\n" + spawn, head=from_arg) == []
    missing = HEAD.replace("'controllers.yaml'", "'nothing.yaml'")
    assert _check(demo_findings, spawn, head=missing) == []  # P101's
    elsewhere = HEAD.replace("        manager,\n", "")  # a simulator plugin hosts it
    assert _check(demo_findings, spawn, head=elsewhere) == []
    other = """        Node(package='controller_manager', executable='spawner', arguments=['gripper', '-c', '/sim/cm']),
"""
    assert _check(demo_findings, other) == []


def test_only_a_ros2_command_loads_controllers(demo_findings: Any):
    # "control load_controller x ros2": not the ros2 CLI (the word before "control" is not ros2)
    assert _check(demo_findings, """        ExecuteProcess(cmd=['control', 'load_controller', 'gripper', 'ros2']),
""") == []


def test_a_robot_description_of_unknown_value_still_names_only_itself(demo_findings: Any):
    # the ros2_control idiom: the URDF from xacro is known only at launch time, but the dict
    # sets robot_description alone, never a controller's type
    head = HEAD.replace(
        "parameters=[controllers])",
        "parameters=[{'robot_description': ParameterValue(Command(['xacro ', 'robot.urdf.xacro']), "
        "value_type=str)}, controllers])").replace(
        "from launch_ros.substitutions import FindPackageShare",
        "from launch_ros.substitutions import FindPackageShare\nfrom launch.substitutions import Command\n"
        "from launch_ros.parameter_descriptions import ParameterValue")
    found = _check(demo_findings, """        Node(package='controller_manager', executable='spawner', arguments=['arm_controller']),
""", head=head)
    assert [message.split(" but")[0] for _, message in found] == ['spawner loads controller "arm_controller"']
