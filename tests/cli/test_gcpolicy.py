"""The command line tunes the cyclic collector for its run and gives the process back as it was."""
from __future__ import annotations

import gc
from pathlib import Path

import pytest

from physai_lint import cli, gcpolicy
from physai_lint.resolve import instantiate

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "fixed_ws"


@pytest.mark.parametrize("enabled", [True, False])
def test_a_run_restores_the_collector(enabled: bool, monkeypatch: pytest.MonkeyPatch) -> None:
    seen: list[tuple[bool, tuple[int, int, int]]] = []
    real = instantiate.resolve_launch

    def spy(*args, **kwargs):  # type: ignore[no-untyped-def]
        seen.append((gc.isenabled(), gc.get_threshold()))
        return real(*args, **kwargs)

    monkeypatch.setattr(instantiate, "resolve_launch", spy)
    before = gc.get_threshold()
    (gc.enable if enabled else gc.disable)()
    try:
        rc = cli._run(["check", str(EXAMPLE / "src"), "--workspace", str(EXAMPLE), "--no-cache", "-q",
                       "--interfaces", str(EXAMPLE / "interfaces.yaml")])
        assert rc == 0
        assert gc.isenabled() is enabled and gc.get_threshold() == before
    finally:
        gc.enable()
    # while resolving, the collector was off (parsing was done), older generations tuned
    assert seen and all(not on and th == (50_000, 1_000, 1_000) for on, th in seen)


def test_the_library_keeps_the_collector_on() -> None:
    assert gc.isenabled()
    gcpolicy.parsing_done()  # outside a command-line run: nothing changes
    assert gc.isenabled()


def test_a_process_about_to_end_is_left_as_the_run_left_it(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setitem(gcpolicy._state, "ending", True)  # what cli.entry says before os._exit
    before = gc.get_threshold()
    try:
        with gcpolicy.for_run():
            gcpolicy.parsing_done()
        # re-enabling would make the next collection walk every object of the run
        assert not gc.isenabled() and gc.get_threshold() == (50_000, 1_000, 1_000)
    finally:
        gc.set_threshold(*before)
        gc.enable()


def test_only_a_process_about_to_end_keeps_the_project(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(gcpolicy, "_kept", [])
    args = ["check", str(EXAMPLE / "src"), "--workspace", str(EXAMPLE), "--no-cache", "-q",
            "--interfaces", str(EXAMPLE / "interfaces.yaml")]
    assert cli._run(args) == 0
    assert gcpolicy._kept == []  # a library caller's memory is freed as usual
    monkeypatch.setitem(gcpolicy._state, "ending", True)
    before = gc.get_threshold()
    try:
        assert cli._run(args) == 0
    finally:
        gc.set_threshold(*before)
        gc.enable()
    # the project is not freed object by object before the report; os._exit gives it back at once
    assert [type(p).__name__ for p in gcpolicy._kept] == ["Project"]
