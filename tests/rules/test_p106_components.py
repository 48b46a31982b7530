"""P106 for a parameter file only composable nodes load: launch_ros reads it with PyYAML and
normalizes each array itself (normalize_parameter_dict -> _normalize_parameter_array_value), so
ints with floats become a double array and rcl's "Sequence should be of same type" never happens;
any other mix fails evaluate_parameter_dict's uniform-type check. Checked with launch_ros humble
0.19.8's to_parameters_list on the same file."""
from __future__ import annotations

CAM = "package='image_proc', plugin='image_proc::RectifyNode', name='cam', parameters=[params]"
# a plain node loading the same file: rcl reads it
TALKER = ("\n        Node(package='demo_nodes_cpp', executable='talker', name='cam2',\n"
          "             parameters=[params]),")


def _p106(demo_findings, launch: str, values: str) -> list[tuple[int, str]]:
    files = {"launch/a.launch.py": launch,
             "config/cam.yaml": f"/**:\n  ros__parameters:\n    roi: {values}\n"}
    return demo_findings(files, "launch/a.launch.py", "P106")


def test_ints_with_floats_are_a_double_array_for_a_component(demo_findings, component_launch):
    assert _p106(demo_findings, component_launch(CAM), "[0, 0, 640.0, 480.0]") == []


def test_other_mixes_fail_in_launch_ros(demo_findings, component_launch):
    found = _p106(demo_findings, component_launch(CAM), '[0, "a", 480.0]')
    assert [line for line, _ in found] == [3]
    assert "launch_ros fails loading them with TypeError" in found[0][1]
    assert "rcl:" not in found[0][1]
    assert [line for line, _ in _p106(demo_findings, component_launch(CAM), "[true, 1]")] == [3]


def test_a_file_a_plain_node_loads_is_read_by_rcl(demo_findings, component_launch):
    found = _p106(demo_findings, component_launch(CAM, after=TALKER), "[0, 0, 640.0, 480.0]")
    assert [line for line, _ in found] == [3]
    assert "rcl: \"Sequence should be of same type" in found[0][1]
