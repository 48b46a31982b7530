"""``parallel.package_reads`` and ``parallel.prefetch_interfaces``: work done ahead of resolution
and of the rules, shared with a forked helper; what the helper did arrives as if done here, and a
run leaves the same packages, problems and interfaces as the lazy serial path."""
from __future__ import annotations

import os
import time
from pathlib import Path
from typing import Any

import pytest

from physai_lint import parallel
from physai_lint.engine import CheckOptions, _interface_keys, build_project
from physai_lint.workspace.index import PackageIndex, build_package_index

forks = pytest.mark.skipif(not hasattr(os, "fork"), reason="the helper is forked")


@pytest.fixture
def low_thresholds(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(parallel, "MIN_FORK_PACKAGES", 2)
    monkeypatch.setenv(parallel.FORK_MIN_ENV, "0")


class _Interfaces:
    """A store whose answers name the process that computed them."""

    def __init__(self) -> None:
        self.primed: dict[tuple[str, str], Any] = {}
        self.asked: list[tuple[str, str]] = []

    def get(self, package: str, executable: str) -> Any:
        if (package, executable) in self.primed:
            return self.primed[(package, executable)]
        time.sleep(0.003)  # slow enough for the helper to start before this process is done
        self.asked.append((package, executable))
        return {"key": (package, executable), "pid": os.getpid()}

    def prime(self, key: tuple[str, str], value: Any) -> None:
        self.primed.setdefault(key, value)

    def cached(self, key: tuple[str, str]) -> bool:
        return key in self.primed or key in self.asked


@forks
def test_interfaces_are_computed_on_both_sides_and_primed_here(low_thresholds: None) -> None:
    keys = [(f"pkg{i:02d}", exe) for i in range(30) for exe in ("a", "b")]
    store = _Interfaces()
    parallel.prefetch_interfaces(store, keys + keys[:5], 2, files=0)  # duplicates asked once
    here = set(store.asked)
    assert here and len(store.asked) == len(here)
    assert set(store.primed) | here == set(keys), "every key is computed once, here or there"
    assert not set(store.primed) & here
    assert {v["pid"] for v in store.primed.values()} - {os.getpid()}, "the helper computed nothing"
    assert all(v["key"] == k for k, v in store.primed.items())
    # whole packages travel together: the executables of a package are computed in one process
    assert {p for p, _ in store.primed} & {p for p, _ in here} == set()


@forks
def test_interfaces_stay_lazy_with_one_job_or_few_packages(low_thresholds: None,
                                                            monkeypatch: pytest.MonkeyPatch) -> None:
    keys = [(f"pkg{i}", "a") for i in range(10)]
    store = _Interfaces()
    parallel.prefetch_interfaces(store, keys, 1, files=0)
    assert not store.asked and not store.primed
    monkeypatch.setattr(parallel, "MIN_FORK_PACKAGES", 11)
    parallel.prefetch_interfaces(store, keys, 2, files=0)
    assert not store.asked and not store.primed


def _workspace(root: Path, n: int) -> list[str]:
    files = []
    for i in range(n):
        pkg = root / "src" / f"pkg{i:02d}"
        (pkg / "launch").mkdir(parents=True)
        if i == 3:  # colcon rejects it: a problem the reading reports
            (pkg / "package.xml").write_text('<?xml version="1.0"?>\n<package format="3">\n'
                                             f"  <name>pkg{i:02d}</name>\n</package>\n")
        else:
            (pkg / "package.xml").write_text(
                '<?xml version="1.0"?>\n<package format="3">\n'
                f"  <name>pkg{i:02d}</name><version>0.1.0</version><description>d</description>\n"
                '  <maintainer email="a@b.c">a</maintainer><license>MIT</license>\n'
                "  <export><build_type>ament_python</build_type></export>\n</package>\n")
            (pkg / "setup.py").write_text("from setuptools import setup\nsetup(name='x', entry_points="
                                          f"{{'console_scripts': ['node{i} = x.main:main']}})\n")
        launch = pkg / "launch" / "a.launch.xml"
        launch.write_text("<launch/>\n")
        files.append(str(launch))
    return files


def _index(root: Path) -> PackageIndex:
    return build_package_index(str(root), "humble", None, None)


@forks
def test_packages_read_by_the_helper_are_those_read_here(low_thresholds: None, tmp_path: Path) -> None:
    files = _workspace(tmp_path, 12)
    serial = _index(tmp_path)
    serial.read_packages_holding(files)
    shared = _index(tmp_path)
    names = shared.names_holding(files)
    assert names == sorted(f"pkg{i:02d}" for i in range(12))
    reads = parallel.package_reads(shared, names, 2, files=0)
    assert reads is not None
    reads.run()
    assert sorted(shared.packages._read) == sorted(serial.packages._read)
    for name, pkg in serial.packages._read.items():
        assert shared.packages._read[name] == pkg
    assert sorted(shared.problems) == sorted(serial.problems) and serial.problems
    assert sorted(shared.notes) == sorted(serial.notes)


def test_an_unreadable_package_is_adopted_as_unread(tmp_path: Path) -> None:
    _workspace(tmp_path, 4)
    there, here = _index(tmp_path), _index(tmp_path)
    (tmp_path / "src" / "pkg01" / "package.xml").write_bytes(b"\x00\xff")  # after indexing
    there._text_cache.clear()
    there.packages._read.pop("pkg01", None)
    read = there.read_package_elsewhere("pkg01")
    assert read[0] is None and read[1] == [(str(tmp_path / "src/pkg01/package.xml"),
                                            "package.xml is unreadable (binary, too large or not UTF-8)", 1)]
    here.adopt_package("pkg01", read)
    assert "pkg01" not in here.packages._read and here.problems == read[1]
    here.adopt_package("pkg02", there.read_package_elsewhere("pkg02"))
    assert here.packages._read["pkg02"].name == "pkg02"
    here.adopt_package("pkg02", (None, [("again", "x", 1)], []))  # already read here: ignored
    assert ("again", "x", 1) not in here.problems


@forks
def test_a_project_built_with_a_helper_matches_the_serial_one(low_thresholds: None, tmp_path: Path) -> None:
    files = _workspace(tmp_path, 12)
    opts = CheckOptions(paths=[str(tmp_path / "src")], workspace=str(tmp_path), cache=False)
    one = build_project(CheckOptions(**{**opts.__dict__, "jobs": 1}), str(tmp_path))
    two = build_project(CheckOptions(**{**opts.__dict__, "jobs": 2}), str(tmp_path))
    assert sorted(one.packages.packages._read) == sorted(two.packages.packages._read)
    assert sorted(map(repr, one.diagnostics)) == sorted(map(repr, two.diagnostics))
    assert len(files) == 12


def test_interface_keys_are_the_active_non_process_nodes() -> None:
    class N:
        def __init__(self, kind: str, active: Any, package: Any, executable: Any) -> None:
            self.kind, self.active, self.package, self.executable = kind, active, package, executable

    class R:
        nodes = (N("node", True, "a", "x"), N("process", True, "b", "y"), N("node", False, "c", "z"),
                 N("node", None, "d", "w"), N("node", True, None, "v"), N("component", True, "e", "P"))

    assert _interface_keys([R()]) == [("a", "x"), ("d", "w"), ("e", "P")]


@forks
def test_interfaces_ride_along_with_the_resolution_share(low_thresholds: None,
                                                         monkeypatch: pytest.MonkeyPatch) -> None:
    """``interface_side`` taken by ``resolve_entries``: the helper, working from the back, extracts
    interfaces first; every key is computed once, every entry resolved in order."""
    monkeypatch.setattr(parallel, "MIN_FORK_ENTRIES", 2)
    keys = [(f"pkg{i:02d}", "a") for i in range(20)]
    store = _Interfaces()
    side = parallel.interface_side(store, keys, 2, files=0)
    assert side is not None and not side.done

    class _Files:
        launches: dict[str, Any] = {}

    def resolve(entry: str) -> Any:
        time.sleep(0.003)
        return (entry, os.getpid())

    entries = [f"e{i:02d}" for i in range(20)]
    out = parallel.resolve_entries(entries, resolve, _Files(), lambda p: None, 2, side=side)
    assert side.done
    assert [e for e, _ in out] == entries
    here = set(store.asked)
    assert set(store.primed) | here == set(keys) and not set(store.primed) & here
    assert store.primed, "the helper extracted nothing"


@forks
def test_keys_already_extracted_are_not_shared_again(low_thresholds: None) -> None:
    keys = [(f"pkg{i:02d}", "a") for i in range(12)]
    store = _Interfaces()
    for key in keys[:5]:
        store.get(*key)
    side = parallel.interface_side(store, keys, 2, files=0)
    assert side is not None and side.n == 7
    store.asked.clear()
    side.run()
    assert not set(store.asked) & set(keys[:5]) and not set(store.primed) & set(keys[:5])


@forks
def test_a_package_read_for_its_interfaces_in_the_helper_arrives_read_here(low_thresholds: None,
                                                                          tmp_path: Path) -> None:
    """Extraction reads the package (its build rules name the sources); the rules ask for its
    executables later, so the helper's reading comes back with the interfaces."""
    from physai_lint.interfaces.store import InterfaceStore

    _workspace(tmp_path, 12)
    shared, serial = _index(tmp_path), _index(tmp_path)
    keys = [(f"pkg{i:02d}", f"node{i}") for i in range(12)]
    store = InterfaceStore(shared)
    parallel.prefetch_interfaces(store, keys, 2, files=0)
    for key in keys:
        InterfaceStore(serial).get(*key)
    assert sorted(shared.packages._read) == sorted(serial.packages._read) == [p for p, _ in keys]
    for name, pkg in serial.packages._read.items():
        assert shared.packages._read[name] == pkg
    assert sorted(shared.problems) == sorted(serial.problems) and serial.problems
