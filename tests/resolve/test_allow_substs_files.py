"""Workspace parameter files loaded with allow_substs: launch_ros performs their $(...) first."""
import json

from physai_lint import api
from physai_lint.engine import CheckOptions

PKG = """<package format="3"><name>demo</name><version>0.0.0</version><description>d</description>
<maintainer email="m@example.com">a</maintainer><license>MIT</license>
<export><build_type>ament_cmake</build_type></export></package>
"""

PARAMS = """/**:
  ros__parameters:
    use_external: $(var use_ext)
    rate: $(var rate)
    name: fixed
"""

LAUNCH = """<launch>
  <arg name="use_ext" default="false"/>
  <arg name="rate"/>
  <node pkg="demo" exec="a" name="subst">
    <param from="$(find-pkg-share demo)/config/p.yaml" allow_substs="true"/>
  </node>
  <node pkg="demo" exec="a" name="plain">
    <param from="$(find-pkg-share demo)/config/p.yaml"/>
  </node>
</launch>
"""


def _graph(tmp_path, **args):
    pkg = tmp_path / "src" / "demo"
    (pkg / "launch").mkdir(parents=True, exist_ok=True)
    (pkg / "config").mkdir(exist_ok=True)
    (pkg / "package.xml").write_text(PKG)
    (pkg / "CMakeLists.txt").write_text(
        "project(demo)\ninstall(DIRECTORY launch config DESTINATION share/${PROJECT_NAME})\n")
    (pkg / "config" / "p.yaml").write_text(PARAMS)
    entry = pkg / "launch" / "a.launch.xml"
    entry.write_text(LAUNCH)
    opts = CheckOptions(paths=[str(entry)], launch_args=args, workspace=str(tmp_path))
    return {n["name"]: n for n in json.loads(api.graph(opts, str(entry), "json"))["nodes"]}


def test_substitutions_performed_and_typed(tmp_path):
    nodes = _graph(tmp_path, rate="2.5")
    assert nodes["subst"]["parameters"] == {"name": "fixed", "rate": 2.5, "use_external": False}
    assert nodes["subst"]["parameters_complete"] is True
    # without allow_substs the text stays as written (rcl reads strings)
    assert nodes["plain"]["parameters"]["rate"] == "$(var rate)"


def test_unknown_substitution_makes_the_file_unknown(tmp_path):
    nodes = _graph(tmp_path)  # rate has no default and is not given
    assert nodes["subst"]["parameters"] == {}
    assert nodes["subst"]["parameters_complete"] is False


def test_empty_or_directory_param_path_is_not_read_as_a_file(tmp_path):
    from physai_lint.engine import run_check

    pkg = tmp_path / "src" / "demo"
    (pkg / "launch").mkdir(parents=True)
    (pkg / "config").mkdir()
    (pkg / "package.xml").write_text(PKG)
    (pkg / "CMakeLists.txt").write_text(
        "project(demo)\ninstall(DIRECTORY launch config DESTINATION share/${PROJECT_NAME})\n")
    (pkg / "launch" / "a.launch.xml").write_text("""<launch>
  <arg name="cfg" default=""/>
  <node pkg="demo" exec="a" name="n1"><param from="$(var cfg)"/></node>
  <node pkg="demo" exec="a" name="n2"><param from="$(find-pkg-share demo)/config"/></node>
</launch>
""")
    report = run_check(CheckOptions(paths=[str(tmp_path / "src")], workspace=str(tmp_path)))
    codes = sorted(f.code for f in report.findings)
    assert "X002" not in codes  # the workspace root / config directory is never read as a file
    messages = sorted(f.message for f in report.findings if f.code == "P101")
    assert len(messages) == 2
    assert 'path "" is empty' in messages[0] and "is a directory" in messages[1]
