"""Byte-identical JSON and SARIF across runs, PYTHONHASHSEED values and file-system listing orders.
(``--jobs 1`` against ``--jobs N`` is covered with the parallel engine.)"""
from __future__ import annotations

import os
from pathlib import Path

import pytest
from hardening_helpers import package, run_cli, write

FILES: dict[str, str | bytes] = {
    "launch/a.launch.xml": '<launch><arg name="unused_a"/><arg name="z"/>\n'
                           '<node pkg="demo" exec="e" name="dup"/><node pkg="demo" exec="e" name="dup"/>\n'
                           '<include file="$(dirname)/b.launch.yaml"/></launch>\n',
    "launch/b.launch.yaml": "launch:\n- arg: {name: unused_b}\n- node: {pkg: demo, exec: e, name: 'bad name'}\n",
    "launch/c.launch.py": "from launch import LaunchDescription\nfrom launch_ros.actions import Node\n"
                          "def generate_launch_description():\n    return LaunchDescription([\n"
                          "        Node(package='demo', executable='e', name='n', parameters=[{'a': [1, 'x']}],\n"
                          "             remappings=[('t', 't')], bogus=1)])\n",
    "config/p.yaml": "n:\n  ros__parameters:\n    a: [1, 'x']\n    a: 2\n    s: {x: 1}\n",
    "config/q.yaml": "m:\n  ros__parameters:\n    b: [true, 1]\n",
}


def _outputs(ws: Path, tmp: Path, seed: str) -> dict[str, str]:
    out = {}
    for fmt in ("json", "sarif"):
        proc = run_cli(["check", ".", "--format", fmt], ws, tmp, PYTHONHASHSEED=seed)
        assert proc.returncode == 1, proc.stderr
        out[fmt] = proc.stdout
    return out


def test_identical_across_runs_and_hash_seeds(tmp_path: Path) -> None:
    ws = write(tmp_path / "ws", package("demo", FILES))
    first = _outputs(ws, tmp_path, "0")
    assert first["json"].count('"code"') >= 5  # a report with content, not an empty one
    for seed in ("0", "1", "4242", "random"):
        assert _outputs(ws, tmp_path, seed) == first, f"PYTHONHASHSEED={seed}"


def test_identical_regardless_of_creation_order(tmp_path: Path) -> None:
    import shutil

    files = package("demo", FILES)
    ws = write(tmp_path / "ws", dict(files.items()))
    forward = _outputs(ws, tmp_path, "0")
    shutil.rmtree(ws)  # same absolute path (SARIF records it), files created in the reverse order
    write(tmp_path / "ws", dict(reversed(list(files.items()))))
    assert _outputs(ws, tmp_path, "0") == forward


def test_identical_when_the_file_system_lists_in_reverse(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    from physai_lint.catalog import load_catalog
    from physai_lint.engine import CheckOptions, run_check
    from physai_lint.report import render

    ws = write(tmp_path / "ws", package("demo", FILES))
    catalog = load_catalog()

    def report() -> tuple[str, str]:
        r = run_check(CheckOptions(paths=["."], cache=False), cwd=str(ws))
        r.duration_s = 0.0
        return render("json", r, catalog), render("sarif", r, catalog)

    plain = report()
    real_scandir, real_listdir = os.scandir, os.listdir

    class Reversed:
        def __init__(self, path: object = ".") -> None:
            self.entries = list(reversed(list(real_scandir(path))))  # type: ignore[call-overload]

        def __iter__(self):  # type: ignore[no-untyped-def]
            return iter(self.entries)

        def __enter__(self):  # type: ignore[no-untyped-def]
            return iter(self.entries)

        def __exit__(self, *exc: object) -> None:
            return None

    monkeypatch.setattr(os, "scandir", Reversed)
    monkeypatch.setattr(os, "listdir", lambda path=".": list(reversed(real_listdir(path))))
    assert report() == plain
