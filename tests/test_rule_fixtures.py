"""Every rule's fixture folder: ``tests/rules/<CODE>-<name>/{bad,good}/`` are tiny workspaces.

``bad/expected.json`` lists findings ``{code, file, line}`` that must be reported (other findings
are allowed); ``good/`` must not report the folder's code. Neither may report X003 (a crash).
Optional per case: ``args.txt`` (``NAME:=VALUE`` per line), ``distro.txt`` (default humble), ``interfaces.yaml``, ``entry.txt``
(the launch file, relative to the case dir; default: the first launch file under ``src/``).
A folder with ``xfail.txt`` documents a known rule bug: the test is a strict xfail with its reason.
"""
from __future__ import annotations

import json
import os
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from physai_lint.engine import CheckOptions, run_check  # noqa: E402
from physai_lint.workspace import is_launch_file  # noqa: E402

RULES = ROOT / "tests" / "rules"
FOLDERS = sorted(p for p in RULES.iterdir() if p.is_dir()) if RULES.is_dir() else []


def entry_of(case: Path) -> str:
    given = case / "entry.txt"
    if given.is_file():
        return given.read_text(encoding="utf-8").strip()
    found = sorted(p.relative_to(case).as_posix() for p in (case / "src").rglob("*") if p.is_file()
                   and is_launch_file(str(p)))
    assert found, f"{case}: no launch file under src/ and no entry.txt"
    return found[0]


def read_args(case: Path) -> dict[str, str]:
    path = case / "args.txt"
    if not path.is_file():
        return {}
    args = {}
    for line in path.read_text(encoding="utf-8").splitlines():
        if line.strip() and not line.lstrip().startswith("#"):
            name, _, value = line.strip().partition(":=")
            args[name] = value
    return args


def lint(case: Path) -> list[tuple[str, str, int, str]]:
    """(code, file relative to the case, line, message) of every finding."""
    interfaces = ["interfaces.yaml"] if (case / "interfaces.yaml").is_file() else []
    distro = (case / "distro.txt").read_text(encoding="utf-8").strip() if (case / "distro.txt").is_file() \
        else "humble"
    opts = CheckOptions(paths=[entry_of(case)], launch_args=read_args(case), workspace=".",
                        distro=distro, interfaces=interfaces, cache=False)
    report = run_check(opts, cwd=str(case))
    out = []
    for f in report.findings:
        rel = os.path.relpath(f.span.file, case).replace(os.sep, "/")
        out.append((f.code, rel, f.span.line, f.message))
    return out


@pytest.fixture(autouse=True)
def _no_ament(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv("AMENT_PREFIX_PATH", raising=False)


@pytest.mark.parametrize("folder", FOLDERS, ids=[p.name for p in FOLDERS])
def test_rule_fixture(folder: Path, request: pytest.FixtureRequest) -> None:
    code = folder.name.split("-", 1)[0]
    xfail = folder / "xfail.txt"
    if xfail.is_file():
        request.applymarker(pytest.mark.xfail(reason=xfail.read_text(encoding="utf-8").strip(), strict=True))
    bad, good = folder / "bad", folder / "good"
    assert bad.is_dir() and good.is_dir(), f"{folder.name} needs bad/ and good/"
    expected = json.loads((bad / "expected.json").read_text(encoding="utf-8"))
    assert expected and all(e["code"] == code for e in expected), "expected.json lists the folder's code"

    bad_found = lint(bad)
    got = {(c, f, ln) for c, f, ln, _ in bad_found}
    missing = [e for e in expected if (e["code"], e["file"], e["line"]) not in got]
    assert not missing, f"bad/: expected {missing}, got {sorted(got)}"
    assert not [x for x in bad_found if x[0] == "X003"], f"bad/: internal error {bad_found}"

    good_found = lint(good)
    assert not [x for x in good_found if x[0] == "X003"], f"good/: internal error {good_found}"
    wrong = [x for x in good_found if x[0] == code]
    assert not wrong, f"good/: {code} reported: {wrong}"
