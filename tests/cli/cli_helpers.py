"""Helpers for CLI tests: run the command line in a subprocess."""
from __future__ import annotations

import os
import subprocess
import sys

sys.path.insert(0, str(__import__("pathlib").Path(__file__).resolve().parents[2]))  # tests run without an install
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]
FIXTURE_RULES = Path(__file__).resolve().parent / "fixtures" / "rules"
FAKE_RUN = Path(__file__).resolve().parent / "fake_run.py"


def run(args: list[str], cwd: Path, *, fake: bool = True, env: dict[str, str] | None = None) -> subprocess.CompletedProcess[str]:
    full_env = {k: v for k, v in os.environ.items() if k not in ("NO_COLOR", "FORCE_COLOR", "PHYSAI_LINT_TRACEBACK")}
    full_env.update({"PYTHONPATH": str(REPO), "PHYSAI_LINT_RULES_DIR": str(FIXTURE_RULES), "COLUMNS": "100"})
    full_env.update(env or {})
    cmd = [sys.executable, str(FAKE_RUN), *args] if fake else [sys.executable, "-m", "physai_lint", *args]
    return subprocess.run(cmd, cwd=cwd, env=full_env, capture_output=True, text=True, timeout=60)


def one_error_line(proc: subprocess.CompletedProcess[str]) -> str:
    """Assert the process failed the way users should see: exit 2, one ``error:`` line, nothing else."""
    assert proc.returncode == 2, (proc.returncode, proc.stdout, proc.stderr)
    lines = proc.stderr.splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: "), proc.stderr
    assert "Traceback" not in proc.stderr and proc.stdout == ""
    return lines[0]
