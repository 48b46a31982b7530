"""L005 (undefined-name) says when the NameError comes (loading the file, or when a function
reaches the line) and helps with what the name most likely is: a launch API to import, or a
name defined there that it misspells."""
from __future__ import annotations

HEAD = "from launch import LaunchDescription\nfrom launch_ros.actions import Node\n\n"


def _l005(demo_findings, body: str) -> list[tuple[int, str]]:
    return demo_findings({"launch/a.launch.py": HEAD + body}, "launch/a.launch.py", "L005")


def _help(demo_package, tmp_path, body: str) -> list[str]:
    from physai_lint.engine import CheckOptions, run_check

    path = demo_package({"launch/a.launch.py": HEAD + body}) / "launch/a.launch.py"
    opts = CheckOptions(paths=[str(path)], workspace=str(tmp_path), cache=False)
    return [f.help for f in run_check(opts).findings if f.code == "L005"]


MISSPELT = """
def generate_launch_description():
    params_b = {'rpm': 600.0}
    return LaunchDescription([
        Node(package='demo', executable='talker', parameters=[params_c]),
    ])
"""


def test_a_name_inside_a_function_raises_when_the_function_reaches_it(demo_findings) -> None:
    [(line, message)] = _l005(demo_findings, MISSPELT)
    assert line == 8
    assert message == ('name "params_c" is used but never imported or defined; '
                       "generate_launch_description() raises NameError when it reaches this line")


def test_a_misspelt_local_name_is_suggested_not_an_import(demo_package, tmp_path) -> None:
    [help_] = _help(demo_package, tmp_path, MISSPELT)
    assert help_ == 'did you mean "params_b"? Otherwise import or define "params_c"'


def test_a_launch_api_name_is_suggested_with_its_module(demo_package, tmp_path) -> None:
    [help_] = _help(demo_package, tmp_path, (
        "def generate_launch_description():\n"
        "    return LaunchDescription([DeclareLaunchArgument('x', default_value='1')])\n"))
    assert help_ == 'import it: "from launch.actions import DeclareLaunchArgument"'


def test_a_name_at_module_level_raises_on_loading(demo_findings) -> None:
    [(_, message)] = _l005(demo_findings, (
        "CONFIG = make_config()\n\n"
        "def generate_launch_description():\n    return LaunchDescription([])\n"))
    assert message.endswith("; loading the file raises NameError")
