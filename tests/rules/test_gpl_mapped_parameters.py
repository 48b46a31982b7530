"""generate_parameter_library ``__map_<array>`` subtrees: ParamListener declares the subtree once
per element of the string array (``gains.<joint>.i`` for each joint), with the template's type
and validation, so values given to those instances are checked like any declared parameter."""
from __future__ import annotations

from typing import Any

CMAKE = """project(demo)
generate_parameter_library(pid_parameters src/pid_parameters.yaml)
add_executable(pid src/pid.cpp)
target_link_libraries(pid pid_parameters)
install(TARGETS pid DESTINATION lib/${PROJECT_NAME})
install(DIRECTORY launch config DESTINATION share/${PROJECT_NAME})
"""
GPL = """pid:
  joints:
    type: string_array
    default_value: [shoulder]
  gains:
    __map_joints:
      i:
        type: double
        default_value: 0.0
        validation:
          gt_eq<>: [0.0]
"""
CPP = '#include "demo/pid_parameters.hpp"\nint main() { return 0; }\n'
LAUNCH = """from launch import LaunchDescription
from launch.substitutions import PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    params = PathJoinSubstitution([FindPackageShare('demo'), 'config', 'pid.yaml'])
    return LaunchDescription([Node(package='demo', executable='pid', name='pid', parameters=[params])])
"""


def _findings(demo_findings: Any, params: str, code: str) -> list[int]:
    files = {"CMakeLists.txt": CMAKE, "src/pid_parameters.yaml": GPL, "src/pid.cpp": CPP,
             "launch/a.launch.py": LAUNCH, "config/pid.yaml": params}
    return [line for line, _ in demo_findings(files, "launch/a.launch.py", code)]


def test_an_instance_of_a_mapped_declaration_is_validated(demo_findings: Any) -> None:
    params = ("pid:\n  ros__parameters:\n    joints: [shoulder, elbow]\n    gains:\n"
              "      shoulder: {i: 0.5}\n      elbow: {i: -0.1}\n")
    assert _findings(demo_findings, params, "P107") == [6]


def test_the_instances_follow_the_default_of_the_array(demo_findings: Any) -> None:
    params = "pid:\n  ros__parameters:\n    gains:\n      shoulder: {i: 1}\n      elbow: {i: 1}\n"
    # joints defaults to [shoulder]: only gains.shoulder.i is declared, an int for a double
    assert _findings(demo_findings, params, "P105") == [4]


def test_the_default_of_the_array_counts_only_when_every_source_is_known(demo_findings: Any) -> None:
    # a parameter file not known here may set joints: the instances are then unknown
    launch = LAUNCH.replace("parameters=[params]", "parameters=[params, LaunchConfiguration('extra')]").replace(
        "from launch.substitutions import PathJoinSubstitution",
        "from launch.substitutions import LaunchConfiguration, PathJoinSubstitution")
    files = {"CMakeLists.txt": CMAKE, "src/pid_parameters.yaml": GPL, "src/pid.cpp": CPP,
             "launch/a.launch.py": launch,
             "config/pid.yaml": "pid:\n  ros__parameters:\n    gains:\n      shoulder: {i: 1}\n"}
    assert demo_findings(files, "launch/a.launch.py", "P105") == []
