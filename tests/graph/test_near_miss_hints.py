"""T201/T202 near-miss hints: the same topic in another robot's namespace (``/robot2/cmd_vel``
for ``/robot1/cmd_vel``) is that robot's copy, not a misspelling; a name at another depth
(``/scan`` for ``/robot1/scan``: an absolute name in the code) still is one."""
from __future__ import annotations

from pathlib import Path
from typing import Any

from physai_lint.engine import CheckOptions, run_check

INTERFACES = """demo/mux:
  subscribers: [{name: cmd_vel_joy, type: geometry_msgs/msg/Twist}, {name: /scan, type: sensor_msgs/msg/LaserScan}]
demo/joy:
  publishers: [{name: cmd_vel_joy, type: geometry_msgs/msg/Twist}]
demo/lidar:
  publishers: [{name: scan, type: sensor_msgs/msg/LaserScan}]
"""
LAUNCH = """<launch>
  <group><push_ros_namespace namespace="robot1"/>
    <node pkg="demo" exec="mux" name="mux"/>
    <node pkg="demo" exec="lidar" name="lidar"/>
  </group>
  <group><push_ros_namespace namespace="robot2"/>
    <node pkg="demo" exec="mux" name="mux"/>
    <node pkg="demo" exec="joy" name="joy"/>
    <node pkg="demo" exec="lidar" name="lidar"/>
  </group>
</launch>
"""


def test_another_robots_copy_is_no_near_miss(tmp_path: Path, demo_nodes: Any) -> None:
    pkg = demo_nodes({"mux": "", "joy": "", "lidar": ""}, {"launch/a.launch.xml": LAUNCH})
    (tmp_path / "interfaces.yaml").write_text(INTERFACES)
    opts = CheckOptions(paths=[str(pkg / "launch/a.launch.xml")], workspace=str(tmp_path), cache=False,
                        interfaces=[str(tmp_path / "interfaces.yaml")])
    found = sorted((f.span.line, f.message) for f in run_check(opts).findings if f.code == "T201")
    assert found == [
        (3, '/robot1/mux subscribes to "/robot1/cmd_vel_joy" but nothing publishes it'),
        (3, '/robot1/mux subscribes to "/scan" but nothing publishes it (did you mean "/robot1/scan" or '
            '"/robot2/scan"?)'),
        (7, '/robot2/mux subscribes to "/scan" but nothing publishes it (did you mean "/robot1/scan" or '
            '"/robot2/scan"?)'),
    ]
