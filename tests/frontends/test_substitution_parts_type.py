"""L008 for a substitution whose list argument holds something that is neither a string nor a
substitution: its constructor runs normalize_to_list_of_substitutions over the list, which raises
TypeError while the description is built. PathJoinSubstitution takes a list per path component
since ros2/launch#838 (backported), so its nested lists are left alone."""
from __future__ import annotations

LAUNCH = """from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.conditions import IfCondition
from launch.substitutions import Command, LaunchConfiguration, PathJoinSubstitution, PythonExpression
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    urdf = PathJoinSubstitution([FindPackageShare('demo'), 'urdf', [LaunchConfiguration('robot'), '.urdf']])
    description = Command(['xacro ', [urdf, ' use_sim:=true']])
    return LaunchDescription([
        DeclareLaunchArgument('robot', default_value='arm'),
        Node(package='robot_state_publisher', executable='robot_state_publisher',
             parameters=[{'robot_description': description}],
             condition=IfCondition(PythonExpression([LaunchConfiguration('robot'), ' != ', 0]))),
    ])
"""


def test_parts_that_are_no_substitution(demo_findings):
    found = demo_findings({"launch/a.launch.py": LAUNCH}, "launch/a.launch.py", "L008")
    assert [(line, msg.split(" is given")[0], msg.split(" as one")[0].rsplit(" ", 1)[-1].rstrip(",")) for line, msg in found] == [
        (11, "Command(command=[...])", "list"),
        (16, "PythonExpression(expression=[...])", "int"),
    ]
    assert found[0][1].startswith("Command(command=[...]) is given [PathJoinSubstitution(")
    assert found[0][1].endswith("raises \"TypeError: Failed to normalize given item of type '<class 'list'>'\" "
                                "when the description is built")


def test_a_path_join_given_one_string_joins_its_characters(demo_findings):
    text = LAUNCH.replace("[FindPackageShare('demo'), 'urdf', [LaunchConfiguration('robot'), '.urdf']]",
                          "'urdf/arm.urdf'")
    found = [(line, msg) for line, msg in demo_findings({"launch/a.launch.py": text}, "launch/a.launch.py", "L008")
             if msg.startswith("PathJoinSubstitution")]
    assert [(line, msg.split(", so it yields ")[1].split(" ")[0]) for line, msg in found] == [(10, "'/a/r/m/./u/r/d/f'")]
