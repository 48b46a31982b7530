"""``parallel.map_jobs``: this process parses from the front while a forked helper (or, where
the platform cannot fork, a pool) takes the back; the results are those of a serial loop, in input
order."""
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


@pytest.mark.skipif(not hasattr(os, "fork"), reason="the helper is forked")
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
    assert len(here) < len(jobs), "the helper parsed nothing"
    # it works from the front of the travel order (parameter files first, whose results cost
    # the most to send back): what it parsed is a head of that order
    ordered = sorted(jobs, key=parallel._travel_rank)
    assert ordered[0].kind == "params" and ordered[-1].kind == "launch"
    assert here == [j.path for j in ordered[:len(here)]]
    # its own results come without a pickle; the helper's with theirs (for the cache)
    mine = set(here)
    assert all((data is None) == (job.path in mine) for job, (_, _, data) in zip(jobs, shared))


def test_few_jobs_stay_in_this_process(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    jobs = _jobs(tmp_path, parallel.MIN_PARALLEL_FILES - 1)

    def no_pool(workers: int) -> None:
        raise AssertionError("a pool was started")

    monkeypatch.setattr(parallel, "_pool", no_pool)
    assert _plain(list(parallel.map_jobs(jobs, 4))) == _plain(list(parallel.map_jobs(jobs, 1)))


@pytest.mark.skipif(not hasattr(os, "fork"), reason="the helper is forked")
def test_a_helper_that_dies_loses_nothing(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    jobs = _jobs(tmp_path, 4 * parallel.MIN_PARALLEL_FILES)
    serial = list(parallel.map_jobs(jobs, 1))
    real = files.run_job
    parent = os.getpid()

    def dying(job: Job, reader: object) -> tuple[object, bool]:
        if os.getpid() != parent:
            os._exit(3)  # the helper dies on its first job
        return real(job, reader)  # type: ignore[arg-type]

    monkeypatch.setattr(files, "run_job", dying)
    assert _plain(list(parallel.map_jobs(jobs, 2))) == _plain(serial)


def _share_pids(n: int, helpers: int) -> tuple[list[int], dict[int, int]]:
    """``parallel.share`` over ``n`` slow items: the items this process did, in its order, and
    the pid that did each item."""
    import time

    done: list[int] = []
    out: dict[int, int] = {}

    def local(i: int) -> None:
        time.sleep(0.001)  # slow enough for the helpers to start before this process is done
        done.append(i)
        out[i] = os.getpid()

    def remote(i: int) -> bytes:
        time.sleep(0.001)
        return str(os.getpid()).encode()

    def accept(i: int, data: bytes) -> bool:
        out[i] = int(data)
        return True

    parallel.share(n, local, remote, accept, helpers)
    return done, out


@pytest.mark.skipif(not hasattr(os, "fork"), reason="the helpers are forked")
def test_several_helpers_share_the_back_under_a_lock() -> None:
    """With 4 jobs, three helpers claim from the back: every item is done, once, in order."""
    n = 200
    done, out = _share_pids(n, 3)
    assert sorted(out) == list(range(n))
    assert done == list(range(len(done))), "this process works from the front"
    assert len(set(out.values())) >= 2


def test_without_fork_a_pool_shares_the_work(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """Where forking is unsafe (macOS, a threaded process), a process pool takes the front."""
    jobs = _jobs(tmp_path, 4 * parallel.MIN_PARALLEL_FILES)
    serial = list(parallel.map_jobs(jobs, 1))
    monkeypatch.setattr(parallel, "_can_fork", lambda *args: False)
    shared = list(parallel.map_jobs(jobs, 2))
    assert _plain(shared) == _plain(serial)


@pytest.mark.skipif(not hasattr(os, "fork"), reason="the helper is forked")
def test_without_a_lock_one_helper_still_shares(monkeypatch: pytest.MonkeyPatch) -> None:
    """No record lock on this platform: one helper (which needs none) instead of three."""
    monkeypatch.setattr(parallel, "_lockable", lambda fd: False)
    _, out = _share_pids(100, 3)
    assert sorted(out) == list(range(100))
    assert len(set(out.values())) == 2, "one helper and this process"


@pytest.mark.skipif(not hasattr(os, "fork"), reason="the helper is forked")
def test_side_items_ride_along_with_the_parsing_and_the_helper_starts_with_them(tmp_path: Path) -> None:
    """``map_jobs(..., side=)``: the items of another share (the package reads) join the parsing's
    fork, after the jobs: the helper, working from the back, does them first; each is done once,
    and what the helper computed is taken here."""
    jobs = _jobs(tmp_path, 4 * parallel.MIN_PARALLEL_FILES)
    serial = list(parallel.map_jobs(jobs, 1))
    here: list[int] = []
    taken: dict[int, int] = {}

    def take(i: int, value: int) -> bool:
        taken[i] = value
        return True

    side = parallel.Side(10, here.append, lambda i: os.getpid(), take, 1)
    shared = list(parallel.map_jobs(jobs, 2, side=side))
    assert _plain(shared) == _plain(serial)
    assert side.done
    assert sorted(here + list(taken)) == list(range(10)), "each side item is done once"
    assert taken and set(taken.values()) != {os.getpid()}, "the helper did side items"
    side.run()  # done already: nothing more
    assert sorted(here + list(taken)) == list(range(10))


def test_side_items_are_left_to_the_caller_when_nothing_forks(tmp_path: Path) -> None:
    jobs = _jobs(tmp_path, 4)
    done: list[int] = []
    side = parallel.Side(3, done.append, lambda i: i, lambda i, v: True, 1)
    list(parallel.map_jobs(jobs, 2, side=side))  # too few files to fork
    assert not side.done and not done
