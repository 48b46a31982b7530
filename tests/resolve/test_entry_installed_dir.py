"""``ros2 launch <package> <file>`` runs the installed copy of the file, so ThisLaunchFileDir() /
``$(dirname)`` in the checked file is its folder in the install space: a file beside it in the
source tree that the package does not install is not found there (L105). A file its package does
not install (a test's launch file) keeps its source folder."""
PY = """from launch import LaunchDescription
from launch.actions import IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import ThisLaunchFileDir


def generate_launch_description():
    return LaunchDescription([
        IncludeLaunchDescription(PythonLaunchDescriptionSource([ThisLaunchFileDir(), '/{target}'])),
    ])
"""
SIDE = "from launch import LaunchDescription\n\n\ndef generate_launch_description():\n    return LaunchDescription([])\n"
XML = '<launch>\n  <include file="$(dirname)/{target}"/>\n</launch>\n'


def _l105(demo_findings, entry: str, text: str) -> list[int]:
    files = {entry: text, "launch/side.launch.py": SIDE, "scripts/side.launch.py": SIDE}
    return [line for line, _ in demo_findings(files, entry, "L105")]


def test_a_sibling_the_package_installs_is_found(demo_findings):
    assert _l105(demo_findings, "launch/a.launch.py", PY.format(target="side.launch.py")) == []
    assert _l105(demo_findings, "launch/a.launch.xml", XML.format(target="side.launch.py")) == []


def test_a_file_outside_what_the_package_installs_is_missing_from_the_installed_copy(demo_findings):
    assert _l105(demo_findings, "launch/a.launch.py", PY.format(target="../scripts/side.launch.py")) == [9]
    assert _l105(demo_findings, "launch/a.launch.xml", XML.format(target="../scripts/side.launch.py")) == [2]


def test_a_file_not_installed_keeps_its_source_folder(demo_findings):
    assert _l105(demo_findings, "scripts/a.launch.py", PY.format(target="side.launch.py")) == []
