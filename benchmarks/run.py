#!/usr/bin/env python3
"""Time physai-lint as a whole process on synthetic and example workspaces.

    python benchmarks/run.py [--runs 5] [--sizes 100,1000] [--m 3] [--workdir DIR]

For each workspace it prints the number of launch/parameter files, the wall time of
`physai-lint check` (median and min-max over --runs), files per second, the peak RSS of one
extra run, and a "parse floor": the time to merely parse the same files in this process
(libcst for Python, xml.etree for XML, yaml.compose with the libyaml CSafeLoader for YAML),
with the ratio lint/floor. It also prints `physai-lint --version` against `python -c pass`.
The figures are printed, never asserted.
"""
from __future__ import annotations

import argparse
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
import xml.etree.ElementTree as ET
from dataclasses import dataclass
from pathlib import Path

HERE = Path(__file__).resolve().parent
REPO = HERE.parent
LAUNCH_SUFFIXES = ("launch.py", "launch.xml", "launch.yaml")
IGNORE_MARKERS = ("COLCON_IGNORE", "AMENT_IGNORE", "CATKIN_IGNORE")
SKIP_DIRS = {"build", "install", "log", "node_modules"}


def lint_command() -> list[str]:
    """The installed console script, else the module next to this interpreter."""
    beside = Path(sys.executable).parent / "physai-lint"
    exe = str(beside) if beside.exists() else shutil.which("physai-lint")
    return [exe] if exe else [sys.executable, "-m", "physai_lint"]


def discover(root: Path) -> list[Path]:
    """Launch files and parameter files, found the way the linter documents it."""
    found: list[Path] = []
    for dirpath, dirnames, filenames in os.walk(root):
        if any(marker in filenames for marker in IGNORE_MARKERS):
            dirnames[:] = []
            continue
        dirnames[:] = sorted(d for d in dirnames if not d.startswith((".", "_")) and d not in SKIP_DIRS)
        for name in sorted(filenames):
            path = Path(dirpath) / name
            is_param = name.endswith((".yaml", ".yml")) and _is_param_file(path)
            if name.endswith(LAUNCH_SUFFIXES) or is_param:
                found.append(path)
    return found


def _is_param_file(path: Path) -> bool:
    try:
        return "ros__parameters" in path.read_text(encoding="utf-8", errors="replace")
    except OSError:
        return False


def parse_floor(files: list[Path]) -> float:
    """Seconds to parse every file once with the fastest plain parser for its format."""
    import libcst
    import yaml

    loader = getattr(yaml, "CSafeLoader", yaml.SafeLoader)
    start = time.perf_counter()
    for path in files:
        text = path.read_text(encoding="utf-8", errors="replace")
        try:
            if path.name.endswith(".py"):
                libcst.parse_module(text)
            elif path.name.endswith(".xml"):
                ET.fromstring(text)
            else:
                yaml.compose(text, Loader=loader)
        except Exception:  # noqa: BLE001, S112 - a broken file still costs its parse attempt
            continue
    return time.perf_counter() - start


def wall_times(cmd: list[str], runs: int, cwd: Path) -> tuple[list[float], int]:
    times, code = [], 0
    for _ in range(runs):
        start = time.perf_counter()
        proc = subprocess.run(cmd, check=False, cwd=cwd, stdin=subprocess.DEVNULL,
                              stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        times.append(time.perf_counter() - start)
        code = proc.returncode
    return times, code


def peak_rss_mib(cmd: list[str], cwd: Path) -> float:
    """Peak RSS of one run: /usr/bin/time -v when present, else getrusage in a fresh parent."""
    if Path("/usr/bin/time").exists():
        proc = subprocess.run(["/usr/bin/time", "-v", *cmd], check=False, cwd=cwd, stdin=subprocess.DEVNULL,
                              stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
        m = re.search(r"Maximum resident set size \(kbytes\): (\d+)", proc.stderr)
        if m:
            return int(m[1]) / 1024
    # RUSAGE_CHILDREN only grows, so measure in a fresh interpreter whose only child is the lint.
    probe = ("import resource, subprocess, sys; "
             "subprocess.run(sys.argv[1:], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL); "
             "print(resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss)")
    out = subprocess.run([sys.executable, "-c", probe, *cmd], check=False, cwd=cwd, capture_output=True,
                         text=True, stdin=subprocess.DEVNULL)
    kib = int(out.stdout.strip() or 0)
    return kib / 1024 / (1024 if sys.platform == "darwin" else 1)


@dataclass(frozen=True)
class Row:
    name: str
    files: int
    times: list[float]
    rss_mib: float
    floor: float
    exit_code: int


def measure(name: str, args: list[str], scan_root: Path, runs: int, cwd: Path = REPO) -> Row:
    cmd = lint_command() + args
    files = discover(scan_root)
    times, code = wall_times(cmd, runs, cwd)
    return Row(name, len(files), times, peak_rss_mib(cmd, cwd), parse_floor(files), code)


HEADER = (f"{'workspace':<28} {'files':>6} {'wall median s':>14} {'min-max s':>15} "
          f"{'files/s':>9} {'peak MiB':>9} {'parse floor s':>14} {'lint/floor':>10} {'exit':>5}")


def fmt(row: Row) -> str:
    med = statistics.median(row.times)
    rate = row.files / med if med else 0.0
    ratio = med / row.floor if row.floor else float("inf")
    span = f"{min(row.times):.3f}-{max(row.times):.3f}"
    # exit 0/1 are both normal (1 = findings); 2 means the linter failed on this input.
    return (f"{row.name:<28} {row.files:>6} {med:>14.3f} {span:>15} {rate:>9.1f} "
            f"{row.rss_mib:>9.1f} {row.floor:>14.3f} {ratio:>9.1f}x {row.exit_code:>5}")


def startup(runs: int) -> str:
    lint, _ = wall_times(lint_command() + ["--version"], runs, REPO)
    bare, _ = wall_times([sys.executable, "-c", "pass"], runs, REPO)
    lm, bm = statistics.median(lint), statistics.median(bare)
    return (f"start-up: physai-lint --version {lm * 1000:.0f} ms, python -c pass {bm * 1000:.0f} ms, "
            f"ratio {lm / bm:.1f}x")


def example_rows(runs: int) -> list[Row]:
    rows = []
    for ws in ("buggy_ws", "fixed_ws"):
        root = REPO / "examples" / ws
        args = ["check", str(root / "src"), "--workspace", str(root),
                "--interfaces", str(root / "interfaces.yaml")]
        rows.append(measure(f"examples/{ws}", args, root / "src", runs))
    return rows


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=5)
    parser.add_argument("--sizes", default="100,1000", help="comma-separated package counts N")
    parser.add_argument("--m", type=int, default=3, help="launch files per package")
    parser.add_argument("--workdir", type=Path, help="keep generated workspaces here")
    args = parser.parse_args()

    sys.path.insert(0, str(HERE))
    from gen_workspace import generate

    print(f"physai-lint: {' '.join(lint_command())}  (python {sys.version.split()[0]}, "
          f"{os.cpu_count()} CPUs, {args.runs} runs)")
    print(startup(args.runs))
    print(HEADER)
    for row in example_rows(args.runs):
        print(fmt(row), flush=True)
    with tempfile.TemporaryDirectory(prefix="physai-bench-") as tmp:
        base = args.workdir or Path(tmp)
        for n in (int(s) for s in args.sizes.split(",") if s):
            ws = base / f"synthetic_{n}x{args.m}"
            generate(n, args.m, ws)
            row = measure(f"synthetic N={n} M={args.m}",
                          ["check", str(ws / "src"), "--workspace", str(ws)], ws / "src", args.runs)
            print(fmt(row), flush=True)


if __name__ == "__main__":
    main()
