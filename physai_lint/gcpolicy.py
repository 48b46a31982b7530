"""The cyclic garbage collector during one command-line run.

A run builds a large object graph and keeps it to the end (IR, resolved launches, parameter models,
graphs). CPython's collector walks every young container it has not yet promoted, and the default
thresholds make it re-walk the older generations often; on a large workspace that was 12-20% of a
run (measured with ``gc.callbacks``), and its cost grew faster than the workspace.

Most reference cycles are made while files are parsed (the Python frontend's interpreter: functions
and the scopes that hold them; catkin_pkg's minidom trees): the collector stays on there, with the
older generations collected rarely. Resolution and the rules make few cycles (the walkers break
their own, see ``Instantiator.close``), so the collector is off from the end of parsing to the end
of the run: peak memory stays within what the run holds anyway (measured: +10-45 MiB on a public
1,180-file workspace, +14 MiB on the 1,000-package synthetic one).

Only the command line turns this on (``for_run``), and it restores the previous state when the run
ends, so a process that calls the library (tests, an editor integration) keeps its own collector
settings. The ``physai-lint`` command itself ends with ``os._exit`` right after the run
(``cli.entry``, which calls ``ending_process``): there, nothing is restored. Turning the collector
back on made its next collection walk every object the run had made (0.85 s after the 1,180-file
workspace), for a process about to end.
"""
from __future__ import annotations

import gc
from collections.abc import Iterator
from contextlib import contextmanager

_state = {"active": False, "ending": False}


def ending_process() -> None:
    """The process ends (``os._exit``) as soon as the run does: ``for_run`` need not restore."""
    _state["ending"] = True


@contextmanager
def for_run() -> Iterator[None]:
    """Tune the collector for one run of the command line; restored on exit."""
    was_enabled, thresholds = gc.isenabled(), gc.get_threshold()
    gc.set_threshold(50_000, 1_000, 1_000)
    _state["active"] = True
    try:
        yield
    finally:
        _state["active"] = False
        if not _state["ending"]:  # a process that is about to end needs nothing restored
            gc.set_threshold(*thresholds)
            if was_enabled:
                gc.enable()
            else:
                gc.disable()


_kept: list[object] = []


def keep_to_exit(obj: object) -> None:
    """Hold ``obj`` until the process ends, when it ends with ``os._exit`` right after the run.

    Dropping the last reference to a run's project frees its whole object graph one object at a
    time, in this process, before the report is written: 0.1 s on a public 1,180-file workspace,
    serial whatever ``--jobs`` says. A process that is about to end gives its memory back at once.
    """
    if _state["ending"]:
        _kept.append(obj)


def parsing_done() -> None:
    """Called once every file is parsed: the collector is off for the rest of a command-line run."""
    if _state["active"]:
        gc.disable()
