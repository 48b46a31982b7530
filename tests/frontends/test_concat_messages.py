"""L004 substitution-concatenation says once what was done to which substitution."""
LAUNCH = """
import os
from pathlib import Path
from launch import LaunchDescription
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    dof = LaunchConfiguration("dof")
    a = "config/" + dof
    b = os.path.join(FindPackageShare("demo"), "x.yaml")
    c = f"{dof}.yaml"
    d = "-".join(["a", dof])
    e = str(dof)
    f = "{}.yaml".format(dof)
    g = Path("/opt/robot") / dof  # PurePath.__truediv__: TypeError
    return LaunchDescription([Node(package="demo_nodes_cpp", executable="talker", arguments=[a, b, c, d, e, f, g])])
"""


def test_each_message_names_the_substitution_and_what_was_done_once(demo_findings):
    findings = demo_findings({"launch/a.launch.py": LAUNCH}, "launch/a.launch.py", "L004")
    assert [message.split(":")[0] for _, message in findings] == [
        'substitution LaunchConfiguration("dof") is joined with + at description time',
        "substitution FindPackageShare is passed to os.path.join at description time",
        'substitution LaunchConfiguration("dof") is put into an f-string at description time',
        'substitution LaunchConfiguration("dof") is joined into a str with str.join at description time',
        'substitution LaunchConfiguration("dof") is converted with str() at description time',
        'substitution LaunchConfiguration("dof") is formatted with str.format at description time',
        'substitution LaunchConfiguration("dof") is joined to a pathlib.Path with / at description time',
    ]


PRINTED = """
import logging
from launch import LaunchDescription
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    dof = LaunchConfiguration("dof")
    print(str(dof))
    print(f"dof is {dof}")
    logging.getLogger(__name__).info("dof: " + str(dof))
    name = "arm_" + dof
    return LaunchDescription([Node(package="demo_nodes_cpp", executable="talker", name=name)])
"""


def test_text_only_printed_or_logged_is_not_reported(demo_findings):
    # a substitution's description on the terminal harms nothing; the same text in an action does
    findings = demo_findings({"launch/a.launch.py": PRINTED}, "launch/a.launch.py", "L004")
    assert [(line, message.split(":")[0]) for line, message in findings] == [
        (13, 'substitution LaunchConfiguration("dof") is joined with + at description time')]


PACKAGE_LOOKUP = """
import os
from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def load_yaml(package_name, file_path):
    return os.path.join(get_package_share_directory(package_name), file_path)


def generate_launch_description():
    pkg = LaunchConfiguration("moveit_config_package")
    kinematics = load_yaml(pkg, "config/kinematics.yaml")
    return LaunchDescription([
        DeclareLaunchArgument("moveit_config_package", default_value="demo_nodes_cpp"),
        Node(package="demo_nodes_cpp", executable="talker", arguments=[kinematics]),
    ])
"""


def test_a_substitution_given_to_a_package_lookup_raises_type_error(demo_findings):
    # ament_index_python: "TypeError: expected string or bytes-like object, got 'LaunchConfiguration'"
    # while generate_launch_description() runs, whatever is declared (the Kinova MoveIt launch idiom)
    entry = "launch/a.launch.py"
    (found,) = demo_findings({entry: PACKAGE_LOOKUP}, entry, "L004")
    assert found[0] == 11 and 'LaunchConfiguration("moveit_config_package") is passed to ' \
        "get_package_share_directory() at description time" in found[1], found
    assert demo_findings({entry: PACKAGE_LOOKUP}, entry, "L101") == []  # not "declared too late"
    assert demo_findings({entry: PACKAGE_LOOKUP}, entry, "L102") == []
