"""A fixed report (two files, every severity, related locations, a fix) for reporter snapshots."""
from __future__ import annotations

import os
from dataclasses import dataclass, field
from pathlib import Path

import sys
from pathlib import Path as _Path

sys.path.insert(0, str(_Path(__file__).resolve().parents[2]))  # tests run without an install

from physai_lint.catalog import load_catalog  # noqa: E402
from physai_lint.model.findings import Finding, Fix, Related
from physai_lint.model.span import Span

FIXTURE_RULES = Path(__file__).resolve().parents[1] / "cli" / "fixtures" / "rules"
SNAPSHOTS = Path(__file__).resolve().parent / "snapshots"
CWD = "/ws"
A = "/ws/src/demo/launch/bringup.launch.py"
B = "/ws/src/demo/config/params.yaml"
SOURCES = {
    A: 'from launch_ros.actions import Node\n\nNode(package="demo", name="talker")\nNode(package="demo", name="talker")\n',
    B: "talker:\n  ros__parameters:\n\trate: 10  # comma, colon: 100%\n",
}


@dataclass
class FakeReport:
    findings: list[Finding]
    files: list[str]
    cwd: str = CWD
    duration_s: float = 0.25
    baseline_suppressed: int = 0
    extra: dict = field(default_factory=dict)


def sample_report() -> FakeReport:
    dup = Finding(
        "N101", "duplicate-node-name", "error", Span(A, 4, 26, 4, 34), 'duplicate node name "/talker"',
        "give one of the nodes another name", (Related(Span(A, 3, 26, 3, 34), "first defined here"),), "/talker",
        Fix(Span(A, 4, 27, 4, 33), "talker2", "rename the second node"),
    )
    missing = Finding(
        "P101", "parameter-file-missing", "warning", Span(B, 3, 2, 3, 6), 'parameter "rate": 100%, not found,\nreally',
        None, (), "rate",
    )
    unused = Finding("X004", "unused-suppression", "note", Span(A, 1, 1, 1, 5), 'unused suppression for "N101"', "remove it", (), "u")
    return FakeReport([missing, dup, unused], [A, B, "/ws/src/demo/launch/other.launch.py"], baseline_suppressed=2)


def catalog():  # type: ignore[no-untyped-def]
    return load_catalog(FIXTURE_RULES)


def check_snapshot(name: str, text: str) -> None:
    path = SNAPSHOTS / name
    if os.environ.get("UPDATE_SNAPSHOTS") or not path.exists():
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text, encoding="utf-8")
        if not os.environ.get("UPDATE_SNAPSHOTS"):
            raise AssertionError(f"snapshot {name} was missing and has been written; re-run")
    assert text == path.read_text(encoding="utf-8"), f"snapshot {name} differs (UPDATE_SNAPSHOTS=1 to accept)"
