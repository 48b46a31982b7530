"""Data read statically from a package's build files."""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Literal


@dataclass(frozen=True)
class InstallRule:
    """One install statement, normalised. ``dest`` is relative to the install prefix
    (``share/<pkg>/launch``); ``source`` is an absolute ``/`` path, or ``None`` when it could not be
    known (a generated file, an unknown variable): then everything below ``dest`` is unknown.

    kind "file": ``source`` installs as ``dest/<rename or basename>``.
    kind "directory": ``source`` installs as ``dest/<basename>/...``, or its contents as
    ``dest/...`` when ``contents_only`` (a trailing slash). ``patterns``/``excludes`` are CMake
    ``PATTERN`` globs on file names (``files_matching``: only files matching a pattern install)."""

    kind: Literal["file", "directory"]
    dest: str
    source: str | None
    line: int
    origin: str  # the build file path
    rename: str | None = None
    contents_only: bool = False
    files_matching: bool = False
    patterns: tuple[str, ...] = ()
    excludes: tuple[str, ...] = ()


@dataclass
class BuildInfo:
    """What a package installs. ``complete`` is False when something could not be evaluated
    statically (then "not installed" verdicts would be guesses and ``locate`` says "unknown")."""

    executables: set[str] = field(default_factory=set)  # installed to lib/<pkg>
    executables_in_bin: set[str] = field(default_factory=set)  # console scripts not sent to lib/<pkg>
    scripts_dir: str | None = None  # where setup.cfg sends them instead (as written), else bin/
    plugins: set[str] = field(default_factory=set)
    rules: list[InstallRule] = field(default_factory=list)
    # executable or plugin -> parameter YAML files (absolute paths)
    parameter_yamls: dict[str, list[str]] = field(default_factory=dict)
    # executable or plugin -> its source files (absolute paths), for parameter extraction
    sources: dict[str, list[str]] = field(default_factory=dict)
    # executable or plugin -> those of its sources that a library it links brings (for a plugin:
    # all of them): only the classes its own code names run from them
    library_sources: dict[str, list[str]] = field(default_factory=dict)
    # executable or plugin -> the classes known to run in it (a component's plugin class)
    source_roots: dict[str, list[str]] = field(default_factory=dict)
    # generate_parameter_module: (module name, yaml absolute path)
    parameter_modules: list[tuple[str, str]] = field(default_factory=list)
    python_packages: set[str] = field(default_factory=set)
    registers_in_index: bool = True
    complete: bool = True
    executables_complete: bool = True  # False: an executable list we could not fully read
    project_name: str | None = None
    problems: list[tuple[str, str, int]] = field(default_factory=list)  # (path, message, line)
    # Commands the CMake reader did not interpret (CMake's own, or a dependency's macros), the
    # packages find_package() names, and the functions and macros the CONFIG_EXTRAS files define
    # that install something (lower case): a dependency's macro may install into this package.
    calls: set[str] = field(default_factory=set)
    found_packages: set[str] = field(default_factory=set)
    installers: set[str] = field(default_factory=set)
