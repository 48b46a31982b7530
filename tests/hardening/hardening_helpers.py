"""Shared helpers for the hardening tests: tiny workspaces written into tmp_path and the real CLI in a
subprocess, with the cache pointed into tmp_path so no run touches $HOME."""
from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(REPO))

PACKAGE_XML = """<?xml version="1.0"?>
<package format="3">
  <name>{name}</name>
  <version>0.1.0</version>
  <description>{name} package</description>
  <maintainer email="dev@example.com">Robot Team</maintainer>
  <license>Apache-2.0</license>
  <buildtool_depend>ament_cmake</buildtool_depend>
  <export><build_type>ament_cmake</build_type></export>
</package>
"""

CMAKE = """cmake_minimum_required(VERSION 3.8)
project({name})
find_package(ament_cmake REQUIRED)
install(DIRECTORY launch config DESTINATION share/${{PROJECT_NAME}})
ament_package()
"""


def write(root: Path, files: dict[str, str | bytes]) -> Path:
    """Write ``{relative path: text or bytes}`` under ``root``; returns ``root``."""
    for rel, content in files.items():
        path = root / rel
        path.parent.mkdir(parents=True, exist_ok=True)
        if isinstance(content, bytes):
            path.write_bytes(content)
        else:
            path.write_text(content, encoding="utf-8")
    return root


def package(name: str = "demo", files: dict[str, str | bytes] | None = None) -> dict[str, str | bytes]:
    """The files of a minimal ament_cmake package ``src/<name>`` plus ``files`` (relative to it)."""
    out: dict[str, str | bytes] = {
        f"src/{name}/package.xml": PACKAGE_XML.format(name=name),
        f"src/{name}/CMakeLists.txt": CMAKE.format(name=name),
    }
    for rel, content in (files or {}).items():
        out[f"src/{name}/{rel}"] = content
    return out


def cli_env(tmp: Path, **extra: str) -> dict[str, str]:
    env = {k: v for k, v in os.environ.items()
           if k not in ("NO_COLOR", "FORCE_COLOR", "PHYSAI_LINT_TRACEBACK", "AMENT_PREFIX_PATH",
                        "PHYSAI_LINT_RULES_DIR")}
    cache = tmp / "_cache"
    env.update({"PYTHONPATH": str(REPO), "COLUMNS": "100", "PHYSAI_LINT_CACHE_DIR": str(cache),
                "XDG_CACHE_HOME": str(cache)})
    env.update(extra)
    return env


def run_cli(args: list[str], cwd: Path, tmp: Path, *, timeout: float = 120,
            **env: str) -> subprocess.CompletedProcess[str]:
    """``python -m physai_lint ARGS`` in ``cwd``; the cache lives under ``tmp/_cache``."""
    return subprocess.run([sys.executable, "-m", "physai_lint", *args], cwd=cwd, env=cli_env(tmp, **env),
                          capture_output=True, text=True, timeout=timeout)


def assert_no_traceback(proc: subprocess.CompletedProcess[str]) -> None:
    """Exit 0/1 with a report, or exit 2 with one ``error:`` line; never a traceback."""
    assert "Traceback" not in proc.stderr and "Traceback" not in proc.stdout, proc.stderr[-3000:]
    assert proc.returncode in (0, 1, 2), (proc.returncode, proc.stderr[-3000:])
    if proc.returncode == 2:
        lines = proc.stderr.splitlines()
        assert len(lines) == 1 and lines[0].startswith("error: "), proc.stderr[-3000:]
