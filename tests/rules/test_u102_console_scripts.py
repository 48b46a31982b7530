"""U102 (unknown-executable) on an ament_python package whose console scripts go to ``bin/``:
without a setup.cfg sending them to ``lib/<package>``, launch cannot find them, and the finding
says why instead of "it provides: none"."""
from __future__ import annotations

from pathlib import Path

import pytest

from physai_lint.engine import CheckOptions, run_check

PACKAGE_XML = """<package format="3"><name>pybot</name><version>0.0.0</version><description>d</description>
<maintainer email="m@example.com">a</maintainer><license>MIT</license>
<export><build_type>ament_python</build_type></export></package>
"""
SETUP_PY = """from setuptools import setup

setup(
    name='pybot',
    packages=['pybot'],
    data_files=[('share/pybot', ['package.xml']), ('share/pybot/launch', ['launch/a.launch.py'])],
    entry_points={'console_scripts': ['driver = pybot.driver:main']},
)
"""
SETUP_CFG = "[develop]\nscript_dir=$base/lib/pybot\n[install]\ninstall_scripts=$base/lib/pybot\n"
LAUNCH = """from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='pybot', executable='driver', name='a'),
        Node(package='pybot', executable='driver.py', name='b'),
    ])
"""


def _u102(tmp_path: Path, setup_cfg: str | None, setup_py: str = SETUP_PY) -> list[tuple[int, str, str]]:
    pkg = tmp_path / "src" / "pybot"
    files = {"package.xml": PACKAGE_XML, "setup.py": setup_py, "launch/a.launch.py": LAUNCH,
             "pybot/__init__.py": "", "resource/pybot": ""}
    if setup_cfg is not None:
        files["setup.cfg"] = setup_cfg
    for rel, text in files.items():
        (pkg / rel).parent.mkdir(parents=True, exist_ok=True)
        (pkg / rel).write_text(text)
    report = run_check(CheckOptions(paths=[str(pkg / "launch/a.launch.py")], workspace=str(tmp_path), cache=False))
    return sorted((f.span.line, f.message, f.help) for f in report.findings if f.code == "U102")


@pytest.mark.parametrize("setup_cfg", [None, "[metadata]\nname = pybot\n"])
def test_console_scripts_in_bin_are_explained(tmp_path: Path, setup_cfg: str | None) -> None:
    found = _u102(tmp_path, setup_cfg)
    assert [line for line, _, _ in found] == [7, 8]
    (_, msg_a, help_a), (_, msg_b, help_b) = found
    assert msg_a.startswith('package "pybot" installs its console script "driver" to bin/ (no setup.cfg sends '
                            'its scripts elsewhere), not to lib/pybot, where launch looks for "driver"')
    assert "script_dir=$base/lib/pybot" in help_a and "install_scripts=$base/lib/pybot" in help_a
    assert 'where launch looks for "driver.py"' in msg_b and help_b.endswith(', and use "driver"')


def test_console_scripts_sent_to_another_package_dir(tmp_path: Path) -> None:
    """A package renamed without its setup.cfg (seen in a public workspace)."""
    found = _u102(tmp_path, SETUP_CFG.replace("lib/pybot", "lib/old_name"))
    _, msg, help_ = found[0]
    assert msg.startswith('package "pybot" installs its console script "driver" to $base/lib/old_name '
                          "(setup.cfg's script_dir), not to lib/pybot")
    assert help_ == "set script_dir and install_scripts in setup.cfg to $base/lib/pybot"


def test_console_scripts_in_lib_are_executables(tmp_path: Path) -> None:
    found = _u102(tmp_path, SETUP_CFG)
    assert [(line, msg) for line, msg, _ in found] == [
        (8, 'package "pybot" has no executable "driver.py" (did you mean "driver"?); it provides: "driver"')]


def test_a_long_list_of_executables_says_how_many_are_left_out(demo_findings):
    names = [f"tool_{i:02d}" for i in range(11)]
    cmake = ("project(demo)\n" + "".join(f"add_executable({n} src/{n}.cpp)\n" for n in names)
             + f"install(TARGETS {' '.join(names)} DESTINATION lib/${{PROJECT_NAME}})\n")
    launch = '<launch>\n  <node pkg="demo" exec="tool_99" name="t"/>\n</launch>\n'
    found = demo_findings({"CMakeLists.txt": cmake, "launch/a.launch.xml": launch}, "launch/a.launch.xml", "U102")
    assert [m.rsplit("it provides: ", 1)[1] for _, m in found] == [
        ", ".join(f'"{n}"' for n in names[:8]) + " and 3 more"]


def test_distutils_scripts_go_where_console_scripts_go(tmp_path: Path) -> None:
    """setup(scripts=['scripts/driver.py']) copies the file, under its own name, to install_scripts."""
    setup_py = SETUP_PY.replace("    entry_points=", "    scripts=['scripts/driver.py'],\n    entry_points=")
    assert _u102(tmp_path, SETUP_CFG, setup_py) == []
