"""L002 and launch extensions: a workspace Python package that declares a
``launch.frontend.launch_extension`` entry point registers its ``@expose_action`` tags (ros_gz_sim's
<gz_server>), which launch knows when it parses the file."""
from __future__ import annotations

from pathlib import Path

LAUNCH = """<launch>
  <gz_server world_sdf_file="empty.sdf">
    <anything/>
  </gz_server>
  <gz_srever/>
</launch>
"""
ACTION = """from launch.frontend import expose_action


@expose_action('gz_server')
class GzServer:
    pass
"""
SETUP_CFG = "[options.entry_points]\nlaunch.frontend.launch_extension =\n    sim = sim_ext\n"
PACKAGE_XML = ('<?xml version="1.0"?>\n<package format="3"><name>sim_ext</name><version>0.0.0</version>'
               '<description>d</description><maintainer email="a@example.com">a</maintainer>'
               '<license>MIT</license><export><build_type>ament_python</build_type></export></package>\n')


def _l002(tmp_path: Path, demo_findings, entry_point: bool) -> list[tuple[int, str]]:
    ext = tmp_path / "src" / "sim_ext"
    (ext / "sim_ext" / "actions").mkdir(parents=True)
    (ext / "package.xml").write_text(PACKAGE_XML)
    (ext / "setup.cfg").write_text(SETUP_CFG if entry_point else "[metadata]\nname = sim_ext\n")
    (ext / "setup.py").write_text("from setuptools import setup\nsetup(name='sim_ext')\n")
    (ext / "sim_ext" / "actions" / "gz_server.py").write_text(ACTION)
    return demo_findings({"launch/a.launch.xml": LAUNCH}, "launch/a.launch.xml", "L002")


def test_a_workspace_extension_s_tags_are_known(tmp_path, demo_findings):
    assert _l002(tmp_path, demo_findings, entry_point=True) == [
        (5, 'unknown tag "gz_srever"; launch rejects it when it parses the file')]


def test_without_the_entry_point_launch_does_not_load_them(tmp_path, demo_findings):
    assert [line for line, _ in _l002(tmp_path, demo_findings, entry_point=False)] == [2, 3, 5]


RELEASED = """<launch>
  <trace session-name="s1" events-ust="ros2:*"/>
  <gz_server world_sdf_file="empty.sdf"/>
</launch>
"""


def test_released_extensions_tags_are_known_in_the_distros_that_have_them(tmp_path, demo_package):
    # tracetools_launch registers <trace> from humble on; ros_gz_sim its <gz_server> from jazzy
    from physai_lint.engine import CheckOptions, run_check

    path = demo_package({"launch/a.launch.xml": RELEASED}) / "launch/a.launch.xml"

    def l002(distro: str) -> list[tuple[int, str]]:
        opts = CheckOptions(paths=[str(path)], workspace=str(tmp_path), cache=False, distro=distro)
        return [(f.span.line, f.message.split(";")[0]) for f in run_check(opts).findings if f.code == "L002"]

    assert l002("humble") == [(3, 'unknown tag "gz_server"')]
    assert l002("jazzy") == []
