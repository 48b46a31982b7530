"""``parallel.resolve_entries``: a forked helper resolves entries from the back while this process
resolves them from the front; the results, and the file store afterwards, are those of a serial
loop."""
from __future__ import annotations

import os
import time
from pathlib import Path
from typing import Any

import pytest

from physai_lint import parallel
from physai_lint.engine import CheckOptions, build_project
from physai_lint.resolve import instantiate

forks = pytest.mark.skipif(not hasattr(os, "fork"), reason="the helper is forked")


class _Store:
    def __init__(self) -> None:
        self.launches: dict[str, Any] = {}


def _toy(store: _Store, fail: Any = None) -> Any:
    """A resolve function: (entry, pid), parsing a "lazy" file of its own on the way."""
    def resolve(entry: str) -> Any:
        if fail is not None:
            fail(entry)
        time.sleep(0.005)  # slow enough for the helper to start before this process is done
        store.launches.setdefault(f"lazy/{entry}", None)
        return (entry, os.getpid())
    return resolve


@pytest.fixture
def low_thresholds(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(parallel, "MIN_FORK_ENTRIES", 2)
    monkeypatch.setenv(parallel.FORK_MIN_ENV, "0")


@forks
def test_both_processes_resolve_and_the_results_come_back_in_order(low_thresholds: None) -> None:
    entries = [f"e{i:02d}" for i in range(40)]
    store = _Store()
    replayed: list[str] = []
    out = parallel.resolve_entries(entries, _toy(store), store, replayed.append, 2)
    assert [e for e, _ in out] == entries
    pids = {pid for _, pid in out}
    assert os.getpid() in pids and len(pids) == 2, "the helper resolved nothing"
    here = [e for e, pid in out if pid == os.getpid()]
    # this process works from the front, the helper from the back
    assert here == entries[:len(here)]
    # what the helper parsed for its entries is parsed here too; this process's own are in store
    assert sorted(replayed) == sorted(f"lazy/{e}" for e, pid in out if pid != os.getpid())
    assert {f"lazy/{e}" for e in here} <= set(store.launches)


@forks
def test_one_job_or_few_entries_stay_in_this_process(low_thresholds: None,
                                                     monkeypatch: pytest.MonkeyPatch) -> None:
    store = _Store()
    entries = [f"e{i}" for i in range(10)]
    assert {pid for _, pid in parallel.resolve_entries(entries, _toy(store), store, print, 1)} == {os.getpid()}
    monkeypatch.setattr(parallel, "MIN_FORK_ENTRIES", 11)
    assert {pid for _, pid in parallel.resolve_entries(entries, _toy(store), store, print, 2)} == {os.getpid()}


@forks
def test_leaves_fork_only_when_there_are_many_of_them(low_thresholds: None,
                                                      monkeypatch: pytest.MonkeyPatch) -> None:
    """Entries that include nothing resolve in a fraction of a millisecond: a fork is not worth
    it below ``MIN_FORK_LEAVES`` of them, though it is for as many includers."""
    entries = [f"e{i:02d}" for i in range(40)]
    monkeypatch.setattr(parallel, "MIN_FORK_LEAVES", 41)
    store = _Store()
    out = parallel.resolve_entries(entries, _toy(store), store, print, 2, leaves=True)
    assert [e for e, _ in out] == entries and {pid for _, pid in out} == {os.getpid()}
    monkeypatch.setattr(parallel, "MIN_FORK_LEAVES", 40)
    out = parallel.resolve_entries(entries, _toy(store), store, lambda p: None, 2, leaves=True)
    assert [e for e, _ in out] == entries and len({pid for _, pid in out}) == 2


@forks
def test_a_helper_that_dies_loses_nothing(low_thresholds: None) -> None:
    parent = os.getpid()

    def die(entry: str) -> None:
        if os.getpid() != parent and entry == "e35":
            os._exit(3)

    entries = [f"e{i}" for i in range(40)]
    store = _Store()
    out = parallel.resolve_entries(entries, _toy(store, die), store, lambda p: None, 2)
    assert [e for e, _ in out] == entries
    assert dict(out)["e35"] == parent


@forks
def test_a_result_that_cannot_travel_is_resolved_here(low_thresholds: None) -> None:
    parent = os.getpid()

    def resolve(entry: str) -> Any:
        if os.getpid() != parent and entry == "e39":
            return (entry, lambda: None)  # not picklable
        return (entry, os.getpid())

    entries = [f"e{i}" for i in range(40)]
    out = parallel.resolve_entries(entries, resolve, _Store(), lambda p: None, 2)
    assert out[-1] == ("e39", parent)
    assert [e for e, _ in out] == entries


def _workspace(tmp_path: Path, n: int) -> Path:
    """A package whose launch files each include a file of another package (outside the checked
    folder, so it is parsed only when an include asks for it) with a parse problem in it."""
    ws = tmp_path / "ws"
    for pkg in ("demo", "common"):
        (ws / "src" / pkg / "launch").mkdir(parents=True)
        (ws / "src" / pkg / "package.xml").write_text(
            f'<?xml version="1.0"?>\n<package format="3"><name>{pkg}</name><version>0.0.0</version>'
            '<description>d</description><maintainer email="a@b.c">m</maintainer>'
            '<license>MIT</license><buildtool_depend>ament_cmake</buildtool_depend></package>\n')
        (ws / "src" / pkg / "CMakeLists.txt").write_text(
            f"project({pkg})\ninstall(DIRECTORY launch DESTINATION share/${{PROJECT_NAME}})\n")
    for i in range(n):
        (ws / "src" / "common" / "launch" / f"s{i:02d}.launch.xml").write_text(
            '<launch>\n  <arg name="robot"/>\n'
            '  <node pkg="demo" exec="driver" name="$(var robot)_driver" output="log" output="screen"/>\n'
            '</launch>\n')
        (ws / "src" / "demo" / "launch" / f"r{i:02d}.launch.xml").write_text(
            f'<launch>\n  <include file="$(find-pkg-share common)/launch/s{i:02d}.launch.xml">\n'
            f'    <arg name="robot" value="r{i}"/>\n  </include>\n'
            f'  <node pkg="demo" exec="talker" name="t{i}" namespace="$(var ns)"/>\n</launch>\n')
    return ws


@forks
def test_two_jobs_build_the_project_one_job_builds(tmp_path: Path, low_thresholds: None,
                                                   monkeypatch: pytest.MonkeyPatch) -> None:
    ws = _workspace(tmp_path, 24)
    opts = CheckOptions(paths=[str(ws / "src" / "demo")], workspace=str(ws), cache=False, jobs=1)
    serial = build_project(opts)
    log = tmp_path / "pids"
    real = instantiate.resolve_launch

    def logged(*args: Any, **kwargs: Any) -> Any:
        time.sleep(0.005)  # the helper starts before this process is done
        with open(log, "a") as fh:
            fh.write(f"{os.getpid()}\n")
        return real(*args, **kwargs)

    monkeypatch.setattr(instantiate, "resolve_launch", logged)
    opts.jobs = 2
    shared = build_project(opts)
    assert len(set(log.read_text().split())) == 2, "the helper resolved nothing"
    assert shared.launches == serial.launches
    included = {str(ws / "src" / "common" / "launch" / f"s{i:02d}.launch.xml") for i in range(24)}
    assert included <= set(serial.store.launches)
    assert set(shared.store.launches) == set(serial.store.launches)
    assert set(shared.store.texts) == set(serial.store.texts)
    assert sorted(map(repr, shared.diagnostics)) == sorted(map(repr, serial.diagnostics))
    assert {d.span.file for d in serial.diagnostics if d.code == "X006"} == included


@forks
def test_without_a_scratch_file_everything_is_resolved_here(low_thresholds: None,
                                                           monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(parallel, "_scratch_file", lambda name: None)
    store = _Store()
    entries = [f"e{i}" for i in range(20)]
    out = parallel.resolve_entries(entries, _toy(store), store, lambda p: None, 2)
    assert out == [(e, os.getpid()) for e in entries]


@forks
def test_leaves_riding_with_includers_do_not_make_a_fork(monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> None:
    """The first wave of resolution carries the leaves no include names (resolve.roots): they
    resolve in a fraction of a millisecond, so only the includers count towards a fork."""
    from physai_lint.files import FileStore

    monkeypatch.setenv(parallel.FORK_MIN_ENV, "0")
    monkeypatch.setattr(parallel, "MIN_FORK_ENTRIES", 4)
    store = FileStore()
    leaves, includers = [], []
    for i in range(30):
        leaf = tmp_path / f"leaf{i:02d}.launch.xml"
        leaf.write_text('<launch><node pkg="demo" exec="talker"/></launch>\n')
        leaves.append(str(leaf))
    for i in range(4):
        inc = tmp_path / f"inc{i}.launch.xml"
        inc.write_text(f'<launch><include file="{leaves[i]}"/></launch>\n')
        includers.append(str(inc))
    for path in leaves + includers:
        store.launch(path)

    def resolve(entry: str) -> Any:
        time.sleep(0.002)
        return (entry, os.getpid())

    wave = leaves + includers[:3]
    out = parallel.resolve_entries(wave, resolve, store, lambda p: None, 2)
    assert [e for e, _ in out] == wave and {pid for _, pid in out} == {os.getpid()}
    wave = leaves + includers
    out = parallel.resolve_entries(wave, resolve, store, lambda p: None, 2)
    assert [e for e, _ in out] == wave and len({pid for _, pid in out}) == 2
