#!/usr/bin/env python3
"""The long fuzz run (docs/fuzzing.md): N inputs per format through every frontend and the pipeline.

    .venv/bin/python scripts/fuzz_long.py --per-format 10000 --jobs 2 --out fuzz-out

Each format's inputs are split over ``--jobs`` worker processes, each with its own hypothesis seed
(``--seed`` + worker index, so a run is repeatable). Failures (an escaping exception or an X003
finding) are saved to ``OUT/<format>-<n>.bin`` with the traceback next to them; the run prints a
summary and exits 1 if anything failed.
"""
from __future__ import annotations

import argparse
import json
import multiprocessing
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tests" / "fuzz"))


def _worker(job: tuple[str, int, int, int, str]) -> dict[str, object]:
    fmt, count, seed, api_every, out = job
    import fuzz_harness as fh
    from hypothesis import HealthCheck, given, settings
    from hypothesis import seed as hseed

    runner = fh.Runner()
    state = {"n": 0, "failures": 0}
    started = time.perf_counter()

    @hseed(seed)
    @settings(max_examples=count, database=None, deadline=None, phases=["generate"],
              suppress_health_check=list(HealthCheck))
    @given(fh.inputs(fmt))
    def body(data: bytes) -> None:
        state["n"] += 1
        try:
            runner.run(fmt, data, api=state["n"] % api_every == 0)
        except fh.Failure as exc:
            state["failures"] += 1
            stem = Path(out) / f"{fmt}-seed{seed}-{state['n']}"
            stem.with_suffix(".bin").write_bytes(data)
            stem.with_suffix(".txt").write_text(str(exc), encoding="utf-8")

    try:
        body()
    finally:
        runner.close()
    return {"format": fmt, "inputs": state["n"], "failures": state["failures"],
            "seconds": round(time.perf_counter() - started, 1)}


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--per-format", type=int, default=10_000)
    ap.add_argument("--formats", default="xml,yaml,python,params")
    ap.add_argument("--jobs", type=int, default=multiprocessing.cpu_count())
    ap.add_argument("--seed", type=int, default=20260601)
    ap.add_argument("--api-every", type=int, default=10,
                    help="also run graph/plan/params on every Nth input (default 10)")
    ap.add_argument("--out", default="fuzz-out", help="folder for failing inputs")
    args = ap.parse_args()
    Path(args.out).mkdir(parents=True, exist_ok=True)
    jobs = []
    for fmt in args.formats.split(","):
        share, extra = divmod(args.per_format, args.jobs)
        for i in range(args.jobs):
            jobs.append((fmt, share + (1 if i < extra else 0), args.seed + i, args.api_every, args.out))
    started = time.perf_counter()
    totals: dict[str, dict[str, float]] = {}
    with multiprocessing.Pool(args.jobs) as pool:
        for res in pool.imap_unordered(_worker, jobs):
            print(json.dumps(res), flush=True)
            t = totals.setdefault(str(res["format"]), {"inputs": 0, "failures": 0, "cpu_seconds": 0.0})
            t["inputs"] += int(res["inputs"])  # type: ignore[call-overload]
            t["failures"] += int(res["failures"])  # type: ignore[call-overload]
            t["cpu_seconds"] += float(res["seconds"])  # type: ignore[arg-type]
    summary = {"wall_seconds": round(time.perf_counter() - started, 1), "jobs": args.jobs, "seed": args.seed,
               "formats": totals}
    print(json.dumps(summary, indent=2))
    return 1 if any(t["failures"] for t in totals.values()) else 0


if __name__ == "__main__":
    sys.exit(main())
