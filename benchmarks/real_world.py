#!/usr/bin/env python3
"""Run the benchmarks/run.py rows on a folder of cloned public ROS 2 repositories.

    python benchmarks/real_world.py DIR [--runs 3] [--distro humble]

DIR holds one clone per subdirectory (for example `git clone --depth 1` of navigation2,
ros2_control_demos, turtlebot3, ...). It prints one row per repository and one for DIR as a
whole, each linted as its own workspace. Nothing under DIR is committed to this repository
and nothing in it is executed: the linter only reads files. Findings are expected (exit 1);
exit 2 means the linter failed on that input and is worth a bug report.
"""
from __future__ import annotations

import argparse
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from run import HEADER, fmt, measure, startup


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("dir", type=Path, help="folder of cloned ROS 2 repositories")
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--distro", default="humble")
    args = parser.parse_args()
    root = args.dir.resolve()
    if not root.is_dir():
        parser.error(f"{root} is not a directory")

    print(startup(args.runs))
    print(HEADER)
    repos = sorted(p for p in root.iterdir() if p.is_dir() and not p.name.startswith("."))
    for target in [*repos, root]:
        name = target.name if target != root else f"{root.name} (all)"
        lint_args = ["check", str(target), "--workspace", str(target), "--distro", args.distro]
        print(fmt(measure(name[:28], lint_args, target, args.runs)), flush=True)


if __name__ == "__main__":
    main()
