"""The ``physai-lint`` command leaves with ``os._exit`` once ``main`` returns (cli.entry): the
report is complete, the exit code is main's, and no interpreter teardown runs."""
from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def test_the_module_entry_writes_the_whole_report_and_keeps_the_exit_code(tmp_path: Path) -> None:
    out = tmp_path / "report.json"
    done = subprocess.run([sys.executable, "-m", "physai_lint", "check", str(EXAMPLES / "buggy_ws"),
                           "--format", "json", "-o", str(out), "--no-cache"],
                          capture_output=True, text=True, timeout=120)
    assert done.returncode == 1, done.stderr
    report = json.loads(out.read_text())
    assert report["findings"]


def test_entry_skips_the_teardown_but_flushes_stdout(tmp_path: Path) -> None:
    mark = tmp_path / "atexit-ran"
    code = ("import atexit, sys\n"
            f"atexit.register(lambda: open({str(mark)!r}, 'w').close())\n"
            "sys.argv = ['physai-lint', '--version']\n"
            "from physai_lint.cli import entry\n"
            "entry()\n")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=60)
    assert done.returncode == 0
    assert done.stdout.startswith("physai-lint ")  # buffered output (a pipe) was flushed
    assert not mark.exists()  # left with os._exit: no atexit handlers, no teardown
