"""T103 for a SetRemap that reaches nodes but matches no name any of them uses (rcl's
rcl_remap_first_match compares the expanded match name with each expanded topic name): reported only
when every node it reaches has a declared interface, as T102 does for a node's own rules."""
from __future__ import annotations

from typing import Any

from physai_lint.engine import CheckOptions, run_check

CMAKE = """project(demo)
add_executable(gate src/gate.cpp)
add_executable(other src/other.cpp)
install(TARGETS gate other DESTINATION lib/${PROJECT_NAME})
install(DIRECTORY launch DESTINATION share/${PROJECT_NAME})
"""
LAUNCH = """from launch import LaunchDescription
from launch.actions import GroupAction
from launch_ros.actions import Node, PushRosNamespace, SetRemap


def generate_launch_description():
    return LaunchDescription([
        GroupAction([
            PushRosNamespace('tb3_0'),
            SetRemap(src={src!r}, dst='cmd_vel_safe'),
            Node(package='demo', executable='gate', name='gate'),{more}
        ]),
    ])
"""
INTERFACES = "demo/gate:\n  publishers: [cmd_vel]\n  subscribers: [scan]\n"
OTHER = "demo/other:\n  publishers: [odom]\n"


def _t103(tmp_path: Any, demo_package: Any, src: str, more: str = "", interfaces: str = INTERFACES
          ) -> list[tuple[int, str]]:
    pkg = demo_package({"CMakeLists.txt": CMAKE, "src/gate.cpp": "", "src/other.cpp": "",
                        "launch/a.launch.py": LAUNCH.format(src=src, more=more)})
    (tmp_path / "interfaces.yaml").write_text(interfaces)
    opts = CheckOptions(paths=[str(pkg / "launch/a.launch.py")], workspace=str(tmp_path),
                        interfaces=[str(tmp_path / "interfaces.yaml")], cache=False)
    return [(f.span.line, f.message) for f in run_check(opts).findings if f.code == "T103"]


def test_an_absolute_rule_for_a_relative_name_in_a_pushed_namespace(tmp_path: Any, demo_package: Any):
    found = _t103(tmp_path, demo_package, "/cmd_vel")
    assert len(found) == 1 and found[0][0] == 10, found
    assert 'matches no topic or service of the nodes it reaches (/tb3_0/gate' in found[0][1]
    assert 'write the rule as "cmd_vel"' in found[0][1]


def test_a_rule_a_node_uses_is_fine(tmp_path: Any, demo_package: Any):
    assert _t103(tmp_path, demo_package, "cmd_vel") == []


def test_a_rule_one_of_several_nodes_uses_is_fine(tmp_path: Any, demo_package: Any):
    more = "\n            Node(package='demo', executable='other', name='other'),"
    assert _t103(tmp_path, demo_package, "odom", more, INTERFACES + OTHER) == []
    found = _t103(tmp_path, demo_package, "odm", more, INTERFACES + OTHER)
    assert len(found) == 1 and "/tb3_0/gate" in found[0][1] and "/tb3_0/other" in found[0][1]


def test_a_node_whose_names_are_not_declared_may_use_it(tmp_path: Any, demo_package: Any):
    more = "\n            Node(package='demo', executable='other', name='other'),"
    assert _t103(tmp_path, demo_package, "odm", more) == []
