"""A rule or frontend that raises becomes an X003 finding naming the file and asking for a report;
the run goes on (other files and rules still report) and the exit code says so."""
from __future__ import annotations

import os
from pathlib import Path

import pytest
from hardening_helpers import package, write

from physai_lint.engine import CheckOptions, exit_code, run_check

FILES: dict[str, str | bytes] = {
    "launch/a.launch.xml": '<launch><arg name="unused_xml"/></launch>\n',
    "launch/b.launch.yaml": "launch:\n- arg: {name: unused_yaml}\n",
    "launch/c.launch.py": "from launch import LaunchDescription\nfrom launch.actions import DeclareLaunchArgument\n"
                          "def generate_launch_description():\n"
                          "    return LaunchDescription([DeclareLaunchArgument('unused_py')])\n",
}


@pytest.fixture()
def ws(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    monkeypatch.delenv("AMENT_PREFIX_PATH", raising=False)
    return write(tmp_path / "ws", package("demo", FILES))


def _found(ws: Path) -> tuple[set[tuple[str, str]], list, int]:  # type: ignore[type-arg]
    report = run_check(CheckOptions(paths=["."], cache=False, jobs=1), cwd=str(ws))
    got = {(f.code, os.path.relpath(f.span.file, ws)) for f in report.findings}
    return got, [f for f in report.findings if f.code == "X003"], exit_code(report, "error")


def test_frontend_crash_is_x003_on_that_file(ws: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    import physai_lint.frontends.yaml_launch as yl

    def boom(path: str, text: str) -> object:
        raise ZeroDivisionError("boom in the yaml frontend")

    monkeypatch.setattr(yl, "parse_yaml_launch", boom)
    got, crashes, code = _found(ws)
    assert [os.path.relpath(c.span.file, ws) for c in crashes] == ["src/demo/launch/b.launch.yaml"]
    assert "ZeroDivisionError" in crashes[0].message and "report" in (crashes[0].help or "")
    assert ("L102", "src/demo/launch/a.launch.xml") in got and ("L102", "src/demo/launch/c.launch.py") in got
    assert code == 1


def test_rule_crash_is_x003_and_other_rules_still_report(ws: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    from physai_lint.checks.base import load_all

    rules = load_all()
    victim = next(code for code in sorted(rules) if code != "L102")

    def boom(ctx: object) -> list[object]:
        raise KeyError("boom in a rule")

    import dataclasses

    monkeypatch.setitem(rules, victim, dataclasses.replace(rules[victim], func=boom))
    got, crashes, code = _found(ws)
    assert len(crashes) == 1 and f"rule {victim}" in crashes[0].message and "KeyError" in crashes[0].message
    assert crashes[0].span.file.startswith(str(ws))  # names a file of the run
    assert "report" in (crashes[0].help or "")
    assert {("L102", f"src/demo/launch/{n}") for n in ("a.launch.xml", "b.launch.yaml", "c.launch.py")} <= got
    assert code == 1


def test_parameter_loader_crash_is_x003(ws: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    import physai_lint.params.loader as loader

    write(ws, {"src/demo/config/p.yaml": "n:\n  ros__parameters:\n    a: 1\n"})

    def boom(path: str, text: str, distro: str = "humble") -> object:
        raise RuntimeError("boom in the parameter loader")

    monkeypatch.setattr(loader, "load_param_file", boom)
    got, crashes, code = _found(ws)
    assert [os.path.relpath(c.span.file, ws) for c in crashes] == ["src/demo/config/p.yaml"]
    assert ("L102", "src/demo/launch/a.launch.xml") in got
    assert code == 1
