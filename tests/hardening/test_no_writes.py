"""A run writes nothing but --output, the baseline when asked, and its cache directory; a read-only
workspace works. The cache is pointed into tmp_path and HOME at an empty folder that must stay empty."""
from __future__ import annotations

import os
import stat
from pathlib import Path

import pytest
from hardening_helpers import package, run_cli, write

FILES: dict[str, str | bytes] = {
    "launch/a.launch.xml": '<launch><arg name="unused"/><node pkg="demo" exec="e" name="n">'
                           '<param from="$(dirname)/../config/p.yaml"/></node></launch>\n',
    "launch/b.launch.py": "from launch import LaunchDescription\nfrom launch_ros.actions import Node\n"
                          "def generate_launch_description():\n"
                          "    return LaunchDescription([Node(package='demo', executable='e', name='m')])\n",
    "config/p.yaml": "n:\n  ros__parameters:\n    a: [1, 'x']\n",
}


def _snapshot(root: Path) -> dict[str, tuple[int, int, int]]:
    out = {}
    for dirpath, dirnames, filenames in os.walk(root):
        for name in dirnames + filenames:
            p = Path(dirpath) / name
            st = p.lstat()
            out[str(p.relative_to(root))] = (st.st_mtime_ns, st.st_size, st.st_mode)
    return out


COMMANDS = [
    ["check", "."], ["check", ".", "--format", "sarif"], ["check", "src/demo/launch/a.launch.xml"],
    ["graph", "src/demo/launch/a.launch.xml", "--format", "json"], ["plan", "src/demo/launch/b.launch.py"],
    ["params", "src/demo/launch/a.launch.xml"],
]


def test_runs_write_nothing_unasked(tmp_path: Path) -> None:
    ws = write(tmp_path / "ws", package("demo", FILES))
    home = tmp_path / "home"
    home.mkdir()
    before = _snapshot(ws)
    for args in COMMANDS:
        proc = run_cli(args, ws, tmp_path, HOME=str(home))
        assert proc.returncode in (0, 1), (args, proc.stderr)
    assert _snapshot(ws) == before
    assert list(home.iterdir()) == []


def test_only_the_output_and_baseline_files_appear(tmp_path: Path) -> None:
    ws = write(tmp_path / "ws", package("demo", FILES))
    before = _snapshot(ws)
    proc = run_cli(["check", ".", "--format", "json", "--output", "report.json", "--write-baseline", "base.json"],
                   ws, tmp_path, HOME=str(tmp_path))
    assert proc.returncode == 0, proc.stderr
    after = _snapshot(ws)
    assert set(after) - set(before) == {"report.json", "base.json"}
    assert {k: v for k, v in after.items() if k in before} == before
    proc = run_cli(["check", ".", "--baseline", "base.json"], ws, tmp_path, HOME=str(tmp_path))
    assert proc.returncode == 0, proc.stderr
    assert _snapshot(ws) == after  # reading a baseline does not rewrite it


def test_read_only_workspace(tmp_path: Path) -> None:
    ws = write(tmp_path / "ws", package("demo", FILES))
    modes = {}
    for dirpath, dirnames, filenames in os.walk(ws, topdown=False):
        for name in dirnames + filenames + [""]:
            p = Path(dirpath) / name
            modes[p] = p.stat().st_mode
            p.chmod(stat.S_IMODE(modes[p]) & ~0o222)
    try:
        before = _snapshot(ws)
        for args in COMMANDS:
            proc = run_cli(args, ws, tmp_path, HOME=str(tmp_path / "nohome"))
            assert proc.returncode in (0, 1), (args, proc.stderr)
            assert "error" not in proc.stderr.lower(), proc.stderr
        assert _snapshot(ws) == before
    finally:
        for p, mode in modes.items():
            p.chmod(stat.S_IMODE(mode))
    if os.geteuid() == 0:
        pytest.skip("ran, but as root a read-only mode does not stop writes: the snapshot is the proof")
