"""A launch file included through ``find-pkg-share`` from a package that installs its share
directories with autoware_cmake's ``autoware_ament_auto_package`` is installed, not missing."""
from __future__ import annotations

from pathlib import Path
from typing import Callable

CMAKE = """cmake_minimum_required(VERSION 3.14)
project(demo)
find_package(autoware_cmake REQUIRED)
autoware_package()
autoware_ament_auto_package(INSTALL_TO_SHARE config launch)
"""
OUTER = """<launch>
  <include file="$(find-pkg-share demo)/launch/inner.launch.xml">
    <arg name="params" value="$(find-pkg-share demo)/config/inner.param.yaml"/>
  </include>
</launch>
"""
INNER = """<launch>
  <arg name="params"/>
  <node pkg="demo" exec="inner" name="inner">
    <param from="$(var params)"/>
  </node>
</launch>
"""


def _codes(tmp_path: Path, demo_package: Callable[[dict[str, str]], Path], cmake: str) -> list[str]:
    from physai_lint.engine import CheckOptions, run_check

    pkg = demo_package({"CMakeLists.txt": cmake, "launch/outer.launch.xml": OUTER,
                        "launch/inner.launch.xml": INNER,
                        "config/inner.param.yaml": "inner:\n  ros__parameters:\n    rate: 1\n"})
    opts = CheckOptions(paths=[str(pkg / "launch/outer.launch.xml")], workspace=str(tmp_path), cache=False)
    return [f.code for f in run_check(opts).findings]


def test_autoware_ament_auto_package_installs_share_dirs(tmp_path, demo_package):
    assert "L105" not in _codes(tmp_path, demo_package, CMAKE)


def test_without_install_to_share_the_include_is_still_not_installed(tmp_path, demo_package):
    assert "L105" in _codes(tmp_path, demo_package, CMAKE.replace("INSTALL_TO_SHARE config launch", ""))
