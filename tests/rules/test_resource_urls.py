"""Resource URLs in parameter values (``package://<package>/<path>``, ``file:///<path>``), which a
node resolves itself (camera_info_manager's ``camera_info_url``, resource_retriever): U101 for
the package, U104 for the file, P114 for a ``camera_info_url`` camera_info_manager rejects."""
from __future__ import annotations

from typing import Any

import pytest

DEPENDS_ON_CIM = """<package format="3"><name>demo</name><version>0.0.0</version><description>d</description>
<maintainer email="m@example.com">a</maintainer><license>MIT</license>
<depend>camera_info_manager</depend>
<export><build_type>ament_cmake</build_type></export></package>
"""

XML = """<launch>
  <node pkg="usb_cam" exec="usb_cam_node_exe" name="rear">
    <param name="camera_info_url" value="{url}"/>
  </node>
</launch>
"""

PARAMS_LAUNCH = """from launch import LaunchDescription
from launch.substitutions import PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    return LaunchDescription([
        Node(package='usb_cam', executable='usb_cam_node_exe', name='front',
             parameters=[PathJoinSubstitution([FindPackageShare('demo'), 'config', 'cam.yaml'])]),
    ])
"""

PY = """from launch import LaunchDescription
from launch.substitutions import PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    share = FindPackageShare('demo')
    return LaunchDescription([
        Node(package='{pkg}', executable='{exe}', name='front',
             parameters=[{{'camera_info_url': {value}}}]),
    ])
"""

CALIBRATION = "image_width: 640\nimage_height: 480\ncamera_name: front\n"


def _xml(demo_findings: Any, url: str, code: str) -> list[tuple[int, str]]:
    files = {"launch/cam.launch.xml": XML.format(url=url), "config/front.yaml": CALIBRATION}
    return demo_findings(files, "launch/cam.launch.xml", code)


def _params(demo_findings: Any, url: str, code: str, **extra: str) -> list[tuple[int, str]]:
    files = {"launch/cam.launch.py": PARAMS_LAUNCH, "config/front.yaml": CALIBRATION,
             "config/cam.yaml": f"/**:\n  ros__parameters:\n    camera_name: front\n    camera_info_url: {url}\n",
             **extra}
    return demo_findings(files, "launch/cam.launch.py", code)


def _py(demo_findings: Any, value: str, code: str, pkg: str = "usb_cam", exe: str = "usb_cam_node_exe",
        **extra: str) -> list[tuple[int, str]]:
    files = {"launch/cam.launch.py": PY.format(pkg=pkg, exe=exe, value=value), "config/front.yaml": CALIBRATION,
             **extra}
    return demo_findings(files, "launch/cam.launch.py", code)


def test_the_package_of_a_package_url_must_exist(demo_findings: Any) -> None:
    found = _xml(demo_findings, "package://demo_camera_calibrations/config/front.yaml", "U101")
    assert [line for line, _ in found] == [3]
    assert found[0][1].startswith(
        'package "demo_camera_calibrations" of URL "package://demo_camera_calibrations/config/front.yaml" '
        '(parameter "camera_info_url" of /rear) is not in the workspace or the humble distro, so the node '
        'cannot resolve the URL')


@pytest.mark.parametrize("url", ["package://demo/config/front.yaml", "package://usb_cam/config/camera_info.yaml",
                                 "package://${NAME}_calibration/front.yaml", "package://", "file:///opt/cam.yaml",
                                 "package://demo/calibration/${NAME}.yaml"])
def test_known_packages_and_urls_not_yet_known_are_not_reported(demo_findings: Any, url: str) -> None:
    assert _xml(demo_findings, url, "U101") == []
    assert _xml(demo_findings, url, "U104") == []


def test_a_package_url_in_a_parameter_file_names_a_missing_file(demo_findings: Any) -> None:
    found = _params(demo_findings, "package://demo/config/fromt.yaml", "U104")
    assert [line for line, _ in found] == [4]
    assert found[0][1].startswith(
        'file "config/fromt.yaml" named by URL "package://demo/config/fromt.yaml", given as parameter '
        '"camera_info_url" for "/**" in a parameter file, does not exist in package "demo"')
    assert 'did you mean "config/front.yaml"' in found[0][1]
    assert "the camera runs uncalibrated" in found[0][1]


def test_a_package_url_naming_a_file_that_is_not_installed(demo_findings: Any) -> None:
    found = _params(demo_findings, "package://demo/calibration/front.yaml", "U104",
                    **{"calibration/front.yaml": CALIBRATION})
    assert [line for line, _ in found] == [4]
    assert "exists in the sources of package \"demo\" but is not installed" in found[0][1]


def test_a_package_url_naming_an_installed_file_is_quiet(demo_findings: Any) -> None:
    assert _params(demo_findings, "package://demo/config/front.yaml", "U104") == []
    assert _params(demo_findings, "package://demo/config/${NAME}.yaml", "U104") == []


def test_a_file_url_built_from_the_package_share(demo_findings: Any) -> None:
    missing = "['file://', PathJoinSubstitution([share, 'config', 'rear.yaml'])]"
    found = _py(demo_findings, missing, "U104")
    assert [line for line, _ in found] == [11]
    assert 'file "config/rear.yaml" named by URL "file://' in found[0][1]
    assert _py(demo_findings, "['file://', PathJoinSubstitution([share, 'config', 'front.yaml'])]", "U104") == []


def test_a_path_that_runs_the_package_share_into_the_next_part(demo_findings: Any) -> None:
    for value in ("['file://', share, 'config/front.yaml']", "[share, 'config/front.yaml']"):
        found = _py(demo_findings, value, "U104")
        assert found == [(11, 'path given as parameter "camera_info_url" of /front runs the share directory of '
                              'package "demo" into "config": it names "share/democonfig/front.yaml", which does '
                              'not exist; a "/" is missing between "share/demo" and "config/front.yaml"')]
    assert _py(demo_findings, "[share, '/config/front.yaml']", "U104") == []


def test_p114_a_bare_path_is_no_camera_info_url(demo_findings: Any) -> None:
    found = _py(demo_findings, "PathJoinSubstitution([share, 'config', 'front.yaml'])", "P114")
    assert [line for line, _ in found] == [11]
    message = found[0][1]
    assert message.startswith('parameter "camera_info_url" of /front is "/')
    assert message.endswith('/install/demo/share/demo/config/front.yaml", a path, not a URL: camera_info_manager '
                            'accepts only "file:///<absolute path>", "package://<package>/<path>" or "" (the '
                            'default), logs "Invalid camera calibration URL" for anything else and loads no '
                            'calibration, so the camera publishes a CameraInfo with K all zero')


@pytest.mark.parametrize("url, why", [
    ("file://config/front.yaml", "a file URL whose path is not absolute"),
    ("package://demo", "a package URL with no package name or no file after it"),
    ("http://cameras.local/front.yaml", 'a URL with the scheme "http"'),
    ("config/front.yaml", "neither a URL nor an absolute path"),
    ("flash:///front", "a flash URL, which camera_info_manager recognises but does not read"),
])
def test_p114_forms_camera_info_manager_rejects(demo_findings: Any, url: str, why: str) -> None:
    found = _params(demo_findings, url, "P114")
    assert [line for line, _ in found] == [4]
    assert f'parameter "camera_info_url" for "/**" in a parameter file is "{url}", {why}' in found[0][1]


@pytest.mark.parametrize("url", ["", "''", "file:///home/robot/front.yaml", "FILE:///home/robot/front.yaml",
                                 "package://demo/config/front.yaml",
                                 "file://${ROS_HOME}/camera_info/${NAME}.yaml"])
def test_p114_forms_camera_info_manager_reads(demo_findings: Any, url: str) -> None:
    assert _params(demo_findings, url, "P114") == []


def test_p114_judges_only_drivers_that_use_camera_info_manager(demo_findings: Any) -> None:
    bare = "PathJoinSubstitution([share, 'config', 'front.yaml'])"
    cpp = "#include <camera_info_manager/camera_info_manager.hpp>\n"
    # a node of the workspace reading its own camera_info_url may take a plain path
    assert _py(demo_findings, bare, "P114", pkg="demo", exe="cam", **{"src/cam.cpp": cpp}) == []
    # one whose package depends on camera_info_manager hands it on
    found = _py(demo_findings, bare, "P114", pkg="demo", exe="cam",
                **{"package.xml": DEPENDS_ON_CIM, "src/cam.cpp": cpp})
    assert [line for line, _ in found] == [11]


def test_the_package_of_a_url_with_the_camera_name_in_its_path(demo_findings: Any) -> None:
    found = _xml(demo_findings, "package://demo_camera_calibrations/${NAME}.yaml", "U101")
    assert [line for line, _ in found] == [3]


MIXED = """from launch import LaunchDescription
from launch.substitutions import PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    params = PathJoinSubstitution([FindPackageShare('demo'), 'config', 'cams.yaml'])
    common = {'camera_info_url': '/opt/calib/front.yaml'}
    return LaunchDescription([
        Node(package='demo', executable='checker', name='calib_checker', parameters=[params, common]),
        Node(package='usb_cam', executable='usb_cam_node_exe', name='front', parameters=[params, common]),
    ])
"""

CAMS = """front:
  ros__parameters:
    camera_info_url: /opt/calib/front.yaml
calib_checker:
  ros__parameters:
    camera_info_url: /opt/calib/rear.yaml
"""


def test_p114_judges_the_values_that_reach_a_camera(demo_findings: Any) -> None:
    # a file's block by the nodes it names; a dict given to several nodes by all of them
    found = demo_findings({"launch/a.launch.py": MIXED, "config/cams.yaml": CAMS}, "launch/a.launch.py", "P114")
    assert [(line, msg.split(" is ")[0]) for line, msg in found] == [
        (3, 'parameter "camera_info_url" for "front" in a parameter file'),
        (9, 'parameter "camera_info_url" of /calib_checker'),
    ]


def test_p114_leaves_a_list_to_the_type_rules(demo_findings: Any) -> None:
    assert _py(demo_findings, "['/opt/a.yaml', '/opt/b.yaml']", "P114") == []
