"""Workspace parameter files loaded with allow_substs: launch_ros performs their $(...) first."""
from physai_lint.engine import CheckOptions

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


FILES = {"config/p.yaml": PARAMS, "launch/a.launch.xml": LAUNCH}


def test_substitutions_performed_and_typed(demo_graph):
    nodes = demo_graph(FILES, "launch/a.launch.xml", rate="2.5")
    assert nodes["subst"]["parameters"] == {"name": "fixed", "rate": 2.5, "use_external": False}
    assert nodes["subst"]["parameters_complete"] is True
    # without allow_substs the text stays as written (rcl reads strings)
    assert nodes["plain"]["parameters"]["rate"] == "$(var rate)"


def test_unknown_substitution_makes_the_file_unknown(demo_graph):
    nodes = demo_graph(FILES, "launch/a.launch.xml")  # rate has no default and is not given
    assert nodes["subst"]["parameters"] == {}
    assert nodes["subst"]["parameters_complete"] is False


def test_empty_or_directory_param_path_is_not_read_as_a_file(tmp_path, demo_package):
    from physai_lint.engine import run_check

    pkg = demo_package({"launch/a.launch.xml": """<launch>
  <arg name="cfg" default=""/>
  <node pkg="demo" exec="a" name="n1"><param from="$(var cfg)"/></node>
  <node pkg="demo" exec="a" name="n2"><param from="$(find-pkg-share demo)/config"/></node>
</launch>
"""})
    (pkg / "config").mkdir()
    report = run_check(CheckOptions(paths=[str(tmp_path / "src")], workspace=str(tmp_path)))
    codes = sorted(f.code for f in report.findings)
    assert "X002" not in codes  # the workspace root / config directory is never read as a file
    messages = sorted(f.message for f in report.findings if f.code == "P101")
    assert len(messages) == 2
    assert 'path "" is empty' in messages[0] and "is a directory" in messages[1]


def test_an_undeclared_configuration_read_in_the_file_is_l101(demo_findings):
    # ParameterFile.evaluate performs the file's $(var robot) while launch runs: a configuration
    # nothing declares raises SubstitutionFailure there, reported in the YAML file (the file's
    # values are unknown then, and it was left out of the files whose findings are reported)
    launch = LAUNCH.replace('<arg name="rate"/>', '<arg name="rate" default="1.0"/>')
    launch = launch[:launch.index('  <node pkg="demo" exec="a" name="plain">')] + "</launch>\n"
    files = {"config/p.yaml": PARAMS + "    frame: $(var robot)/base_link\n", "launch/a.launch.xml": launch}
    found = demo_findings(files, "launch/a.launch.xml", "L101")
    assert [(line, message.split(";")[0]) for line, message in found] == [
        (6, 'launch configuration "robot" is read but never declared or set')]  # p.yaml:6
