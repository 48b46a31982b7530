"""``--jobs``: parse files in a process pool, results in input order.

A pool costs a fork per worker and a pickle round trip per file, so small runs (the pre-commit
case) stay in this process: below ``MIN_PARALLEL_FILES`` files to parse, or with one job, nothing
is started. Output never depends on the number of jobs: ``map_jobs`` returns results in the
order of its input, and the caller merges them in that order.
"""
from __future__ import annotations

import os
import sys
from collections.abc import Iterator, Sequence
from typing import Any

# Below this many files a pool costs more than it saves (measured: forking two workers and
# shipping results back is ~40 ms; a launch file parses in 2-15 ms).
MIN_PARALLEL_FILES = 24


def default_jobs() -> int:
    """The number of CPUs this process may run on."""
    try:
        return max(1, len(os.sched_getaffinity(0)))
    except (AttributeError, OSError):
        return max(1, os.cpu_count() or 1)


def map_jobs(jobs: Sequence[Any], workers: int, progress: Any = None
             ) -> Iterator[tuple[Any, bool, bytes | None]]:
    """``files.run_job`` over ``jobs`` as (value, cacheable, pickled value or None), in a pool
    when there are enough of them; always in input order."""
    from physai_lint.files import run_job

    workers = min(workers, len(jobs))
    pool = _pool(workers) if workers > 1 and len(jobs) >= MIN_PARALLEL_FILES else None
    done = 0
    if pool is not None:
        from concurrent.futures.process import BrokenProcessPool

        from physai_lint.cache import loads

        try:
            chunk = max(1, min(16, len(jobs) // (workers * 8)))
            for job, (data, cacheable) in zip(jobs, pool.map(_work, jobs, chunksize=chunk)):
                value = loads(data) if data is not None else None
                if value is None:  # could not travel back: parse it here instead
                    value, cacheable = run_job(job, None)
                    data = None
                done += 1
                yield value, cacheable, data
                if progress is not None:
                    progress.advance()
        except (BrokenProcessPool, OSError):
            pass  # a worker died (out of memory, killed): finish the rest in this process
        finally:
            pool.shutdown(wait=True, cancel_futures=True)
    for job in jobs[done:]:
        value, cacheable = run_job(job, None)
        yield value, cacheable, None
        if progress is not None:
            progress.advance()


def _pool(workers: int) -> Any:
    """A process pool, or None when this platform cannot start one (then: serial)."""
    import multiprocessing
    from concurrent.futures import ProcessPoolExecutor

    methods = multiprocessing.get_all_start_methods()
    # fork inherits the already imported frontends (no re-import per worker); elsewhere spawn.
    method = "fork" if "fork" in methods and sys.platform != "darwin" else "spawn"
    try:
        return ProcessPoolExecutor(workers, mp_context=multiprocessing.get_context(method))
    except (OSError, ValueError, ImportError, NotImplementedError):
        return None


def _work(job: Any) -> tuple[bytes | None, bool]:
    """In a worker: parse and pickle here, so the parent only unpickles (and can cache the bytes)."""
    from physai_lint.cache import dumps
    from physai_lint.files import run_job

    value, cacheable = run_job(job, None)
    return dumps(value), cacheable
