"""Fixture tests for the launch-structure and dependency rules (L001, L002, L108-L114, U103, U104).

Each ``tests/rules/<CODE>-<name>/`` holds a ``bad/`` and a ``good/`` workspace: every finding of
``bad/expected.json`` must be reported, and the rule's code must not be reported in ``good/``.
"""
from __future__ import annotations

import json
import os
from pathlib import Path

import pytest

from physai_lint.engine import CheckOptions, run_check

RULES_DIR = Path(__file__).parent / "rules"
CODES = ("L001", "L002", "L108", "L109", "L110", "L111", "L112", "L113", "L114", "U103", "U104")


def _cases() -> list[Path]:
    return sorted(d for d in RULES_DIR.iterdir() if d.is_dir() and d.name.split("-", 1)[0] in CODES)


def _entry(case: Path) -> str:
    launch = sorted(p for p in (case / "src").rglob("*")
                    if p.is_file() and "/launch/" in p.as_posix()
                    and p.name.endswith((".launch.py", ".launch.xml", ".launch.yaml", ".py", ".xml", ".yaml")))
    assert launch, f"no launch file under {case}/src"
    return str(launch[0])


def _args(case: Path) -> dict[str, str]:
    path = case / "args.txt"
    if not path.exists():
        return {}
    out = {}
    for line in path.read_text().splitlines():
        if ":=" in line:
            k, v = line.strip().split(":=", 1)
            out[k] = v
    return out


def _run(case: Path) -> list[tuple[str, str, int]]:
    interfaces = [str(case / "interfaces.yaml")] if (case / "interfaces.yaml").exists() else []
    report = run_check(CheckOptions(paths=[_entry(case)], workspace=str(case), launch_args=_args(case),
                                    interfaces=interfaces), cwd=str(case))
    out = []
    for f in report.findings:
        rel = os.path.relpath(f.span.file, case).replace(os.sep, "/")
        out.append((f.code, rel, f.span.line))
    return out


def test_every_rule_has_a_case() -> None:
    names = {d.name.split("-", 1)[0] for d in _cases()}
    assert set(CODES) <= names, f"missing fixture folders for {sorted(set(CODES) - names)}"


@pytest.mark.parametrize("case", _cases(), ids=lambda d: d.name)
def test_bad_reports_expected(case: Path) -> None:
    bad = case / "bad"
    expected = json.loads((bad / "expected.json").read_text())
    assert expected, "bad/expected.json lists no finding"
    got = _run(bad)
    for exp in expected:
        key = (exp["code"], exp["file"], exp["line"])
        assert key in got, f"{key} not reported; got {got}"


@pytest.mark.parametrize("case", _cases(), ids=lambda d: d.name)
def test_good_is_quiet(case: Path) -> None:
    code = case.name.split("-", 1)[0]
    got = _run(case / "good")
    assert not [g for g in got if g[0] == code], got


@pytest.mark.parametrize("name, text", [
    ("a.launch.yaml", ("launch:\n- node:\n    pkg: demo_nodes_cpp\n    exec: talker\n"
                       '    args: "--dir $(launch_log_dir) --old $(log_dir)"\n')),
    ("a.launch.py", ("from launch import LaunchDescription\nfrom launch.substitutions import LaunchLogDir\n"
                     "from launch_ros.actions import Node\n\n\ndef generate_launch_description():\n"
                     "    return LaunchDescription([\n"
                     "        Node(package='demo_nodes_cpp', executable='talker', arguments=[LaunchLogDir()]),\n"
                     "    ])\n")),
])
def test_launch_log_dir_is_newer_than_humble_and_log_dir_is_not(tmp_path: Path, name: str, text: str) -> None:
    """``$(launch_log_dir)`` / ``LaunchLogDir`` came with iron; humble exposes only ``log_dir``."""
    path = tmp_path / name
    path.write_text(text)
    found = {}
    for distro in ("humble", "jazzy"):
        report = run_check(CheckOptions(paths=[str(path)], distro=distro, cache=False), cwd=str(tmp_path))
        found[distro] = [(f.span.line, f.message, f.help) for f in report.findings if f.code == "L114"]
    assert found["jazzy"] == []
    assert len(found["humble"]) == 1
    line, message, help_ = found["humble"][0]
    assert "(added in iron)" in message
    if name.endswith(".yaml"):
        assert line == 5 and '"$(launch_log_dir)"' in message and "$(log_dir)" in help_
    else:
        assert line == 8 and message.startswith("LaunchLogDir does not exist in launch on humble")
