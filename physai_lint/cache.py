"""A content-addressed disk cache for per-file parse results.

Only results that are pure functions of one file's bytes (and of the path and options named in
the key) are stored: a launch file's IR and parse diagnostics, a parameter file's model, what one
C++ source declares (``interfaces/extract_cpp.py``), a package.xml's manifest data and problem,
a CMakeLists.txt's build data (``workspace/index.py``; with the digests of the subdirectory
CMakeLists.txt files it read, checked on every hit). Nothing that depends on other files
(resolution, includes, findings) or on directory listings is cached here.

Layout: ``<dir>/v2-<16 hex>/<2 hex>/<62 hex>.pickle``: one folder per generation (the first 16
hex digits of the code fingerprint), the name being the SHA-256 of (code fingerprint, kind,
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

The cache keeps itself bounded (``ParseCache.prune``, at most once a day, on opening): entries of
other generations (older or other installs of physai-lint, and the flat layout of format 1) go
once they are a week old, and when everything together exceeds ``$PHYSAI_LINT_CACHE_MAX_MB``
(default 512; the space the files take on disk) the least recently written entries go until it
is under four fifths of that. Only files with the names this module writes are ever removed, so
a cache directory pointed at the wrong folder loses nothing else.
"""
from __future__ import annotations

import hashlib
import os
import pickle
import re
import sys
import tempfile
import time
from typing import Any

ENV_DIR = "PHYSAI_LINT_CACHE_DIR"
ENV_MAX_MB = "PHYSAI_LINT_CACHE_MAX_MB"
FORMAT = b"physai-lint parse cache 2"
GENERATION_PREFIX = "v2-"
DEFAULT_MAX_MB = 512
PRUNE_EVERY = 24 * 3600  # seconds between two prunes of one cache directory
STALE_AFTER = 7 * 24 * 3600  # age at which another generation's entries go
TMP_STALE = 3600  # age at which a temporary file is an interrupted write, not one in progress
_STAMP = ".last-prune"  # its modification time: when the directory was last pruned
_GENERATION = re.compile(r"v\d+-[0-9a-f]{16}")
_SHARD = re.compile(r"[0-9a-f]{2}")
_ENTRY = re.compile(r"[0-9a-f]{62}\.pickle")
# Modules whose code decides what a cached value looks like (relative to the package).
_PRODUCERS = ("files.py", "sniff.py", "cache.py", "frontends", "params", "model", "interfaces", "workspace")
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
        self.root = directory
        self.fingerprint = fingerprint if fingerprint is not None else code_fingerprint()
        self.generation = GENERATION_PREFIX + self.fingerprint.hex()[:16]
        self.directory = os.path.join(directory, self.generation)
        self.enabled = True
        self.hits = self.misses = self.writes = 0

    @classmethod
    def open(cls, enabled: bool = True) -> ParseCache | None:
        if not enabled:
            return None
        directory = default_dir()
        if not directory:
            return None
        cache = cls(directory)
        cache.prune()
        return cache

    def prune(self, now: float | None = None, force: bool = False) -> int:
        """Bound the cache directory (see the module docstring); returns the entries removed.

        Does nothing when the directory was pruned less than ``PRUNE_EVERY`` ago (one ``stat`` per
        run), unless ``force``. Never fails: what cannot be listed or removed stays."""
        now = time.time() if now is None else now
        stamp = os.path.join(self.root, _STAMP)
        try:
            if not force and now - os.stat(stamp).st_mtime < PRUNE_EVERY:
                return 0
        except OSError:
            if not os.path.isdir(self.root):
                return 0  # nothing written yet
        try:  # claim this prune first: concurrent runs then mostly skip it
            with open(stamp, "ab"):
                pass
            os.utime(stamp, (now, now))
        except OSError:
            return 0
        entries, folders = _entries(self.root)
        removed = 0
        kept: list[tuple[float, int, str]] = []
        for mtime, size, path, generation, temporary in entries:
            age = now - mtime
            if (temporary and age > TMP_STALE) or (generation != self.generation and age > STALE_AFTER):
                removed += _remove(path)
            elif not temporary:
                kept.append((mtime, size, path))
        limit = _max_bytes()
        total = sum(size for _, size, _ in kept)
        if total > limit:
            for _, size, path in sorted(kept):
                if total <= limit * 4 // 5:
                    break
                if _remove(path):
                    removed += 1
                    total -= size
        for folder in folders:  # those left empty (a folder with anything in it stays)
            try:
                os.rmdir(folder)
            except OSError:
                pass
        return removed

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
        folder = os.path.dirname(target)
        try:
            os.makedirs(folder, exist_ok=True)
            try:
                fd, tmp = tempfile.mkstemp(prefix=".tmp-", dir=folder)
            except FileNotFoundError:  # another run's prune removed the folder it found empty
                os.makedirs(folder, exist_ok=True)
                fd, tmp = tempfile.mkstemp(prefix=".tmp-", dir=folder)
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


def _max_bytes() -> int:
    try:
        return max(0, int(os.environ.get(ENV_MAX_MB, DEFAULT_MAX_MB))) * 2**20
    except ValueError:
        return DEFAULT_MAX_MB * 2**20


def _subdirs(path: str) -> list[tuple[str, str]]:
    """(name, path) of the folders in ``path``, sorted; links to folders are not folders here."""
    try:
        with os.scandir(path) as it:
            return sorted((e.name, e.path) for e in it if e.is_dir(follow_symlinks=False))
    except OSError:
        return []


def _entries(root: str) -> tuple[list[tuple[float, int, str, str | None, bool]], list[str]]:
    """(mtime, size, path, generation or None for the flat format-1 layout, temporary) of every
    file this module may have written below ``root``, and the shard and generation folders that
    hold them (each shard before its generation: the order to remove them in once empty)."""
    files: list[tuple[float, int, str, str | None, bool]] = []
    folders: list[str] = []

    def shards(path: str, generation: str | None) -> None:
        for name, shard in _subdirs(path):
            if not _SHARD.fullmatch(name):
                continue
            folders.append(shard)
            try:
                with os.scandir(shard) as it:
                    for e in it:
                        temporary = e.name.startswith(".tmp-")
                        if not (temporary or _ENTRY.fullmatch(e.name)) or not e.is_file(follow_symlinks=False):
                            continue
                        try:
                            st = e.stat(follow_symlinks=False)
                        except OSError:  # removed meanwhile
                            continue
                        # the space it takes on disk where the platform says (small files fill a block)
                        size = getattr(st, "st_blocks", 0) * 512 or st.st_size
                        files.append((st.st_mtime, size, e.path, generation, temporary))
            except OSError:
                continue

    shards(root, None)
    for name, path in _subdirs(root):
        if _GENERATION.fullmatch(name):
            shards(path, name)
            folders.append(path)
    return files, folders


def _remove(path: str) -> int:
    try:
        os.unlink(path)
        return 1
    except OSError:
        return 0


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
