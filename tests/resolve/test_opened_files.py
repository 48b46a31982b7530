"""A Python launch file that opens a file of a package's share directory while its description is
built (``open(path)``, ``Path(path).read_text()``) fails there with FileNotFoundError when the file
is not installed: U104, unless the open may not run (a ``try`` body, an undecided branch, a
function launch calls later) or only writes."""
from __future__ import annotations

LAUNCH = """
import os
from pathlib import Path

from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import OpaqueFunction
from launch_ros.actions import Node


def later(context):
    open(os.path.join(get_package_share_directory('demo'), 'urdf', 'late.urdf')).read()
    return []


def generate_launch_description():
    share = get_package_share_directory('demo')
    with open(os.path.join(share, 'urdf', 'robot.urdf')) as f:
        description = f.read()
    installed = open(os.path.join(share, 'config', 'ok.yaml')).read()
    srdf = Path(share, 'urdf', 'arm.srdf').read_text()
    log = open(os.path.join(share, 'config', 'out.log'), 'w')
    try:
        extra = open(os.path.join(share, 'urdf', 'optional.urdf')).read()
    except OSError:
        extra = ''
    if os.environ.get('WITH_GRIPPER'):
        open(os.path.join(share, 'urdf', 'gripper.urdf'))
    kept = open(os.path.join(share, 'urdf', 'kept.urdf')).read()
    return LaunchDescription([
        OpaqueFunction(function=later),
        Node(package='robot_state_publisher', executable='robot_state_publisher',
             parameters=[{'robot_description': description + srdf + installed + extra + kept}]),
    ])
"""


def test_files_opened_while_the_description_is_built(demo_findings):
    found = demo_findings({"launch/a.launch.py": LAUNCH, "config/ok.yaml": "a: 1\n",
                           "urdf/robot.urdfx": "<robot/>", "urdf/kept.urdf": "<robot/>"},
                          "launch/a.launch.py", "U104")
    assert [(line, msg.split(" while")[0]) for line, msg in found] == [
        (18, 'file "urdf/robot.urdf" opened'),
        (21, 'file "urdf/arm.srdf" opened'),
        (29, 'file "urdf/kept.urdf" opened'),
    ]
    by_line = dict(found)
    assert by_line[18].endswith('launch fails with FileNotFoundError; did you mean "urdf/robot.urdfx" or "urdf/kept.urdf"?')
    assert 'is in the sources of package "demo" but is not installed' in by_line[29]
