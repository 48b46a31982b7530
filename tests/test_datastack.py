"""``datastack.call``: the run's frames in one chunk of CPython's frame stack."""
from __future__ import annotations

import resource
import sys

import pytest

from physai_lint import datastack


def test_call_passes_arguments_results_and_exceptions():
    assert datastack.call(lambda a, b=0: a * 10 + b, 4, b=2) == 42

    def fail() -> None:
        raise KeyError("x")

    with pytest.raises(KeyError):
        datastack.call(fail)


def _down(n: int) -> int:
    return 0 if n == 0 else _down(n - 1) + 1


def _oscillate(times: int) -> int:
    # 300 frames of ~100 bytes: deeper than one 16 KiB chunk, so each descent crosses an edge
    return sum(_down(300) for _ in range(times))


@pytest.mark.skipif(sys.version_info < (3, 11) or sys.implementation.name != "cpython"
                    or not sys.platform.startswith("linux"),
                    reason="CPython 3.11+ frame-stack chunks, counted by Linux page faults")
def test_call_keeps_deep_calls_from_mapping_chunks_again_and_again():
    def faults(fn: object) -> int:
        before = resource.getrusage(resource.RUSAGE_SELF).ru_minflt
        fn()  # type: ignore[operator]
        return resource.getrusage(resource.RUSAGE_SELF).ru_minflt - before

    plain = faults(lambda: _oscillate(2000))  # a fresh chunk (and its page faults) per descent
    inside = faults(lambda: datastack.call(_oscillate, 2000))
    assert plain >= 1000
    assert inside < plain / 10


def test_the_command_runs_main_under_call(monkeypatch):
    from physai_lint import cli, gcpolicy

    monkeypatch.setitem(gcpolicy._state, "ending", False)  # entry() sets it: restored after
    ran: list[object] = []
    monkeypatch.setattr(datastack, "call", lambda fn, *args: ran.append(fn) or 0)

    def leave(code: int) -> None:
        raise SystemExit(code)

    monkeypatch.setattr(cli.os, "_exit", leave)
    with pytest.raises(SystemExit) as exc:
        cli.entry()
    assert exc.value.code == 0 and ran == [cli.main]
