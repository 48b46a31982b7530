"""U103 (missing-exec-depend): a dependency declared under a condition false for the distro is
named as such (not "no <exec_depend>"), and the help does not ask for a dependency that would
close a cycle of packages without saying so."""
from __future__ import annotations

from pathlib import Path
from typing import Callable

from physai_lint.engine import CheckOptions, run_check

XML = """<launch>
  <node pkg="acme_tools" exec="tool" name="tool"/>
</launch>
"""
PACKAGE_XML = """<package format="3"><name>{name}</name><version>0.0.0</version><description>d</description>
<maintainer email="m@example.com">a</maintainer><license>MIT</license>{depends}
<export><build_type>ament_cmake</build_type></export></package>
"""


def _u103(tmp_path: Path, demo_package: Callable[[dict[str, str]], Path], demo_depends: str,
          tools_depends: str = "", distro: str = "humble") -> list[tuple[str, str]]:
    (tmp_path / "src" / "acme_tools").mkdir(parents=True)
    (tmp_path / "src" / "acme_tools" / "package.xml").write_text(
        PACKAGE_XML.format(name="acme_tools", depends=tools_depends))
    pkg = demo_package({"package.xml": PACKAGE_XML.format(name="demo", depends=demo_depends),
                        "launch/a.launch.xml": XML})
    opts = CheckOptions(paths=[str(pkg / "launch/a.launch.xml")], workspace=str(tmp_path), cache=False,
                        distro=distro)
    return [(f.message, f.help) for f in run_check(opts).findings if f.code == "U103"]


def test_a_dependency_conditioned_away_on_this_distro_is_named_with_its_condition(tmp_path, demo_package):
    depends = "<exec_depend condition=\"$ROS_DISTRO != 'humble'\">acme_tools</exec_depend>"
    [(message, help_)] = _u103(tmp_path, demo_package, depends)
    assert message.endswith("declares it only under the condition \"$ROS_DISTRO != 'humble'\", "
                            "which is false for humble")
    assert help_.startswith('make the condition of the dependency on "acme_tools" hold for humble')


def test_the_same_dependency_holds_on_another_distro(tmp_path, demo_package):
    depends = "<exec_depend condition=\"$ROS_DISTRO != 'humble'\">acme_tools</exec_depend>"
    assert _u103(tmp_path, demo_package, depends, distro="jazzy") == []


def test_the_help_warns_when_the_dependency_would_close_a_cycle(tmp_path, demo_package):
    [(message, help_)] = _u103(tmp_path, demo_package, "", "<exec_depend>demo</exec_depend>")
    assert message.endswith("does not declare it (no <exec_depend> or <depend>)")
    assert help_ == ('add <exec_depend>acme_tools</exec_depend> to the package.xml of "demo"; but '
                     '"acme_tools" already depends on "demo" (acme_tools -> demo), and colcon cannot '
                     'order packages that depend on each other: move this launch file into '
                     '"acme_tools" or a package depending on both')


def _u103_messages(tmp_path: Path, demo_package: Callable, depends: str, xml: str) -> list[str]:
    """The U103 messages of checking the demo package's launch/a.launch.xml (``xml``) when its
    package.xml declares ``depends``."""
    pkg = demo_package({"package.xml": PACKAGE_XML.format(name="demo", depends=depends),
                        "launch/a.launch.xml": xml})
    opts = CheckOptions(paths=[str(pkg / "launch/a.launch.xml")], workspace=str(tmp_path), cache=False)
    return [f.message for f in run_check(opts).findings if f.code == "U103"]


def test_a_dependency_brought_by_a_declared_metapackage_or_workspace_package_is_declared(
        tmp_path, demo_package):
    # <depend>ros2_control</depend> installs controller_manager; a workspace package declared
    # as a dependency brings its own run dependencies along
    xml = """<launch>
  <node pkg="controller_manager" exec="spawner" args="arm_controller"/>
  <node pkg="acme_tools" exec="tool" name="tool"/>
</launch>
"""
    (tmp_path / "src" / "acme_bringup").mkdir(parents=True)
    (tmp_path / "src" / "acme_bringup" / "package.xml").write_text(
        PACKAGE_XML.format(name="acme_bringup", depends="<exec_depend>acme_tools</exec_depend>"))
    (tmp_path / "src" / "acme_tools").mkdir(parents=True)
    (tmp_path / "src" / "acme_tools" / "package.xml").write_text(PACKAGE_XML.format(name="acme_tools", depends=""))
    depends = "<depend>ros2_control</depend><exec_depend>acme_bringup</exec_depend>"
    assert _u103_messages(tmp_path, demo_package, depends, xml) == []


def test_members_of_nested_metapackages_are_declared(tmp_path, demo_package):
    # ros_gz brings ros_gz_sim; navigation2 brings nav2_map_server, and nav2_dwb_controller,
    # itself a metapackage, brings dwb_core; ros_ign (humble) brings ros_gz and so ros_gz_bridge
    xml = """<launch>
  <node pkg="ros_gz_sim" exec="create" args="-topic robot_description"/>
  <node pkg="nav2_map_server" exec="map_server" name="map_server"/>
  <node pkg="dwb_core" exec="tool" name="dwb"/>
  <node pkg="ros_gz_bridge" exec="parameter_bridge" name="bridge"/>
</launch>
"""
    depends = "<depend>ros_gz</depend><exec_depend>navigation2</exec_depend><exec_depend>ros_ign</exec_depend>"
    assert _u103_messages(tmp_path, demo_package, depends, xml) == []


def test_moveit_and_ros2_controllers_metapackages_bring_their_members(tmp_path, demo_package):
    # crane_x7_moveit_config: <depend>moveit</depend> brings moveit_ros, which brings move_group
    xml = """<launch>
  <node pkg="moveit_ros_move_group" exec="move_group" name="move_group"/>
  <node pkg="moveit_simple_controller_manager" exec="x" name="x"/>
  <node pkg="joint_trajectory_controller" exec="y" name="y"/>
</launch>
"""
    depends = "<depend>moveit</depend><exec_depend>ros2_controllers</exec_depend>"
    assert _u103_messages(tmp_path, demo_package, depends, xml) == []
