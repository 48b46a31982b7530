"""P111 leaves the /clock source alone; T201's near misses carry the same messages; a
robot_localization set_pose input is expected from outside the launch."""
from __future__ import annotations

from typing import Any

CMAKE = """project(demo)
add_executable(sim src/sim.cpp)
add_executable(mover src/mover.cpp)
install(TARGETS sim mover DESTINATION lib/${PROJECT_NAME})
install(DIRECTORY launch DESTINATION share/${PROJECT_NAME})
"""
SIM = """
Sim::Sim() : Node("sim") {
  clock_ = create_publisher<rosgraph_msgs::msg::Clock>("/clock", 10);
  pose_ = create_publisher<geometry_msgs::msg::PoseStamped>("robot_pose", 10);
}
"""
MOVER = """
Mover::Mover() : Node("mover") {
  sub_ = create_subscription<sensor_msgs::msg::JointState>("robot_poses", 10, [this](auto m) { on(m); });
  pose_ = create_subscription<geometry_msgs::msg::PoseStamped>("robot_pose", 10, [this](auto m) { on(m); });
}
"""
LAUNCH = """from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='demo', executable='sim', name='sim'),
        Node(package='demo', executable='mover', name='mover', parameters=[{'use_sim_time': True}]),
        Node(package='robot_localization', executable='ekf_node', name='ekf',
             parameters=[{'use_sim_time': True}], remappings=[('odometry/filtered', '/odom')]),
    ])
"""
FILES = {"CMakeLists.txt": CMAKE, "src/sim.cpp": SIM, "src/mover.cpp": MOVER, "launch/sim.launch.py": LAUNCH}


def test_the_clock_source_runs_on_wall_time(demo_findings: Any) -> None:
    assert demo_findings(FILES, "launch/sim.launch.py", "P111") == []


def test_a_near_miss_of_another_message_type_is_no_suggestion(demo_findings: Any) -> None:
    found = [m for _, m in demo_findings(FILES, "launch/sim.launch.py", "T201")]
    # /robot_poses (JointState) is not a misspelt /robot_pose (PoseStamped); /set_pose is an
    # operator's reset of the EKF, expected from outside the launch
    assert any('"/robot_poses" but nothing publishes it' in m and "did you mean" not in m for m in found)
    assert not any("set_pose" in m for m in found)


TF_BESIDE = """from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='demo', executable='mover', name='mover'),
        Node(package='tf2_ros', executable='static_transform_publisher',
             arguments=['0', '0', '0', '0', '0', '0', 'base_link', 'lidar']),
    ])
"""


def test_a_static_transform_beside_one_node_keeps_it_a_one_node_launch(demo_findings: Any) -> None:
    # the mover's inputs come from a driver or a bag: a node that only publishes /tf_static (an
    # ignored topic) does not make the launch a system whose topics must all connect
    files = {**FILES, "launch/tf.launch.py": TF_BESIDE}
    assert demo_findings(files, "launch/tf.launch.py", "T201") == []
    sim = {**files, "launch/tf.launch.py": TF_BESIDE.replace(
        "        Node(package='tf2_ros'", "        Node(package='demo', executable='sim', name='sim'),\n"
        "        Node(package='tf2_ros'")}
    assert any('"/robot_poses" but nothing publishes it' in m
               for _, m in demo_findings(sim, "launch/tf.launch.py", "T201"))
