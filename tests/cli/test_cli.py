"""The command line end to end, in a subprocess, against a stand-in engine (see fake_run.py)."""
from __future__ import annotations

import json
import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest
from cli_helpers import REPO, one_error_line, run


@pytest.fixture()
def ws(tmp_path: Path) -> Path:
    launch = tmp_path / "src" / "demo" / "launch"
    launch.mkdir(parents=True)
    (launch / "bad.launch.py").write_text("from launch import LaunchDescription\nx = 'BAD'\n")
    (launch / "warn.launch.py").write_text("y = 'WARN'\n")
    (launch / "good.launch.py").write_text("z = 1\n")
    return tmp_path


def test_version_is_fast_and_light(tmp_path: Path) -> None:
    proc = run(["--version"], tmp_path, fake=False)
    assert proc.returncode == 0 and proc.stdout.startswith("physai-lint ")
    code = (
        "import sys; from physai_lint.cli import main; main(['--version']);"
        "heavy = {'rich', 'jsonschema', 'libcst', 'networkx', 'yaml', 'typer', 'click'};"
        "print(sorted(m for m in sys.modules if m.split('.')[0] in heavy))"
    )
    out = subprocess.run([sys.executable, "-c", code], cwd=REPO, capture_output=True, text=True, check=True)
    assert out.stdout.strip().splitlines()[-1] == "[]"


def test_help_lists_subcommands(tmp_path: Path) -> None:
    proc = run(["--help"], tmp_path, fake=False)
    assert proc.returncode == 0
    for sub in ("check", "graph", "plan", "params", "rules", "rule"):
        assert sub in proc.stdout
    assert "--fail-on" in run(["check", "--help"], tmp_path, fake=False).stdout


def test_bad_option_is_one_line(ws: Path) -> None:
    line = one_error_line(run(["src", "--bogus"], ws))
    assert "--bogus" in line


def test_bad_option_value_is_one_line(ws: Path) -> None:
    assert '"yaml"' in one_error_line(run(["src", "--format", "yaml"], ws))
    assert '"galactic"' in one_error_line(run(["src", "--distro", "galactic"], ws))
    assert "--jobs" in one_error_line(run(["src", "--jobs", "many"], ws))


def test_missing_path_is_one_line(ws: Path) -> None:
    assert 'path "nope.launch.py" does not exist' in one_error_line(run(["nope.launch.py"], ws, fake=False))


def test_no_paths(ws: Path) -> None:
    assert "no paths" in one_error_line(run(["check"], ws))


def test_default_command_is_check_and_exit_codes(ws: Path) -> None:
    proc = run(["src/demo/launch/bad.launch.py"], ws)
    assert proc.returncode == 1, proc.stderr
    assert "src/demo/launch/bad.launch.py:2:6: N101 [duplicate-node-name] flagged \"BAD\"" in proc.stdout
    assert "Found 1 error, 0 warnings in 1 file." in proc.stdout
    assert run(["check", "src/demo/launch/good.launch.py"], ws).stdout.strip() == "All checks passed! (1 file)"
    assert run(["src/demo/launch/good.launch.py"], ws).returncode == 0
    assert run(["src", "--exit-zero"], ws).returncode == 0
    assert run(["src/demo/launch/warn.launch.py"], ws).returncode == 0
    assert run(["src/demo/launch/warn.launch.py", "--fail-on", "warning"], ws).returncode == 1


def test_options_reach_the_engine(ws: Path) -> None:
    record = ws / "opts.json"
    proc = run(
        ["--format", "json", "src", "robot:=r1", "--select", "N,P101", "--ignore", "N101", "--distro", "jazzy",
         "--jobs", "2", "--no-cache", "--no-respect-gitignore", "--strict"],
        ws, env={"FAKE_RECORD": str(record)},
    )
    assert proc.returncode in (0, 1), proc.stderr
    opts = json.loads(record.read_text())
    assert opts["paths"] == [str(ws / "src")]
    assert opts["launch_args"] == {"robot": "r1"}
    assert opts["select"] == ["N", "P101"] and opts["ignore"] == ["N101"]
    assert (opts["distro"], opts["jobs"], opts["cache"], opts["respect_gitignore"], opts["strict"]) == ("jazzy", 2, False, False, True)


def test_unknown_selector_is_one_line(ws: Path) -> None:
    assert '"Q999"' in one_error_line(run(["src", "--select", "Q999"], ws))
    assert 'did you mean "duplicate-node-name"' in one_error_line(run(["src", "--ignore", "duplicate-node-nam"], ws))


def test_json_sarif_and_output_file(ws: Path) -> None:
    doc = json.loads(run(["src", "--format", "json"], ws).stdout)
    assert doc["format"] == "physai-lint-report"
    assert [(f["code"], f["file"]) for f in doc["findings"]] == [
        ("N101", "src/demo/launch/bad.launch.py"), ("P101", "src/demo/launch/warn.launch.py")]
    proc = run(["src", "--format", "sarif", "--output", "out.sarif"], ws)
    assert proc.returncode == 1 and proc.stdout == ""
    sarif = json.loads((ws / "out.sarif").read_text())
    assert [r["ruleId"] for r in sarif["runs"][0]["results"]] == ["N101", "P101"]


def test_xunit_file(ws: Path) -> None:
    proc = run(["src", "--xunit-file", "build/x.xml"], ws)  # colcon's result folder may not exist yet
    assert proc.returncode == 1
    suite = ET.parse(ws / "build" / "x.xml").getroot().find("testsuite")
    assert suite is not None and suite.get("tests") == "3" and suite.get("failures") == "1"


def test_colour(ws: Path) -> None:
    assert "\x1b[" not in run(["src"], ws).stdout  # not a TTY
    assert "\x1b[" in run(["src"], ws, env={"FORCE_COLOR": "1"}).stdout
    assert "\x1b[" not in run(["src"], ws, env={"FORCE_COLOR": "1", "NO_COLOR": "1"}).stdout


def test_statistics_and_quiet(ws: Path) -> None:
    out = run(["src", "--statistics"], ws).stdout
    assert "N101" in out and "duplicate-node-name" in out and "flagged" not in out
    quiet = run(["src", "--quiet", "--no-show-source"], ws).stdout
    assert "Found" not in quiet and "N101" in quiet and " | " not in quiet


def test_internal_error_is_one_line(ws: Path) -> None:
    line = one_error_line(run(["src"], ws, env={"FAKE_CRASH": "1"}))
    assert line == "error: internal error: RuntimeError: boom (please report)"


def test_config_discovery_and_cli_precedence(ws: Path) -> None:
    (ws / "physai-lint.toml").write_text('select = ["P"]\nignore = ["N101"]\ndistro = "jazzy"\nfail-on = "warning"\n')
    record = ws / "opts.json"
    sub = ws / "src" / "demo"
    proc = run(["launch"], sub, env={"FAKE_RECORD": str(record)})
    opts = json.loads(record.read_text())
    assert (opts["select"], opts["ignore"], opts["distro"], opts["fail_on"]) == (["P"], ["N101"], "jazzy", "warning")
    assert proc.returncode == 1  # fail-on = warning from the file
    run(["launch", "--select", "N", "--ignore", "P101", "--fail-on", "error"], sub, env={"FAKE_RECORD": str(record)})
    opts = json.loads(record.read_text())
    assert (opts["select"], opts["ignore"], opts["fail_on"]) == (["N"], ["N101", "P101"], "error")


def test_invalid_config_names_file_and_key(ws: Path) -> None:
    (ws / "pyproject.toml").write_text('[tool.physai-lint]\nfail-on = "sometimes"\n')
    line = one_error_line(run(["src"], ws))
    assert "pyproject.toml" in line and "tool.physai-lint.fail-on" in line and "sometimes" in line
    (ws / "pyproject.toml").write_text('[tool.physai-lint]\nselct = ["N"]\n')
    assert 'did you mean "tool.physai-lint.select"' in one_error_line(run(["src"], ws))
    (ws / "pyproject.toml").write_text("[tool.physai-lint\n")
    assert "invalid TOML" in one_error_line(run(["src"], ws))


def test_rule_options_validated_against_catalog(ws: Path) -> None:
    (ws / "physai-lint.toml").write_text('[rules.parameter-file-missing]\nallow-unresolved = "yes"\n')
    line = one_error_line(run(["src"], ws))
    assert "physai-lint.toml" in line and "rules.parameter-file-missing.allow-unresolved" in line


def test_severity_override_from_config(ws: Path) -> None:
    (ws / "physai-lint.toml").write_text('[severity]\nN101 = "note"\n')
    proc = run(["src"], ws)
    assert proc.returncode == 0 and "Found 0 errors, 1 warning (1 note) in 3 files." in proc.stdout


def test_baseline_errors(ws: Path) -> None:
    assert "does not exist" in one_error_line(run(["src", "--baseline", "none.json"], ws))


def test_rules_and_rule(ws: Path) -> None:
    table = run(["rules"], ws, fake=False)
    assert table.returncode == 0
    assert [line.split()[0] for line in table.stdout.splitlines()[1:]] == ["N101", "P101", "X004"]
    listing = json.loads(run(["rules", "--format", "json"], ws, fake=False).stdout)
    assert listing["rules"][1]["options"]["properties"]["allow-unresolved"]["default"] is False
    md = run(["rules", "--format", "markdown"], ws, fake=False).stdout
    assert '<a id="n101"></a>' in md and "#### What it does" in md
    doc = run(["rule", "duplicate-node-name"], ws, fake=False)
    assert doc.returncode == 0 and doc.stdout.startswith("# duplicate-node-name (N101)") and "## Use instead" in doc.stdout
    assert run(["rule", "n101"], ws, fake=False).stdout == doc.stdout
    assert 'did you mean "N101"' in one_error_line(run(["rule", "N1O1"], ws, fake=False))


def test_api_subcommands(ws: Path) -> None:
    proc = run(["graph", "src/demo/launch/good.launch.py", "robot:=r1", "--format", "dot"], ws)
    assert proc.returncode == 0 and proc.stdout == 'graph good.launch.py dot {"robot": "r1"}\n'
    assert "not available" in one_error_line(run(["plan", "src/demo/launch/good.launch.py"], ws))
    assert "exactly one launch file" in one_error_line(run(["graph", "a", "b"], ws))
    assert '"svg"' in one_error_line(run(["graph", "src/demo/launch/good.launch.py", "--format", "svg"], ws))
