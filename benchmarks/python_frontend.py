"""Time one ~300-line Python launch file: parse + evaluate, and parse + evaluate + resolve, in-process.

    python benchmarks/python_frontend.py [--runs 20] [--distro humble] [FILE]

Imports and the package index are warmed up first (one untimed run), so the figures are what a
launch file costs after start-up. Each run uses a fresh ``FileStore`` and no disk cache, so the
entry file and the file it includes are parsed again every time. Prints wall-clock medians and
min-max in ms, and the median CPU time of this process (steadier on a shared, busy machine).
The default FILE is ``benchmarks/fixtures/ws300/src/yard_bringup/launch/fleet.launch.py``, written
for this benchmark (helpers, a dataclass, loops over a YAML fleet file, includes, groups, parameter
dictionaries, conditions, composable nodes, event handlers, an OpaqueFunction).
"""
from __future__ import annotations

import argparse
import os
import platform
import statistics
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT = os.path.join(HERE, "fixtures", "ws300", "src", "yard_bringup", "launch", "fleet.launch.py")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("file", nargs="?", default=DEFAULT)
    ap.add_argument("--runs", type=int, default=20)
    ap.add_argument("--distro", default="humble")
    args = ap.parse_args()
    sys.path.insert(0, os.path.dirname(HERE))
    from physai_lint.files import FileStore
    from physai_lint.frontends.python import parse_python_launch
    from physai_lint.resolve.instantiate import resolve_launch
    from physai_lint.workspace import build_package_index, find_workspace_root
    from physai_lint.workspace.index import read_text_file

    entry = os.path.abspath(args.file).replace(os.sep, "/")
    with open(entry, encoding="utf-8") as fh:
        text = fh.read()
    packages = build_package_index(find_workspace_root([entry]), args.distro)

    def frontend() -> None:
        parse_python_launch(entry, text, read_text_file, args.distro)

    def whole() -> int:
        store = FileStore(distro=args.distro)
        result = resolve_launch(entry, {}, lambda p: store.launch(p, packages.read_text), packages)
        return len(result.nodes)

    nodes = whole()
    frontend()
    rows = []
    for name, fn in (("parse + evaluate (frontend)", frontend), ("parse + evaluate + resolve", whole)):
        times, cpu = [], []
        for _ in range(args.runs):
            t0, c0 = time.perf_counter(), time.process_time()
            fn()
            times.append((time.perf_counter() - t0) * 1000)
            cpu.append((time.process_time() - c0) * 1000)
        rows.append((name, statistics.median(times), min(times), max(times), statistics.median(cpu)))
    print(f"# Python {platform.python_version()}, {os.cpu_count()} CPUs, {args.runs} runs, distro {args.distro}")
    print(f"# {os.path.relpath(entry)}: {text.count(chr(10))} lines, {nodes} nodes resolved")
    for name, med, lo, hi, cpu_med in rows:
        print(f"{name:30} median {med:7.1f} ms   min-max {lo:.1f}-{hi:.1f} ms   CPU median {cpu_med:.1f} ms")


if __name__ == "__main__":
    main()
