"""Errors the command line turns into one ``error: ...`` line and exit code 2."""
from __future__ import annotations


class UsageError(Exception):
    """Bad command-line usage: a missing path, an invalid option value."""


class ConfigError(Exception):
    """An invalid configuration file, rule selector or baseline."""
