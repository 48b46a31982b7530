"""``--jobs``: share parsing, resolution and the rules with forked helpers.

Parsing (``map_jobs``), resolution (``resolve_entries``) and the rules (``run_rules``) take items
from both ends of a list (``share``): this process from the front, ``jobs - 1`` forked helpers
from the back; the helpers' results come back pickled and are put in their places, so the list is
the serial loop's. Where forking is unsafe (macOS, a threaded process), parsing uses a process
pool instead and resolution and the rules stay serial.

A helper costs a fork and a pickle round trip per item, so small runs (the pre-commit case) stay
in this process: below ``MIN_PARALLEL_FILES`` files to parse, or with one job, nothing is started.
Output never depends on the number of jobs: results are returned in the order of the input, and
the caller merges them in that order.

The rules run once the project is built, in units (the rules of a shared memo together) shared
with helpers that inherit it copy-on-write and send back only their findings, from
``MIN_FORK_FILES`` parsed files on; the findings are put back in rule order, so the list is the
one a loop over the rules gives.
"""
from __future__ import annotations

import os
import struct
import sys
from collections.abc import Iterable, Iterator, Sequence
from typing import Any

# Below this many files a pool costs more than it saves (measured: forking two workers and
# shipping results back is ~40 ms; a launch file parses in 2-15 ms).
MIN_PARALLEL_FILES = 24


def default_jobs() -> int:
    """The number of CPUs this process may run on."""
    try:
        return max(1, len(os.sched_getaffinity(0)))
    except (AttributeError, OSError):
        return max(1, os.cpu_count() or 1)


def map_jobs(jobs: Sequence[Any], workers: int, progress: Any = None, side: Side | None = None
             ) -> Iterator[tuple[Any, bool, bytes | None]]:
    """``files.run_job`` over ``jobs`` as (value, cacheable, pickled value or None), always in input
    order; with ``workers`` > 1 and enough jobs, this process and ``workers - 1`` helpers share the
    work: forked helpers (``share``) where the platform forks safely, else a process pool.

    A helper's result costs this process an unpickling, one it parses itself costs nothing more.
    Forked helpers inherit the texts, so nothing is sent to them, and no thread of this process has
    to feed them: with a ``ProcessPoolExecutor`` the parent's feeder and manager threads waited
    for the GIL while it parsed, its one worker sat idle 40% of the time, and two jobs parsed the
    1,180-file workspace no faster than one (1.0 s either way; forked: 0.7-0.8 s).

    ``side``: other items shared in the same fork when helpers are forked (``Side``), marked done;
    otherwise left to the caller."""
    from physai_lint.files import run_job

    jobs = list(jobs)
    if workers <= 1 or len(jobs) < MIN_PARALLEL_FILES:
        for job in jobs:
            value, cacheable = run_job(job, None)
            yield value, cacheable, None
            if progress is not None:
                progress.advance()
        return
    if _can_fork(workers, len(jobs), MIN_PARALLEL_FILES):
        yield from _forked_jobs(jobs, workers - 1, progress, side)
        return
    pool = _pool(workers - 1)
    if pool is None:
        yield from map_jobs(jobs, 1, progress)
        return
    yield from _shared(jobs, pool, workers, progress)


def _forked_jobs(jobs: list[Any], helpers: int, progress: Any, side: Side | None = None
                 ) -> Iterator[tuple[Any, bool, bytes | None]]:
    """``map_jobs`` with forked helpers (``share``): they inherit the jobs, texts included, so only
    their pickled results travel, and no thread of this process has to feed them. The items of
    ``side`` follow the jobs in the same share: the helpers, working from the back, do them first."""
    from physai_lint.cache import dumps, loads
    from physai_lint.files import run_job

    m = len(jobs)
    out: list[tuple[Any, bool, bytes | None] | None] = [None] * m
    # The helpers work from the back: give them the jobs whose results are cheapest to send back
    # for the parsing they save (``_TRAVEL_ORDER``); results still come out in input order.
    order = sorted(range(m), key=lambda i: _travel_rank(jobs[i]))

    def local(k: int) -> None:
        i = order[k]
        value, cacheable = run_job(jobs[i], None)
        out[i] = (value, cacheable, None)
        if progress is not None:
            progress.advance()

    def remote(k: int) -> bytes | None:
        value, cacheable = run_job(jobs[order[k]], None)
        data = dumps(value)
        return None if data is None else (b"+" if cacheable else b"-") + data

    def accept(k: int, payload: bytes) -> bool:
        data = payload[1:]
        value = loads(data)
        if value is None:
            return False
        out[order[k]] = (value, payload[:1] == b"+", data)
        if progress is not None:
            progress.advance()
        return True

    _share_with_side(m, local, remote, accept, helpers, side)
    yield from out  # type: ignore[misc]  # every item is filled by share


# What a parse result costs to send back (pickle there, unpickle here) against the parsing it
# saves, per kind of file, on the 1,180-file real workspace: parameter files 0.71 (libyaml is
# fast, the model has a position on every value), XML launch files 0.56 (positions, element
# trees), Python launch files 0.18 (libcst/ast and our evaluation are slow, the IR small). Ranks
# in that order: this process keeps the first, the helpers take from the back.
_TRAVEL_ORDER = {"params": 0, "xml": 1, "yaml": 1, "python": 2}


def _travel_rank(job: Any) -> int:
    from physai_lint.sniff import launch_format

    kind = getattr(job, "kind", None)
    if kind != "params":
        kind = launch_format(getattr(job, "path", "") or "", getattr(job, "text", None))
    return _TRAVEL_ORDER.get(kind or "", 1)


def _shared(jobs: list[Any], pool: Any, workers: int, progress: Any
            ) -> Iterator[tuple[Any, bool, bytes | None]]:
    """``map_jobs`` with a pool (platforms without a safe fork): the pool takes chunks from the
    front while this process takes them from the back (it cancels a chunk's future before running
    it itself), until they meet."""
    from concurrent.futures.process import BrokenProcessPool

    from physai_lint.cache import loads
    from physai_lint.files import run_job

    size = max(1, min(4, len(jobs) // (workers * 8)))  # small: the last chunks are waited for
    chunks = [jobs[i:i + size] for i in range(0, len(jobs), size)]
    done: list[list[tuple[Any, bool, bytes | None]] | None] = [None] * len(chunks)

    def local(k: int) -> None:
        out: list[tuple[Any, bool, bytes | None]] = []
        for job in chunks[k]:
            value, cacheable = run_job(job, None)
            out.append((value, cacheable, None))
            if progress is not None:
                progress.advance()
        done[k] = out

    def harvest(k: int) -> None:
        """Chunk ``k`` from its worker (waiting for it); parsed here when it cannot come back."""
        try:
            results = futures[k].result()
        except (BrokenProcessPool, OSError):
            local(k)
            return
        out: list[tuple[Any, bool, bytes | None]] = []
        for job, (data, cacheable) in zip(chunks[k], results):
            value = loads(data) if data is not None else None
            if value is None:  # could not travel back: parse it here instead
                value, cacheable = run_job(job, None)
                data = None
            out.append((value, cacheable, data))
            if progress is not None:
                progress.advance()
        done[k] = out

    try:
        try:
            futures = [pool.submit(_work_chunk, chunk) for chunk in chunks]
        except (BrokenProcessPool, OSError, RuntimeError):
            futures = []
        front, back = 0, len(futures) - 1
        while front <= back:
            if futures[front].done():
                harvest(front)
                front += 1
            elif futures[back].cancel():
                local(back)
                back -= 1
            else:  # the pool has started every chunk left: wait for them
                for k in range(front, back + 1):
                    harvest(k)
                break
        for k in range(len(chunks)):
            if done[k] is None:  # the pool could not even take it
                local(k)
    finally:
        pool.shutdown(wait=True, cancel_futures=True)
    for out in done:
        yield from out or ()


def _pool(workers: int) -> Any:
    """A process pool, or None when this platform cannot start one (then: serial)."""
    import multiprocessing
    from concurrent.futures import ProcessPoolExecutor

    methods = multiprocessing.get_all_start_methods()
    # fork inherits the already imported frontends (no re-import per worker); elsewhere spawn.
    method = "fork" if "fork" in methods and sys.platform != "darwin" else "spawn"
    try:
        return ProcessPoolExecutor(workers, mp_context=multiprocessing.get_context(method))
    except (OSError, ValueError, ImportError, NotImplementedError):
        return None


def _work_chunk(chunk: list[Any]) -> list[tuple[bytes | None, bool]]:
    """In a worker: parse and pickle here, so the parent only unpickles (and can cache the bytes)."""
    from physai_lint.cache import dumps
    from physai_lint.files import run_job

    out = []
    for job in chunk:
        value, cacheable = run_job(job, None)
        out.append((dumps(value), cacheable))
    return out


# ---- the rules: units of rules shared with forked helpers --------------------------------------

# Below this many parsed files (launch and parameter files) the rules run in this process: the
# fork, the copy-on-write faults and a process that may wait for a CPU cost about what a second
# process saves. Measured on 2 CPUs, each half of the rules in a fork (synthetic workspaces; serial ->
# slower half): 16 files 28 -> 20 ms, 32 files 37 -> 25 ms, 64 files 65 -> 38 ms, 128 files
# 106 -> 49 ms; forking costs 2-9 ms (30-130 MB processes). A one-file run (its includes and
# parameter files) stays under it. PHYSAI_LINT_FORK_MIN_FILES overrides it (tests lower it).
MIN_FORK_FILES = 64
FORK_MIN_ENV = "PHYSAI_LINT_FORK_MIN_FILES"

# Rules that fill or read the same memo form one unit, run in one process (else each builds it):
# - checks/topics.graphs: the topic graphs of every launch (ctx.options["_graphs"]);
# - checks/_params.effective: the effective parameters of each node (ctx.options["_effective"]).
# The node interfaces (ctx.interfaces: the C++ and Python sources of an executable, extracted the
# first time a node of it is asked about), which both families ask for, are extracted before the
# rules are shared (``prefetch_interfaces``), so the two families can run in different processes.
# Cheap memos are built again in each process instead: package manifests read on first use
# (ctx.packages), close-match suggestions and parameter typing (module lru_caches).
# A rule missing from here is still right, only slower: it builds what it needs itself.
SHARED_MEMOS: tuple[tuple[int, tuple[str, ...]], ...] = (
    # (what the memo costs, in the units of RULE_COST, to add to its rules' own; the rules)
    (100, ("N104", "T102", "T103", "T104", "T201", "T202", "T203", "T204")),  # graphs
    (80, ("P105", "P107", "P108", "P109", "P111", "P112")),  # effective parameters
    (45, ("L114", "U104")),  # every model object of each launch file (checks._util.ir_objects)
)
# Rules that ask those memos about a few nodes only (lifecycle and controller managers, the target of a
# "ros2 param" command, the targets of OnProcessExit handlers): they compute these few wherever they run.
LIGHT_MEMO_USERS = frozenset({"P110", "S101", "S104", "S106", "S201", "S202", "S204"})

# A static cost per rule: about its milliseconds on the real-workspace benchmark (1,180 files,
# interfaces prefetched, medians of four -j2 runs; S101 imports networkx only for a launch whose
# startup edges close a cycle); a rule not listed costs DEFAULT_COST. Only the order of the
# units (and so the balance of the processes) depends on these numbers, never the findings.
RULE_COST: dict[str, int] = {
    "U101": 107, "L101": 101, "L106": 82, "P111": 78, "N104": 50, "P112": 42, "L102": 38, "U102": 30,
    "N106": 28, "U104": 26, "U103": 23, "T104": 22, "N105": 22, "T102": 21, "L002": 21, "L114": 17,
    "N102": 14, "L001": 13, "S101": 13, "T101": 12, "P107": 12, "L108": 12, "P105": 10, "P108": 10,
    "T201": 8, "T203": 8, "P103": 8, "T202": 7, "L110": 6, "N103": 5, "L003": 5,
}
DEFAULT_COST = 3
# A rule's memo family (a key shared by its members) and what the family's memo costs.
_FAMILY = {c: f"memo {f}" for f, (_, members) in enumerate(SHARED_MEMOS) for c in members}
_MEMO_COST = {c: cost for cost, members in SHARED_MEMOS for c in members}


def _fork_min_files() -> int:
    try:
        return max(0, int(os.environ.get(FORK_MIN_ENV, MIN_FORK_FILES)))
    except ValueError:
        return MIN_FORK_FILES


def plan_units(codes: Sequence[str]) -> list[list[int]]:
    """Rules (by their codes, in run order) as units of indexes into ``codes``: the rules of a
    shared memo together, each other rule alone; heaviest first by static cost (``unit_cost``;
    ties: run order), each unit in run order."""
    units: dict[str, list[int]] = {}
    for i, code in enumerate(codes):
        units.setdefault(_FAMILY.get(code, code), []).append(i)
    return sorted(units.values(), key=lambda idx: (-unit_cost(codes, idx), idx[0]))


def unit_cost(codes: Sequence[str], unit: Sequence[int]) -> int:
    """The static cost of a unit of ``plan_units``: its rules' and their shared memo's."""
    own = sum(RULE_COST.get(codes[i], DEFAULT_COST) for i in unit)
    return own + max((_MEMO_COST.get(codes[i], 0) for i in unit), default=0)


def run_rules(rules: Sequence[tuple[str, Any]], run_one: Any, jobs: int, progress: Any = None,
              files: int = 0) -> list[Any]:
    """``run_one(code, impl)`` (a list of findings; it never raises) for every rule, concatenated in
    the order of ``rules``: exactly what a loop over them returns.

    With more than one job, a platform that forks, and at least ``MIN_FORK_FILES`` parsed
    ``files``, the units of rules (``plan_units``) are shared (``share``) between this process,
    which runs them heaviest first, and forked helpers, which inherit the project copy-on-write,
    run them lightest first and send back only their pickled findings; no more helpers than the
    heaviest unit leaves work for. Shared rather than split in fixed groups: while both run, a
    forked helper ran the same rules 1.3-1.6 times slower than this process (copy-on-write faults
    on its first touch of each page, and a second CPU that gives more or less from one minute to
    the next), so groups fixed by static costs left one process idle for 0.1-0.25 s of a
    0.5-0.7 s stage. A helper that
    dies, or whose findings do not come back whole, leaves its units to this process: findings
    are never lost."""
    codes = [c for c, _ in rules]
    results: list[list[Any] | None] = [None] * len(rules)
    units = plan_units(codes) if _can_fork(jobs, files) else []
    helpers = 0
    if len(units) > 1:
        costs = [unit_cost(codes, u) for u in units]
        helpers = min(jobs - 1, len(units) - 1, max(1, sum(costs) // max(1, costs[0]) - 1))
    if helpers > 0:
        _share_rules(rules, run_one, units, results, progress, helpers)
    for i, (code, impl) in enumerate(rules):
        if results[i] is None:  # not shared
            if progress is not None:
                progress.advance()
            results[i] = run_one(code, impl)
    return [d for found in results for d in found]  # type: ignore[union-attr]


def _share_rules(rules: Sequence[tuple[str, Any]], run_one: Any, units: list[list[int]],
                 results: list[list[Any] | None], progress: Any, helpers: int) -> None:
    """``run_rules``'s units through ``share_values``: fills ``results`` for every rule."""

    def local(k: int) -> None:
        for i in units[k]:
            results[i] = run_one(*rules[i])
            if progress is not None:
                progress.advance()

    def take(k: int, found: Any) -> bool:
        if not isinstance(found, list) or len(found) != len(units[k]) or \
                not all(isinstance(f, list) for f in found):
            return False
        for i, f in zip(units[k], found):
            results[i] = f
            if progress is not None:
                progress.advance()
        return True

    share_values(len(units), local, lambda k: [run_one(*rules[i]) for i in units[k]], take, helpers)


def _can_fork(jobs: int, files: int, least: int | None = None) -> bool:
    """Whether to fork helpers: ``jobs`` > 1, at least ``least`` ``files`` (default
    ``MIN_FORK_FILES``, or its environment override), and a platform and process that fork safely."""
    import threading

    least = _fork_min_files() if least is None else least
    return (jobs > 1 and files >= least and hasattr(os, "fork")
            and sys.platform != "darwin"  # as for the parse pool: fork is unsafe there
            and threading.active_count() == 1)  # forking a threaded process can deadlock the child


def _freeze_gc() -> Any:
    """Freeze the objects alive now (unless the caller already has): a forked process's collector
    never visits them, so their pages stay shared instead of being copied by a collection.
    Returns the function that undoes it."""
    import gc

    if gc.get_freeze_count():
        return lambda: None
    gc.freeze()
    return gc.unfreeze


# ---- resolution: entries shared with forked helpers ---------------------------------------------

# Below this many entries to resolve, they are resolved here: a launch entry resolves in 1-30 ms
# (a few reach 0.1-0.4 s), and the fork, the helper's warming of the module caches (parameter
# files that nav2's RewrittenYaml rewrites) and the unpickling of its results cost about that.
MIN_FORK_ENTRIES = 16
# Entries that include nothing (``leaves``) resolve in ~0.2 ms each (the real workspace's 264:
# 0.06 s), less than a fork costs: the helper's start, and a round of copy-on-write faults in
# both processes (~6,000 there, and each later stage's pages copied again).
MIN_FORK_LEAVES = 512


def resolve_entries(entries: Sequence[str], resolve: Any, store: Any, load: Any, jobs: int,
                    progress: Any = None, files: int = 0, leaves: bool = False,
                    side: Side | None = None) -> list[Any]:
    """``[resolve(e) for e in entries]``, in the order of ``entries``.

    With more than one job, a platform that forks, at least ``MIN_FORK_FILES`` parsed ``files``
    and enough entries (``_enough_entries``: ``MIN_FORK_ENTRIES`` that include something, or
    ``MIN_FORK_LEAVES`` in all), ``jobs - 1`` forked helpers resolve entries from the back of
    the list while this process resolves them from the front, until they meet (``share``); a helper
    sends each result back pickled, with the launch files it had to parse on the way
    (``store.launches`` gained them), which this process then ``load``s too, so that its file store
    ends as a serial run leaves it. Entries resolve independently of each other (each has its own
    ``Instantiator``; the module caches are keyed by content), so the results are those of the
    serial loop. An entry a helper took but whose result does not come back whole is resolved
    here. ``side``: other items shared in the same fork when it forks (``Side``), marked done."""
    entries = list(entries)
    if not _enough_entries(entries, store, leaves) or not _can_fork(jobs, files):
        out = []
        for entry in entries:
            if progress is not None:
                progress.advance()
            out.append(resolve(entry))
        return out
    return _resolve_shared(entries, resolve, store, load, progress, jobs - 1, side)


def _enough_entries(entries: list[str], store: Any, leaves: bool) -> bool:
    """Whether ``entries`` are worth a fork: ``MIN_FORK_LEAVES`` of them, or ``MIN_FORK_ENTRIES``
    that include something (unless they are all ``leaves``; an entry not parsed yet counts as
    one that includes). Leaves ride along with the includers (``resolve.roots.choose_roots``) but
    do not make a fork worth it on their own."""
    if len(entries) >= MIN_FORK_LEAVES:
        return True
    if leaves or len(entries) < MIN_FORK_ENTRIES:
        return False
    from physai_lint.resolve.roots import has_include

    parsed = getattr(store, "launches", {})
    heavy = 0
    for entry in entries:
        lf = parsed.get(entry)
        heavy += lf is None or has_include(lf)
        if heavy >= MIN_FORK_ENTRIES:
            return True
    return False


def _resolve_shared(entries: list[str], resolve: Any, store: Any, load: Any, progress: Any,
                    helpers: int, side: Side | None = None) -> list[Any]:
    # What resolution imports on first use, imported once here for the helpers to inherit.
    from importlib import import_module

    for module in ("includes", "nav2_common", "safe_eval"):
        import_module(f"physai_lint.resolve.{module}")

    n = len(entries)
    results: list[Any] = [None] * n

    def local(i: int) -> None:
        if progress is not None:
            progress.advance()
        results[i] = resolve(entries[i])

    def compute(i: int) -> Any:
        known = len(store.launches)
        result = resolve(entries[i])
        return result, list(store.launches)[known:]

    def take(i: int, value: Any) -> bool:
        result, loaded = value
        for path in loaded:  # what the helper parsed on the way: parsed here too
            load(path)
        results[i] = result
        if progress is not None:
            progress.advance()
        return True

    _share_with_side(n, local, *_value_io(compute, take), helpers, side)
    return results


# ---- workspace packages: read before resolution, shared with forked helpers ------------------

# Below this many packages, they are read (and their interfaces extracted) in this process, when
# first asked for: a package reads in 1-3 ms, and its C++ sources extract in 1-30 ms (nav2's
# controller and planner servers ~0.1 s); a helper costs a fork and its copy-on-write faults.
MIN_FORK_PACKAGES = 8


def package_reads(index: Any, names: Sequence[str], jobs: int, files: int = 0) -> Side | None:
    """The reading of the workspace packages ``names`` (``index.packages[name]``: the manifest, the
    CMakeLists.txt or setup.py, a listing of the files) as items to share with forked helpers, to
    be done before resolution asks for them (``Side.run``, or along with the parsing: ``map_jobs``);
    None when the conditions of ``run_rules``'s fork are not met (they are read when first asked for).

    The engine reads every package that holds a checked file anyway (their manifests' problems are
    reported), but lazily: a package a resolution helper read was read there only, and this process
    read it again at the end, alone (~0.2 s of 281 packages on the 1,180-file workspace). Read
    before, resolution and the rules of every process find them read. A helper sends back each
    package pickled with the problems and notes its reading added (``index.adopt_package``)."""
    if not _can_fork(jobs, files) or len(names) < MIN_FORK_PACKAGES:
        return None
    names = list(names)

    def local(i: int) -> None:
        index.packages.get(names[i])

    def take(i: int, read: Any) -> bool:
        return _adopt(index, names[i], read)

    return Side(len(names), local, lambda i: index.read_package_elsewhere(names[i]), take, jobs - 1)


def _adopt(index: Any, name: str, read: Any) -> bool:
    """``index.adopt_package(name, read)`` for what ``read_package_elsewhere`` returned in a
    helper; False when it did not come back as that."""
    if not isinstance(read, tuple) or len(read) != 3:
        return False
    index.adopt_package(name, read)
    return True


# ---- node interfaces: extracted before the rules, shared with forked helpers -----------------

def prefetch_interfaces(interfaces: Any, keys: Sequence[tuple[str, str]], jobs: int,
                        files: int = 0) -> None:
    """``interfaces.get(package, executable)`` for ``keys`` before the rules ask, shared with
    forked helpers (``share``) under the conditions of ``run_rules``'s fork; otherwise nothing
    (the rules ask the store lazily, as before).

    Extracting the interfaces of the executables that nodes run (their C++ and Python sources) is
    about half of the rules' time on a large workspace, and every rule that compares topics or
    parameters with declarations asks for them: done here on every CPU, the rules' forked helpers
    inherit the filled store, so those rules no longer need to run in one process. Items are whole
    packages (executables of a package share sources and their tokens); a helper sends back each
    package's interfaces pickled, which ``interfaces.prime`` takes as if asked here. An interface is
    a pure function of the package index and the sources, so the rules see the same values.
    Keys already extracted (``interface_side``) are left out."""
    side = interface_side(interfaces, keys, jobs, files)
    if side is not None:
        side.run()


def interface_side(interfaces: Any, keys: Iterable[tuple[str, str]], jobs: int, files: int = 0
                   ) -> Side | None:
    """``prefetch_interfaces`` as items to share (``Side``): the resolution share takes them along
    (``resolve_entries``), with the keys the parsed launch files name; the helpers, working from the
    back, extract them first while this process resolves. A package's interfaces are about 3 kB to
    send back for 5-30 ms of extraction, a resolved entry ~100-300 kB for the same time: the
    helpers resolve fewer entries, fewer bytes travel, and the rules' own prefetch (one more fork
    and wait) is left with the keys nobody predicted. None below the conditions of a fork."""
    if not _can_fork(jobs, files):
        return None
    by_package: dict[str, list[tuple[str, str]]] = {}
    for key in sorted(set(keys)):
        if not interfaces.cached(key):
            by_package.setdefault(key[0], []).append(key)
    items = list(by_package.values())
    if len(items) < MIN_FORK_PACKAGES:
        return None
    index: Any = getattr(interfaces, "packages", None)
    adopts = hasattr(index, "unread") and hasattr(index, "adopt_package")

    def local(i: int) -> None:
        for package, executable in items[i]:
            interfaces.get(package, executable)

    def compute(i: int) -> tuple[list[Any], Any]:
        # Extraction reads the package (its build rules name the sources): sent back too, else
        # the rules read it again (U102 asks for its executables), in whichever process runs them.
        package = items[i][0][0]
        read = index.read_package_elsewhere(package) if adopts and index.unread(package) else None
        return [interfaces.get(p, e) for p, e in items[i]], read

    def take(i: int, value: Any) -> bool:
        if not isinstance(value, tuple) or len(value) != 2:
            return False
        values, read = value
        if not isinstance(values, list) or len(values) != len(items[i]) or \
                read is not None and not _adopt(index, items[i][0][0], read):
            return False
        for key, one in zip(items[i], values):
            interfaces.prime(key, one)
        return True

    return Side(len(items), local, compute, take, jobs - 1)


# ---- sharing a list of items with forked helpers --------------------------------------------------

def share_values(n: int, local: Any, compute: Any, take: Any, helpers: int) -> None:
    """``share`` for items whose helper-side result is a value: ``compute(i)`` there, pickled (an
    item whose computing raises or whose value does not pickle is done here), and ``take(i, value)``
    here once unpickled (False, or a value that does not unpickle: done here)."""
    share(n, local, *_value_io(compute, take), helpers)


def _value_io(compute: Any, take: Any) -> tuple[Any, Any]:
    """``share_values``' ``remote`` and ``accept``."""
    import pickle

    def remote(i: int) -> bytes | None:
        try:
            return pickle.dumps(compute(i), protocol=pickle.HIGHEST_PROTOCOL)
        except Exception:  # noqa: BLE001 - this process does this item itself
            return None

    def accept(i: int, data: bytes) -> bool:
        try:
            value = pickle.loads(data)
        except Exception:  # noqa: BLE001 - done here instead
            return False
        return bool(take(i, value))

    return remote, accept


class Side:
    """Items to share (``share_values``) that may ride along with another share: ``map_jobs`` and
    ``resolve_entries`` take them into their fork when they fork, which saves a fork, its copy-on-write faults and a wait for
    the slower process; ``run`` does them alone otherwise. ``done`` once either has."""

    def __init__(self, n: int, local: Any, compute: Any, take: Any, helpers: int) -> None:
        self.n, self.local, self.compute, self.take, self.helpers = n, local, compute, take, helpers
        self.done = False

    def run(self) -> None:
        """Share the items now, unless a share took them along."""
        if not self.done:
            self.done = True
            share_values(self.n, self.local, self.compute, self.take, self.helpers)


def _share_with_side(n: int, local: Any, remote: Any, accept: Any, helpers: int, side: Side | None) -> None:
    """``share`` of items ``0..n-1`` followed by the items of ``side`` (unless done; marked done):
    the helpers, working from the back, do the side's first."""
    if side is None or side.done:
        share(n, local, remote, accept, helpers)
        return
    side.done = True
    side_remote, side_accept = _value_io(side.compute, side.take)

    def local_or_side(k: int) -> None:
        if k >= n:
            side.local(k - n)
        else:
            local(k)

    def remote_or_side(k: int) -> bytes | None:
        return side_remote(k - n) if k >= n else remote(k)  # type: ignore[no-any-return]

    def accept_or_side(k: int, data: bytes) -> bool:
        return bool(side_accept(k - n, data) if k >= n else accept(k, data))

    share(n + side.n, local_or_side, remote_or_side, accept_or_side, helpers)


def share(n: int, local: Any, remote: Any, accept: Any, helpers: int) -> None:
    """Items ``0..n-1``, each done once: ``local(i)`` in this process, which works from the front,
    or, for items that ``helpers`` forked processes claim from the back, ``remote(i)`` there (bytes,
    or None when the item cannot travel) and ``accept(i, bytes)`` here (False: not taken in).

    The helpers inherit everything copy-on-write, so nothing is sent to them; each writes (index,
    size, bytes) frames to a file of its own (in memory where the platform has memfd) and publishes
    how far it has written, and this process takes frames in between its own items. The claims
    live in shared memory: this process alone moves the front, the helpers the back (under a lock
    when there are several), each publishing its claim before working on it; at the meeting point
    an item may be claimed twice (this process keeps its own), never by no one. An item whose
    frame does not come back whole, or is not accepted, is done here: a helper that dies loses
    nothing. Without fork, a file or shared memory, everything is done here, in order.
    """
    import mmap

    helpers = max(0, min(helpers, n - 1))
    fds: list[int] = []
    lock: int | None = None
    shared: Any = None
    pids: list[int] = []
    try:
        while len(fds) < helpers:
            fd = _scratch_file("physai-lint-share")
            if fd is None:
                break
            fds.append(fd)
        if len(fds) > 1:
            lock = _scratch_file("physai-lint-claims")
            if lock is None or not _lockable(lock):  # no lock between helpers: just one
                if lock is not None:
                    os.close(lock)
                    lock = None
                for fd in fds[1:]:
                    os.close(fd)
                del fds[1:]
        if fds:
            try:
                # [front, back, bytes written by helper 0, by helper 1, ...]
                shared = mmap.mmap(-1, (2 + len(fds)) * _COUNTER.size)
            except OSError:
                shared = None
        if shared is None:
            for i in range(n):
                local(i)
            return
        _put(shared, 0, 0)
        # Helper h starts on item n-1-h, claimed for it before the forks: it does at least that
        # one however late it gets a CPU (if its fork fails, this process does it at the end).
        _put(shared, 1, n - len(fds))
        thaw = _freeze_gc()
        try:
            for h, fd in enumerate(fds):
                try:
                    pid = os.fork()
                except OSError:
                    break
                if pid == 0:  # a helper: never returns
                    _helper(h, remote, shared, fd, lock, n - 1 - h)
                pids.append(pid)
            _share_here(n, local, accept, shared, fds[:len(pids)], pids)  # waits for them all
        finally:
            thaw()
    finally:
        for pid in pids:  # interrupted: stop the helpers
            import signal

            try:
                os.kill(pid, signal.SIGKILL)
                os.waitpid(pid, 0)
            except OSError:
                pass
        for fd in fds:
            os.close(fd)
        if lock is not None:
            os.close(lock)
        if shared is not None:
            shared.close()


def _share_here(n: int, local: Any, accept: Any, shared: Any, fds: list[int], pids: list[int]) -> None:
    """This process's side of ``share``: claim from the front and take in the helpers' frames;
    ``pids`` is emptied once every helper has been waited for (``share`` kills those left)."""
    done = [False] * n
    mine = [False] * n
    offsets = [0] * len(fds)

    def merge() -> None:
        for h, fd in enumerate(fds):
            end = _get(shared, 2 + h)
            offset = offsets[h]
            while offset + _FRAME.size <= end:
                i, size = _FRAME.unpack(os.pread(fd, _FRAME.size, offset))
                data = os.pread(fd, size, offset + _FRAME.size) if size else b""
                offset += _FRAME.size + size
                if 0 <= i < n and not done[i] and not mine[i] and len(data) == size and accept(i, data):
                    done[i] = True
            offsets[h] = offset

    if pids:
        while True:
            merge()
            front, back = _get(shared, 0), _get(shared, 1)
            if front >= back:
                break
            _put(shared, 0, front + 1)
            mine[front] = True
            local(front)
            done[front] = True
        for pid in pids:
            try:
                os.waitpid(pid, 0)
            except OSError:
                pass
        pids.clear()
        merge()
    for i in range(n):  # the helpers' items that did not come back (or no helper at all)
        if not done[i]:
            local(i)


def _helper(h: int, remote: Any, shared: Any, fd: int, lock: int | None, first: int) -> None:
    """In forked helper ``h``: item ``first`` (claimed for it), then items claimed from the back;
    write (index, size, bytes) frames to ``fd``, publish the bytes written after each one."""
    status = 1
    try:
        written = 0
        i: int | None = first
        while i is not None:
            data = remote(i)
            if data is not None:  # else it cannot travel: the parent does this one itself
                frame = _FRAME.pack(i, len(data)) + data
                view = memoryview(frame)
                while view:
                    view = view[os.write(fd, view):]
                written += len(frame)
                _put(shared, 2 + h, written)
            i = _claim_back(shared, lock)
        status = 0
    except BaseException:  # noqa: BLE001, S110 - the parent does what did not come back
        pass
    finally:
        os._exit(status)


def _claim_back(shared: Any, lock: int | None) -> int | None:
    """The next item from the back, or None once the claims have met."""
    if lock is not None:
        import fcntl

        fcntl.lockf(lock, fcntl.LOCK_EX)  # a POSIX record lock: released if the helper dies
    try:
        back, front = _get(shared, 1), _get(shared, 0)
        if back - 1 < front:
            return None
        _put(shared, 1, back - 1)
        return back - 1
    finally:
        if lock is not None:
            fcntl.lockf(lock, fcntl.LOCK_UN)


def _lockable(fd: int) -> bool:
    try:
        import fcntl

        fcntl.lockf(fd, fcntl.LOCK_EX)
        fcntl.lockf(fd, fcntl.LOCK_UN)
        return True
    except (ImportError, OSError):
        return False


def _scratch_file(name: str) -> int | None:
    """A file descriptor for a helper's results: in memory where the platform has memfd."""
    try:
        return os.memfd_create(name, getattr(os, "MFD_CLOEXEC", 0))
    except (AttributeError, OSError):
        pass
    try:
        import tempfile

        with tempfile.TemporaryFile() as fh:
            return os.dup(fh.fileno())  # the file lives on while this descriptor is open
    except OSError:
        return None


def _put(shared: Any, slot: int, value: int) -> None:
    _COUNTER.pack_into(shared, slot * _COUNTER.size, value)


def _get(shared: Any, slot: int) -> int:
    return int(_COUNTER.unpack_from(shared, slot * _COUNTER.size)[0])


_COUNTER = struct.Struct("<q")  # one slot of the shared page
_FRAME = struct.Struct("<II")  # a helper result's header: entry index, pickle size
