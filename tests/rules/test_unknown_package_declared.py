"""U101 and a run dependency the package declares: rosdep installs it from sources the
workspace and the distro's package list cannot show (a vendor's apt repository), so it is no
mistake that it is missing here; an undeclared unknown package still is."""
from __future__ import annotations

from typing import Any

PACKAGE_XML = """<package format="3"><name>demo</name><version>0.0.0</version><description>d</description>
<maintainer email="m@example.com">a</maintainer><license>MIT</license>
<exec_depend>vendor_tensor_rt</exec_depend>
<export><build_type>ament_cmake</build_type></export></package>
"""
LAUNCH = """from launch import LaunchDescription
from launch_ros.actions import ComposableNodeContainer
from launch_ros.descriptions import ComposableNode


def generate_launch_description():
    return LaunchDescription([ComposableNodeContainer(
        name='container', namespace='', package='rclcpp_components', executable='component_container',
        composable_node_descriptions=[
            ComposableNode(package='vendor_tensor_rt', plugin='vendor::TensorRTNode', name='trt'),
            ComposableNode(package='vendor_tensor_rtt', plugin='vendor::Decoder', name='dec'),
        ])])
"""


def test_a_declared_dependency_outside_the_distro_is_not_reported(demo_findings: Any) -> None:
    found = demo_findings({"package.xml": PACKAGE_XML, "launch/a.launch.py": LAUNCH}, "launch/a.launch.py", "U101")
    assert [m.split(";")[0] for _, m in found] == [
        'package "vendor_tensor_rtt" is not in the workspace or the humble distro']


IGN = """<launch>
  <include file="$(find-pkg-share ros_ign_gazebo)/launch/ign_gazebo.launch.py"/>
</launch>
"""


def test_a_declared_package_of_another_distro_is_still_reported(
        tmp_path: Any, demo_package: Any) -> None:
    from physai_lint.engine import CheckOptions, run_check

    pkg = demo_package({"package.xml": PACKAGE_XML.replace("vendor_tensor_rt", "ros_ign_gazebo"),
                        "launch/sim.launch.xml": IGN})
    report = run_check(CheckOptions(paths=[str(pkg / "launch/sim.launch.xml")], workspace=str(tmp_path),
                                    cache=False, distro="jazzy"))
    (f,) = [f for f in report.findings if f.code == "U101"]
    assert f.message == ('package "ros_ign_gazebo" is not in the workspace or the jazzy distro; it is '
                         "released for humble, not for jazzy; its successor is ros_gz_sim")
    assert f.help == "use ros_gz_sim, or run with --distro humble"


EMPTY = """from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    urdf = PathJoinSubstitution([FindPackageShare(LaunchConfiguration("description_package")), "urdf"])
    return LaunchDescription([
        DeclareLaunchArgument("description_package", default_value=""),
        Node(package="robot_state_publisher", executable="robot_state_publisher", arguments=[urdf]),
    ])
"""


def test_an_empty_package_name_names_the_argument_it_comes_from(demo_findings: Any) -> None:
    (found,) = demo_findings({"launch/a.launch.py": EMPTY}, "launch/a.launch.py", "U101")
    assert found[1].startswith('the package name is empty: it comes from launch argument '
                               '"description_package", whose value is "" here; ')


def test_a_node_of_an_empty_package_says_the_name_is_empty(demo_findings: Any) -> None:
    text = EMPTY.replace('package="robot_state_publisher"', 'package=LaunchConfiguration("description_package")')
    found = demo_findings({"launch/a.launch.py": text}, "launch/a.launch.py", "U101")
    assert [m.split(";")[0] for _, m in found] == [
        'the package name is empty: it comes from launch argument "description_package", whose value is "" here',
        'the package name is empty (its value here is "")']
