"""U103 (missing-exec-depend) is about packages a launch file names. A package name built from a
launch argument (``$(var vehicle_model)_description``) is picked by whoever starts the launch; its
default is one choice among many, so the package.xml cannot declare it and U103 stays silent."""
from __future__ import annotations

from pathlib import Path
from typing import Callable

from physai_lint.engine import CheckOptions, run_check

XML = """<launch>
  <arg name="vehicle_model" default="acme_car"/>
  <arg name="container_package" default="rclcpp_components"/>
  <node pkg="rviz2" exec="rviz2" args="-d $(find-pkg-share $(var vehicle_model)_description)/a.rviz"/>
  <node pkg="$(var container_package)" exec="component_container" name="container"/>
  <node pkg="rviz2" exec="rviz2" name="tools" args="-d $(find-pkg-share acme_tools)/a.rviz"/>
</launch>
"""
PY = """
from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, OpaqueFunction
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare


def setup(context):
    share = FindPackageShare([LaunchConfiguration("vehicle_model"), "_description"]).perform(context)
    model = LaunchConfiguration("vehicle_model").perform(context)
    other = get_package_share_directory(model + "_description")
    tools = get_package_share_directory("acme_tools")
    return [Node(package="rviz2", executable="rviz2", arguments=["-d", share, other, tools])]


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument("vehicle_model", default_value="acme_car"),
        OpaqueFunction(function=setup),
    ])
"""
PACKAGE_XML = """<package format="3"><name>{name}</name><version>0.0.0</version><description>d</description>
<maintainer email="m@example.com">a</maintainer><license>MIT</license>{depends}
<export><build_type>ament_cmake</build_type></export></package>
"""


def _u103(tmp_path: Path, demo_package: Callable[[dict[str, str]], Path], entry: str, text: str) -> list[str]:
    for name in ("acme_car_description", "acme_tools"):
        (tmp_path / "src" / name).mkdir(parents=True)
        (tmp_path / "src" / name / "package.xml").write_text(PACKAGE_XML.format(name=name, depends=""))
    depends = "<exec_depend>rviz2</exec_depend>"
    pkg = demo_package({"package.xml": PACKAGE_XML.format(name="demo", depends=depends), entry: text})
    opts = CheckOptions(paths=[str(pkg / entry)], workspace=str(tmp_path), cache=False)
    return [f.message for f in run_check(opts).findings if f.code == "U103"]


def test_xml_package_names_from_launch_arguments_are_silent(tmp_path, demo_package):
    messages = _u103(tmp_path, demo_package, "launch/a.launch.xml", XML)
    assert len(messages) == 1 and '"acme_tools"' in messages[0]


def test_python_package_names_from_launch_arguments_are_silent(tmp_path, demo_package):
    messages = _u103(tmp_path, demo_package, "launch/a.launch.py", PY)
    assert len(messages) == 1 and '"acme_tools"' in messages[0]
