"""T204 reports two servers of one name only between nodes both certainly started (as N101), and
never on the services every lifecycle node has."""
from __future__ import annotations

from pathlib import Path
from typing import Any

from physai_lint.engine import CheckOptions, run_check

INTERFACES = """demo/gripper_server:
  services: [{name: /gripper/open, type: std_srvs/srv/Trigger}]
demo/gripper_sim:
  services: [{name: gripper/open, type: std_srvs/srv/Trigger}]
"""
LAUNCH = """<launch>
  <let name="hw" value="$(command 'detect_gripper')"/>
  <node pkg="demo" exec="gripper_server" name="gripper_hw"{hw}/>
  <node pkg="demo" exec="gripper_sim" name="gripper_sim"{sim}/>
</launch>
"""


def _t204(tmp_path: Path, demo_package: Any, launch: str, interfaces: str = INTERFACES) -> list[str]:
    pkg = demo_package({"launch/a.launch.xml": launch})
    (tmp_path / "interfaces.yaml").write_text(interfaces)
    opts = CheckOptions(paths=[str(pkg / "launch/a.launch.xml")], workspace=str(tmp_path), cache=False,
                        interfaces=[str(tmp_path / "interfaces.yaml")])
    return [f.message for f in run_check(opts).findings if f.code == "T204"]


def test_both_started(tmp_path: Path, demo_package: Any) -> None:
    found = _t204(tmp_path, demo_package, LAUNCH.format(hw="", sim=""))
    assert len(found) == 1 and '"/gripper/open"' in found[0]


def test_conditions_that_cannot_be_evaluated(tmp_path: Path, demo_package: Any) -> None:
    # one if, one unless on a value only known at launch time: never both started
    launch = LAUNCH.format(hw=' if="$(var hw)"', sim=' unless="$(var hw)"')
    assert _t204(tmp_path, demo_package, launch) == []


def test_lifecycle_services_are_not_duplicates(tmp_path: Path, demo_package: Any) -> None:
    # two lifecycle nodes of one name collide on ~/change_state & co. too: that is N101's finding
    # (one), not five more T204 ones; the service they declare is still reported
    launch = ("from launch import LaunchDescription\nfrom launch_ros.actions import LifecycleNode\n\n\n"
              "def generate_launch_description():\n    return LaunchDescription([\n"
              "        LifecycleNode(package='demo', executable='gripper_server', name='g', namespace=''),\n"
              "        LifecycleNode(package='demo', executable='gripper_server', name='g', namespace=''),\n"
              "    ])\n")
    pkg = demo_package({"launch/a.launch.py": launch})
    (tmp_path / "interfaces.yaml").write_text(INTERFACES)
    opts = CheckOptions(paths=[str(pkg / "launch/a.launch.py")], workspace=str(tmp_path), cache=False,
                        interfaces=[str(tmp_path / "interfaces.yaml")])
    findings = run_check(opts).findings
    assert [f.message.split('"')[-2] for f in findings if f.code == "T204"] == ["/gripper/open"]
    assert [f.code for f in findings if f.code == "N101"] == ["N101"]
