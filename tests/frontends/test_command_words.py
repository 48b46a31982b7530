"""L004 for a Command whose parts run two words together: launch's ``Command.perform`` joins the
parts' values with nothing between them and splits the line with shlex."""
PY = """
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import Command, FindExecutable, LaunchConfiguration, PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.parameter_descriptions import ParameterValue
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    ns = LaunchConfiguration('ns')
    extra = LaunchConfiguration('extra')
    urdf = PathJoinSubstitution([FindPackageShare('demo'), 'urdf', 'bot.urdf.xacro'])
    stem = PathJoinSubstitution([FindPackageShare('demo'), 'urdf', 'bot'])
    descriptions = [
@COMMANDS@
    ]
    return LaunchDescription([
        DeclareLaunchArgument('ns', default_value='robot1'),
        DeclareLaunchArgument('extra', default_value=''),
    ] + [Node(package='robot_state_publisher', executable='robot_state_publisher', name=f'rsp{i}',
              parameters=[{'robot_description': ParameterValue(d, value_type=str)}])
         for i, d in enumerate(descriptions)])
"""


def _found(demo_findings, *commands: str) -> list[tuple[int, str]]:
    text = PY.replace("@COMMANDS@", "\n".join(f"        {c}," for c in commands))
    return demo_findings({"launch/a.launch.py": text}, "launch/a.launch.py", "L004")


def test_a_file_followed_by_a_mapping_without_a_space(demo_findings):
    ((line, message),) = _found(demo_findings, "Command(['xacro ', urdf, 'namespace:=', ns])")
    assert line == 16
    assert '"namespace:=robot1"' in message and "bot.urdf.xacronamespace:=robot1" in message
    assert "xacro reads it as a mapping and finds no input file" in message
    assert "the command line is 'xacro .../" in message


def test_a_value_followed_by_the_next_mapping(demo_findings):
    ((_, message),) = _found(demo_findings, "Command(['xacro ', urdf, ' namespace:=', ns, 'prefix:=a_'])")
    assert '"namespace:=robot1" and "prefix:=a_" are the one argument "namespace:=robot1prefix:=a_"' in message
    assert "where two were meant" in message


def test_a_program_followed_by_a_path(demo_findings):
    # at the program's literal, inside each Command (not where the path was built)
    found = _found(demo_findings, "Command(['xacro', urdf])", "Command(['xacro', urdf])")
    assert [line for line, _ in found] == [16, 17]
    message = found[0][1]
    assert '"xacro" and ".../' in message and 'are the one word "xacro/.../' in message
    assert "/urdf/bot.urdf.xacro" in message
    assert "a program that does not exist" in message


def test_a_found_program_followed_by_a_path(demo_findings):
    ((_, message),) = _found(demo_findings, "Command([FindExecutable(name='xacro'), urdf])")
    assert '"xacro" and ".../' in message


def test_an_empty_part_between_leaves_the_word_before_it(demo_findings):
    ((_, message),) = _found(demo_findings, "Command(['xacro ', urdf, extra, 'namespace:=', ns])")
    assert "bot.urdf.xacronamespace:=robot1" in message


def test_each_place_is_reported_once_whatever_the_values(demo_findings):
    # one file included twice with two namespaces glues two different words at one place
    robot = PY.replace("@COMMANDS@", "        Command(['xacro ', urdf, 'namespace:=', ns]),")
    fleet = """
from launch import LaunchDescription
from launch.actions import GroupAction, IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import PathJoinSubstitution
from launch_ros.actions import PushRosNamespace
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    robot = PathJoinSubstitution([FindPackageShare('demo'), 'launch', 'robot.launch.py'])
    return LaunchDescription([
        GroupAction([PushRosNamespace(ns), IncludeLaunchDescription(
            PythonLaunchDescriptionSource(robot), launch_arguments={'ns': ns}.items())])
        for ns in ('robot1', 'robot2')])
"""
    found = demo_findings({"launch/robot.launch.py": robot, "launch/fleet.launch.py": fleet},
                          "launch/fleet.launch.py", "L004")
    assert [line for line, _ in found] == [16]


def test_words_written_apart_or_meant_together_are_not_reported(demo_findings):
    assert _found(
        demo_findings,
        "Command(['xacro ', urdf, ' namespace:=', ns])",
        "Command([FindExecutable(name='xacro'), ' ', urdf, ' namespace:=', ns])",
        "Command(['xacro ', stem, '.urdf.xacro', ' namespace:=', ns])",  # a suffix belongs to the word
        "Command(['xacro ', urdf, ' ', 'namespace:=', ns])",
        "Command(['xacro ', urdf, ' --inorder', ' namespace:=', ns])",
        "Command(['ros2 run demo tool --ros-args -r __ns:=/', ns])",
        "Command(['xacro ', urdf, ' namespace:=', ns, ' ', extra, 'a:=b'])",  # extra is '' here
        "Command(['xacro ', urdf, ' namespace:=', LaunchConfiguration('unknown')])",
        "Command(['xacro ', urdf, ' ', ns, '_arm:=true'])",  # a mapping's name built from a value
        "Command(['gz sdf -p', urdf])",  # an option glued to its value
        "Command(['xacro -o', urdf])",
    ) == []


XML = """<launch>
  <arg name="ns" default="robot1"/>
  <node pkg="robot_state_publisher" exec="robot_state_publisher">
    <param name="robot_description" type="str"
           value="$(command 'xacro $(find-pkg-share demo)/urdf/bot.urdf.xacro$(var ns)_prefix:=x')"/>
  </node>
  <node pkg="robot_state_publisher" exec="robot_state_publisher" name="ok">
    <param name="robot_description" type="str"
           value="$(command 'xacro $(find-pkg-share demo)/urdf/bot.urdf.xacro ns:=$(var ns)')"/>
  </node>
</launch>
"""


def test_the_xml_command_substitution(demo_findings):
    ((line, message),) = demo_findings({"launch/a.launch.xml": XML}, "launch/a.launch.xml", "L004")
    assert line == 5 and '"robot1_prefix:=x"' not in message and '"robot1" and' not in message
    assert '"...' in message and '"_prefix:=x"' in message
