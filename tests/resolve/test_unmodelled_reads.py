"""Launch configurations read where no rule looks: a process's output/respawn/prefix/cwd/env, a
component's extra_arguments, and ``lc.perform(context)`` in an OpaqueFunction. Launch substitutes
them when the action runs, so they are read (no unused-argument, L102) and must exist
(undefined-launch-configuration, L101)."""
from __future__ import annotations

PY = """
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, ExecuteProcess, OpaqueFunction
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import ComposableNodeContainer, Node
from launch_ros.descriptions import ComposableNode


def setup(context):
    path = LaunchConfiguration("calibration").perform(context)
    missing = LaunchConfiguration("never_declared").perform(context)
    return [Node(package="demo", executable="calibrate", name="calibrate")]


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument("output", default_value="screen"),
        DeclareLaunchArgument("respawn", default_value="true"),
        DeclareLaunchArgument("prefix", default_value=""),
        DeclareLaunchArgument("log_dir", default_value="/tmp"),
        DeclareLaunchArgument("cwd", default_value="/tmp"),
        DeclareLaunchArgument("intra", default_value="false"),
        DeclareLaunchArgument("calibration", default_value="/tmp/c.yaml"),
        DeclareLaunchArgument("unused", default_value="x"),
        Node(package="demo", executable="driver", name="driver",
             output=LaunchConfiguration("output"), respawn=LaunchConfiguration("respawn"),
             prefix=LaunchConfiguration("prefix"),
             additional_env={"ROS_LOG_DIR": LaunchConfiguration("log_dir")}),
        ExecuteProcess(cmd=["ls"], cwd=LaunchConfiguration("cwd"),
                       output=LaunchConfiguration("undeclared_output")),
        ComposableNodeContainer(
            package="rclcpp_components", executable="component_container", name="box",
            namespace="",
            composable_node_descriptions=[ComposableNode(
                package="demo", plugin="demo::Filter", name="filter",
                extra_arguments=[{"use_intra_process_comms": LaunchConfiguration("intra")}])]),
        OpaqueFunction(function=setup),
    ])
"""

XML = """<launch>
  <arg name="output" default="screen"/>
  <arg name="respawn" default="true"/>
  <arg name="log_dir" default="/tmp"/>
  <arg name="intra" default="false"/>
  <arg name="unused" default="x"/>
  <node pkg="demo" exec="driver" name="driver" output="$(var output)" respawn="$(var respawn)"
        launch-prefix="$(var missing_prefix)">
    <env name="ROS_LOG_DIR" value="$(var log_dir)"/>
  </node>
  <node_container pkg="rclcpp_components" exec="component_container" name="box" namespace="">
    <composable_node pkg="demo" plugin="demo::Filter" name="filter">
      <extra_arg name="use_intra_process_comms" value="$(var intra)"/>
    </composable_node>
  </node_container>
</launch>
"""


def _findings(tmp_path, demo_package, name, text):
    from physai_lint.engine import CheckOptions, run_check

    path = str(demo_package({f"launch/{name}": text}) / "launch" / name)
    report = run_check(CheckOptions(paths=[path], workspace=str(tmp_path), cache=False))
    return sorted((f.code, f.key) for f in report.findings if f.code in ("L101", "L102"))


def test_python_reads(tmp_path, demo_package):
    assert _findings(tmp_path, demo_package, "a.launch.py", PY) == [
        ("L101", "never_declared"), ("L101", "undeclared_output"), ("L102", "unused")]


def test_xml_reads(tmp_path, demo_package):
    assert _findings(tmp_path, demo_package, "a.launch.xml", XML) == [
        ("L101", "missing_prefix"), ("L102", "unused")]


BUILDER = """
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution
from launch_ros.actions import Node
from moveit_configs_utils import MoveItConfigsBuilder


def generate_launch_description():
    config = (
        MoveItConfigsBuilder("panda")
        .robot_description(file_path="config/panda.urdf.xacro",
                           mappings={"hardware": LaunchConfiguration("hardware")})
        .robot_description_semantic(file_path=PathJoinSubstitution(["srdf", LaunchConfiguration("srdf")]))
        .to_moveit_configs()
    )
    return LaunchDescription([
        DeclareLaunchArgument("hardware", default_value="mock"),
        DeclareLaunchArgument("srdf", default_value="panda.srdf"),
        DeclareLaunchArgument("unused", default_value="x"),
        Node(package="demo", executable="move_group", parameters=[config.to_dict()]),
    ])
"""


def test_configurations_handed_to_a_library_may_be_read(tmp_path, demo_package):
    # moveit_configs_utils turns the mappings into a xacro Command: launch reads them
    assert _findings(tmp_path, demo_package, "a.launch.py", BUILDER) == [("L102", "unused")]


STORED = """
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, OpaqueFunction
from launch.conditions import IfCondition
from launch.substitutions import LaunchConfiguration, PythonExpression
from launch_ros.actions import Node
from demo_description.robot_description_loader import RobotDescriptionLoader


def setup(context):
    nodes = []
    if IfCondition(PythonExpression([LaunchConfiguration("localization"), " == 'true'"])).evaluate(context):
        nodes.append(Node(package="demo", executable="localizer"))
    return nodes


def generate_launch_description():
    loader = RobotDescriptionLoader()
    loader.use_camera = LaunchConfiguration("use_camera")
    settings = loader.settings()
    settings["port"] = LaunchConfiguration("port_name")
    return LaunchDescription([
        DeclareLaunchArgument("use_camera", default_value="false"),
        DeclareLaunchArgument("port_name", default_value="/dev/ttyUSB0"),
        DeclareLaunchArgument("localization", default_value="false"),
        DeclareLaunchArgument("unused", default_value="x"),
        Node(package="demo", executable="rsp", parameters=[{"robot_description": loader.load()}]),
        OpaqueFunction(function=setup),
    ])
"""


def test_configurations_stored_in_objects_not_followed_may_be_read(tmp_path, demo_package):
    # an attribute or item set on an object the evaluator cannot follow (crane_plus's description
    # loader), and a condition evaluated by hand (rtabmap's IfCondition(...).evaluate(context)):
    # the object may read what it holds
    assert _findings(tmp_path, demo_package, "a.launch.py", STORED) == [("L102", "unused")]


MISSING_INCLUDE = """<launch>
  <arg name="start_rviz" default="false"/>
  <arg name="unused" default="x"/>
  <include file="$(find-pkg-share demo)/launch/INCLUDED"/>
</launch>
"""


def test_an_include_that_cannot_be_read_may_read_the_arguments(tmp_path, demo_package):
    # turtlebot3_manipulation: the argument is declared for a file that does not exist (L105);
    # that file is the likely reader, so "remove the declaration" would be the wrong advice
    demo_package({"launch/b.launch.xml": "<launch/>\n"})
    present = _findings(tmp_path, demo_package, "a.launch.xml", MISSING_INCLUDE.replace("INCLUDED", "b.launch.xml"))
    assert present == [("L102", "start_rviz"), ("L102", "unused")]  # the included file reads neither
    missing = _findings(tmp_path, demo_package, "a.launch.xml", MISSING_INCLUDE.replace("INCLUDED", "gone.launch.xml"))
    assert missing == []
