"""``parallel.map_jobs``: this process parses from the back while the pool takes the front; the
results are those of a serial loop, in input order."""
from __future__ import annotations

import os
import pickle
from pathlib import Path

import pytest

from physai_lint import files, parallel
from physai_lint.files import Job


def _jobs(tmp_path: Path, n: int) -> list[Job]:
    jobs = []
    for i in range(n):
        if i % 3 == 0:
            text = f"/node_{i}:\n  ros__parameters:\n    rate: {i}.5\n    name: n{i}\n"
            path = tmp_path / f"p{i}.yaml"
            kind = "params"
        else:
            text = (f'<launch>\n  <arg name="a{i}" default="{i}"/>\n'
                    f'  <node pkg="demo" exec="talker" name="t{i}"/>\n</launch>\n')
            path = tmp_path / f"l{i}.launch.xml"
            kind = "launch"
        path.write_text(text)
        jobs.append(Job(kind, str(path), text, "humble"))
    return jobs


def _plain(results: list[tuple[object, bool, bytes | None]]) -> list[bytes]:
    return [pickle.dumps((value, ok)) for value, ok, _ in results]


@pytest.mark.skipif(not hasattr(os, "fork"), reason="the pool forks")
def test_two_jobs_give_the_serial_results_in_order_and_the_parent_takes_a_share(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    jobs = _jobs(tmp_path, 4 * parallel.MIN_PARALLEL_FILES)
    serial = list(parallel.map_jobs(jobs, 1))
    here: list[str] = []
    real = files.run_job
    parent = os.getpid()

    def counting(job: Job, reader: object) -> tuple[object, bool]:
        if os.getpid() == parent:
            here.append(job.path)
        return real(job, reader)  # type: ignore[arg-type]

    monkeypatch.setattr(files, "run_job", counting)
    shared = list(parallel.map_jobs(jobs, 2))
    assert _plain(shared) == _plain(serial)
    assert here, "the parent parsed nothing itself"
    # it works from the back: what it parsed is a tail of the input
    assert set(here) == {j.path for j in jobs[len(jobs) - len(here):]}
    # what came from the pool comes with its pickle (for the cache); the parent's own, without
    assert all(data is not None for _, _, data in shared[:len(jobs) - len(here)])
    assert all(data is None for _, _, data in shared[len(jobs) - len(here):])


def test_few_jobs_stay_in_this_process(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    jobs = _jobs(tmp_path, parallel.MIN_PARALLEL_FILES - 1)

    def no_pool(workers: int) -> None:
        raise AssertionError("a pool was started")

    monkeypatch.setattr(parallel, "_pool", no_pool)
    assert _plain(list(parallel.map_jobs(jobs, 4))) == _plain(list(parallel.map_jobs(jobs, 1)))
