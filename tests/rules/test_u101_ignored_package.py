"""U101 for a package of the workspace whose directory holds COLCON_IGNORE (AMENT_IGNORE,
CATKIN_IGNORE): colcon skips it, so nothing installs it, even when the launching package's
package.xml declares it (which otherwise lets rosdep provide a package unknown here)."""
from __future__ import annotations

from pathlib import Path
from typing import Any

from physai_lint.engine import CheckOptions, run_check

LAUNCH = """<launch>
  <node pkg="survey_gnss" exec="gnss_node" name="gnss"/>
</launch>
"""
GNSS_XML = """<package format="3"><name>survey_gnss</name><version>0.0.0</version><description>d</description>
<maintainer email="m@example.com">a</maintainer><license>MIT</license>
<export><build_type>ament_cmake</build_type></export></package>
"""


def _u101(tmp_path: Path, demo_package: Any, marker: str | None) -> list[str]:
    xml = (demo_package({"launch/a.launch.xml": LAUNCH}) / "package.xml")
    xml.write_text(xml.read_text().replace("<export>", "<exec_depend>survey_gnss</exec_depend><export>"))
    gnss = tmp_path / "src" / "survey_gnss"
    gnss.mkdir(parents=True)
    (gnss / "package.xml").write_text(GNSS_XML)
    (gnss / "CMakeLists.txt").write_text("project(survey_gnss)\n")
    if marker:
        (gnss / marker).write_text("")
    opts = CheckOptions(paths=[str(xml.parent / "launch/a.launch.xml")], workspace=str(tmp_path), cache=False)
    return [f.message for f in run_check(opts).findings if f.code == "U101"]


def test_a_package_colcon_skips_is_unknown_even_when_declared(tmp_path: Path, demo_package: Any) -> None:
    found = _u101(tmp_path, demo_package, "COLCON_IGNORE")
    assert len(found) == 1 and found[0].startswith('package "survey_gnss" is in ')
    assert "which holds COLCON_IGNORE: colcon skips it" in found[0]


def test_the_same_package_built_is_fine(tmp_path: Path, demo_package: Any) -> None:
    assert _u101(tmp_path, demo_package, None) == []
