"""A content-addressed disk cache for per-file parse results.

Only results that are pure functions of one file's bytes (and of the path and options named in
the key) are stored: a launch file's IR and parse diagnostics, a parameter file's model, what one
C++ source declares (``interfaces/extract_cpp.py``), a package.xml's manifest data and problem,
a CMakeLists.txt's build data (``workspace/index.py``; with the digests of the subdirectory
CMakeLists.txt files it read, checked on every hit). Nothing that depends on other files
(resolution, includes, findings) or on directory listings is cached here.

Layout: ``<dir>/<2 hex>/<62 hex>.pickle``, the name being the SHA-256 of (code fingerprint, kind,
options, path, text). Writes go to a temporary file in the same directory and are published with
``os.replace``, so concurrent runs never see half a file; an entry that cannot be read or
unpickled is a miss; a directory that cannot be created or written turns the cache off for the
rest of the run instead of failing it. The code fingerprint covers the package version and the
size and modification time of every module that produces cached values (and of catkin_pkg, which
parses manifests), so an edited checkout never reads results written by older code.

The directory is ``$PHYSAI_LINT_CACHE_DIR``, else the platform cache directory
(``$XDG_CACHE_HOME/physai-lint``, ``~/.cache/physai-lint``; ``~/Library/Caches`` on macOS,
``%LOCALAPPDATA%`` on Windows). Entries are pickles: the directory must be as private as the
user's home (a shared, writable cache directory would let others plant objects).
"""
from __future__ import annotations

import hashlib
import os
import pickle
import sys
import tempfile
from typing import Any

ENV_DIR = "PHYSAI_LINT_CACHE_DIR"
FORMAT = b"physai-lint parse cache 1"
# Modules whose code decides what a cached value looks like (relative to the package).
_PRODUCERS = ("files.py", "cache.py", "frontends", "params", "model", "interfaces", "workspace")
# Third-party packages whose code does (found without importing them: a warm run never does).
_THIRD_PARTY = ("catkin_pkg",)


def default_dir() -> str | None:
    """Where the cache lives, or None when no home or cache directory is known."""
    env = os.environ.get(ENV_DIR)
    if env:
        return env
    if sys.platform == "win32":
        base = os.environ.get("LOCALAPPDATA")
    elif sys.platform == "darwin":
        base = os.path.join(os.path.expanduser("~"), "Library", "Caches")
    else:
        base = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    if not base or base.startswith("~"):
        return None
    return os.path.join(base, "physai-lint")


def code_fingerprint() -> bytes:
    """Version plus (path, size, mtime) of every producer module: cheap (a few dozen stats)."""
    from physai_lint import __version__

    root = os.path.dirname(os.path.abspath(__file__))
    h = hashlib.sha256(FORMAT + b"\0" + __version__.encode() + b"\0" + sys.version.encode())
    for item in _PRODUCERS:
        top = os.path.join(root, item)
        paths = [top] if item.endswith(".py") else sorted(
            os.path.join(d, f) for d, _, fs in os.walk(top) for f in fs if f.endswith(".py"))
        for path in paths:
            try:
                st = os.stat(path)
            except OSError:
                continue
            h.update(f"{os.path.relpath(path, root)}:{st.st_size}:{st.st_mtime_ns}\n".encode())
    for name in _THIRD_PARTY:
        h.update(f"{name}:{_package_stamp(name)}\n".encode())
    return h.digest()


def _package_stamp(name: str) -> str:
    """(file, size, mtime) of a package's top-level modules, or "" when it is not installed."""
    import importlib.util

    try:
        spec = importlib.util.find_spec(name)
    except (ImportError, ValueError):
        return ""
    if spec is None or not spec.origin:
        return ""
    top = os.path.dirname(spec.origin)
    out = []
    try:
        for f in sorted(os.listdir(top)):
            if f.endswith(".py"):
                st = os.stat(os.path.join(top, f))
                out.append(f"{f}:{st.st_size}:{st.st_mtime_ns}")
    except OSError:
        return top
    return top + ";" + ";".join(out)


class ParseCache:
    """get/put of pickled values by key; every failure is a miss, never an error."""

    def __init__(self, directory: str, fingerprint: bytes | None = None) -> None:
        self.directory = directory
        self.fingerprint = fingerprint if fingerprint is not None else code_fingerprint()
        self.enabled = True
        self.hits = self.misses = self.writes = 0

    @classmethod
    def open(cls, enabled: bool = True) -> ParseCache | None:
        if not enabled:
            return None
        directory = default_dir()
        return cls(directory) if directory else None

    def key(self, kind: str, path: str, text: str, options: str = "") -> str:
        h = hashlib.sha256(self.fingerprint)
        for part in (kind, options, path):
            h.update(part.encode("utf-8", "surrogatepass") + b"\0")
        h.update(text.encode("utf-8", "surrogatepass"))
        return h.hexdigest()

    def _path(self, key: str) -> str:
        return os.path.join(self.directory, key[:2], key[2:] + ".pickle")

    def get_bytes(self, key: str) -> bytes | None:
        if not self.enabled:
            return None
        try:
            with open(self._path(key), "rb") as fh:
                data = fh.read()
        except OSError:
            self.misses += 1
            return None
        self.hits += 1
        return data

    def get(self, key: str) -> Any | None:
        """The stored value, or None for a miss or an entry that does not unpickle."""
        data = self.get_bytes(key)
        return None if data is None else loads(data)

    def put(self, key: str, value: Any) -> None:
        """Store a value (nothing when it does not pickle)."""
        if not self.enabled:
            return
        data = dumps(value)
        if data is not None:
            self.put_bytes(key, data)

    def put_bytes(self, key: str, data: bytes) -> None:
        if not self.enabled:
            return
        target = self._path(key)
        tmp = None
        try:
            os.makedirs(os.path.dirname(target), exist_ok=True)
            fd, tmp = tempfile.mkstemp(prefix=".tmp-", dir=os.path.dirname(target))
            with os.fdopen(fd, "wb") as fh:
                fh.write(data)
            os.replace(tmp, target)
            tmp = None
            self.writes += 1
        except OSError:
            self.enabled = False  # read-only or full: run on without the cache
        finally:
            if tmp is not None:
                try:
                    os.unlink(tmp)
                except OSError:
                    pass


def dumps(value: Any) -> bytes | None:
    """Pickle a value, or None when it cannot be (then it is simply not cached)."""
    try:
        return pickle.dumps(value, protocol=pickle.HIGHEST_PROTOCOL)
    except Exception:  # noqa: BLE001 - an unpicklable value is just not cached
        return None


def loads(data: bytes) -> Any | None:
    """Unpickle a cache entry; a truncated, corrupt or stale entry is None (a miss)."""
    try:
        return pickle.loads(data)  # our own cache directory: see the module docstring
    except Exception:  # noqa: BLE001 - any corrupt entry is a miss
        return None
