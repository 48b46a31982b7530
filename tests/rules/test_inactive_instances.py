"""A node one entry includes under a false condition and another starts is checked as started:
which entry comes first must not decide whether its findings are reported."""
from __future__ import annotations

from pathlib import Path
from typing import Any

from physai_lint.engine import CheckOptions, run_check

TALKER = """<launch>
  <node pkg="demo_nodes_cpp" exec="talker" name="talker">
    <param from="$(find-pkg-share demo)/config/talker.yaml"/>
  </node>
</launch>
"""
OPTIONAL = """<launch>
  <arg name="talk" default="false"/>
  <include file="$(find-pkg-share demo)/launch/talker.launch.xml" if="$(var talk)"/>
</launch>
"""
ALWAYS = """<launch>
  <include file="$(find-pkg-share demo)/launch/talker.launch.xml"/>
</launch>
"""


def test_the_started_instance_wins(tmp_path: Path, demo_package: Any) -> None:
    for first in ("a_optional", "c_optional"):  # before and after b_always.launch.xml
        pkg = demo_package({"launch/talker.launch.xml": TALKER, f"launch/{first}.launch.xml": OPTIONAL,
                            "launch/b_always.launch.xml": ALWAYS,
                            "config/talker.yaml": "speaker:\n  ros__parameters:\n    rate: 2\n"})
        report = run_check(CheckOptions(paths=[str(pkg)], workspace=str(tmp_path), cache=False))
        assert [f.code for f in report.findings if f.code == "P103"] == ["P103"], first
        (pkg / "launch" / f"{first}.launch.xml").unlink()
