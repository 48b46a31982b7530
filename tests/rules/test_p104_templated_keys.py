"""P104: a parameter file written as a substitution template (loaded with allow_substs=True) is
not judged by its raw text."""
from __future__ import annotations

from typing import Any

LAUNCH = """from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.descriptions import ParameterFile
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    params = PathJoinSubstitution([FindPackageShare('demo'), 'config', 'arm.yaml'])
    return LaunchDescription([
        DeclareLaunchArgument('robot_name', default_value='arm'),
        Node(package='demo_nodes_cpp', executable='talker', name='driver',
             namespace=LaunchConfiguration('robot_name'),
             parameters=[ParameterFile(params, allow_substs=True)]),
    ])
"""


def test_a_templated_key_is_not_reported(demo_findings: Any) -> None:
    files = {"launch/a.launch.py": LAUNCH,
             "config/arm.yaml": "/$(var robot_name)/driver:\n  ros__parameters:\n    rate: 10\n"}
    assert demo_findings(files, "launch/a.launch.py", "P104") == []


def test_a_plain_invalid_key_still_is(demo_findings: Any) -> None:
    files = {"launch/a.launch.py": LAUNCH,
             "config/arm.yaml": "/arm/dri ver:\n  ros__parameters:\n    rate: 10\n"}
    assert len(demo_findings(files, "launch/a.launch.py", "P104")) == 1


GENERATOR_TEMPLATE = """controller_manager:
  ros__parameters:
    ${name}_controller:
      type: position_controllers/GripperActionController

${name}_controller:
  ros__parameters:
    joint: ${name}_knuckle_joint
"""


def test_a_placeholder_key_in_a_file_no_node_loads_is_a_generators_template(demo_findings: Any) -> None:
    files = {"launch/a.launch.py": LAUNCH.replace("allow_substs=True", "allow_substs=False"),
             "config/arm.yaml": "/arm/driver:\n  ros__parameters:\n    rate: 10\n",
             "config/gripper.yaml": GENERATOR_TEMPLATE}
    assert demo_findings(files, ".", "P104") == []
    files["config/arm.yaml"] = GENERATOR_TEMPLATE  # loaded as it is: rcl's _validate_nodename refuses it
    assert [line for line, _ in demo_findings(files, ".", "P104")] == [6]


def test_a_templated_key_in_a_file_loaded_without_allow_substs_is_reported(demo_findings: Any) -> None:
    template = "/$(var robot_name)/driver:\n  ros__parameters:\n    rate: 10\n"
    for loaded in ("ParameterFile(params, allow_substs=False)", "params"):
        files = {"launch/a.launch.py": LAUNCH.replace("ParameterFile(params, allow_substs=True)", loaded),
                 "config/arm.yaml": template}
        (line, message), = demo_findings(files, "launch/a.launch.py", "P104")
        assert line == 1
        assert message.startswith('invalid node key "/$(var robot_name)/driver": ')
        assert message.endswith("; a node loads the file without ParameterFile(..., allow_substs=True), so rcl "
                                "reads the substitution as written and rejects the whole file for it")
    # the file no node loads is a template of some generator: not judged
    files = {"launch/a.launch.py": LAUNCH, "config/arm.yaml": "/arm/driver:\n  ros__parameters:\n    rate: 1\n",
             "config/other.yaml": template}
    assert demo_findings(files, ".", "P104") == []


def test_one_node_loading_the_template_as_a_plain_path_is_enough(demo_findings: Any) -> None:
    both = LAUNCH.replace("parameters=[ParameterFile(params, allow_substs=True)]),",
                          "parameters=[ParameterFile(params, allow_substs=True)]),\n"
                          "        Node(package='demo_nodes_cpp', executable='talker', name='other', parameters=[params]),")
    files = {"launch/a.launch.py": both,
             "config/arm.yaml": "/$(var robot_name)/driver:\n  ros__parameters:\n    rate: 10\n"}
    assert [line for line, _ in demo_findings(files, "launch/a.launch.py", "P104")] == [1]
