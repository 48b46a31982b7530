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
