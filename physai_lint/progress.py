"""A progress bar on stderr for long runs on a terminal; nothing at all otherwise.

The bar appears only when stderr is a TTY and the run has already taken ``DELAY_S``: short runs
and every redirected or piped run print nothing extra. It is transient (erased when the run ends)
and refreshed by the caller, never by a background thread, so it cannot interleave with the
report (which goes to stdout) or race a process pool's fork.
"""
from __future__ import annotations

import sys
import time
from typing import Any

DELAY_S = 1.0
REFRESH_S = 0.1


class Progress:
    """Stages with a known number of steps: ``stage(name, total)``, ``advance()``, ``stop()``."""

    def __init__(self, enabled: bool, stream: Any = None) -> None:
        self.enabled = enabled
        self.stream = stream
        self.started = time.monotonic()
        self.last = 0.0
        self.bar: Any = None
        self.task: Any = None
        self.name, self.total, self.done = "", 0, 0

    @classmethod
    def start(cls, wanted: bool, stream: Any = None) -> Progress:
        stream = stream if stream is not None else sys.stderr
        try:
            tty = bool(wanted) and stream.isatty()
        except (AttributeError, ValueError, OSError):
            tty = False
        return cls(tty, stream)

    def stage(self, name: str, total: int) -> None:
        if not self.enabled:
            return
        self.name, self.total, self.done = name, total, 0
        if self.bar is not None:
            self.bar.update(self.task, description=name, total=max(total, 1), completed=0)
        self._tick(force=True)

    def advance(self, steps: int = 1) -> None:
        if not self.enabled:
            return
        self.done += steps
        self._tick()

    def stop(self) -> None:
        if self.bar is not None:
            try:
                self.bar.stop()
            except Exception:  # noqa: BLE001, S110 - a broken terminal must not fail the run
                pass
        self.bar = None
        self.enabled = False

    def _tick(self, force: bool = False) -> None:
        now = time.monotonic()
        if now - self.started < DELAY_S or (not force and now - self.last < REFRESH_S):
            return
        self.last = now
        try:
            if self.bar is None:
                self._show()
            self.bar.update(self.task, completed=self.done)
            self.bar.refresh()
        except Exception:  # noqa: BLE001 - a broken terminal must not fail the run
            self.enabled = False

    def _show(self) -> None:
        from rich.console import Console
        from rich.progress import BarColumn, MofNCompleteColumn, TextColumn, TimeElapsedColumn
        from rich.progress import Progress as Bar

        console = Console(file=self.stream, stderr=self.stream is sys.stderr)
        self.bar = Bar(TextColumn("{task.description:<10}"), BarColumn(), MofNCompleteColumn(),
                       TimeElapsedColumn(), console=console, transient=True, auto_refresh=False,
                       redirect_stdout=False, redirect_stderr=False)
        self.bar.start()
        self.task = self.bar.add_task(self.name, total=max(self.total, 1))
