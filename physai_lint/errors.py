"""Errors the command line turns into ``error: ...`` lines: exit code 2, or 1 for ``UnloadableLaunch``."""
from __future__ import annotations


class UsageError(Exception):
    """Bad command-line usage: a missing path, an invalid option value."""


class ConfigError(Exception):
    """An invalid configuration file, rule selector or baseline."""


class UnloadableLaunch(Exception):
    """The launch file ``graph``, ``plan`` or ``params`` was asked about cannot be loaded (a syntax
    error, an unreadable file): ``lines`` are its findings, one ``path:line:col: CODE [name]
    message`` each. Nothing is shown for it (an empty plan would look like a launch that starts
    nothing); the exit code is 1, as ``check`` gives for an error finding."""

    def __init__(self, lines: list[str]) -> None:
        super().__init__("\n".join(lines))
        self.lines = lines
