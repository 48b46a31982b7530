"""Which launch files of the checked set are analysed as roots, and which through an includer.

A file that another analysed file includes is analysed through its includer (which gives it its
real arguments and namespace), not on its own; a file nobody includes is a root. Whether a file is
included is only known by resolving its would-be includers, so the cost is in resolving entries
whose result is then dropped. Two shortcuts keep that cost down without changing the outcome for a
file that some resolved entry reaches:

- a file without an include action adds nothing to what is included: includers go first, and such
  a file that one of them includes is never resolved on its own;
- a file that another entry names in an include (by file name: the literal last part of its path,
  ``PathJoinSubstitution([..., 'launch', 'bringup_launch.py'])``, ``$(find-pkg-share p)/x.launch.xml``)
  is resolved only if none of the other entries' results turns out to include it. A guess that
  does not come true costs nothing but the order: the file is resolved afterwards, as before.
  Files on a cycle of such guesses are always resolved.

What a dropped entry would have included on its own arguments (and nothing resolved includes) is
therefore a root, not an included file. Everything here is deterministic and independent of the
order of the input and of ``--jobs``.
"""
from __future__ import annotations

import posixpath
from collections.abc import Callable, Iterator
from typing import Any

from physai_lint.model import launch as ir
from physai_lint.model import values as v


def actions_of(lf: Any) -> Iterator[ir.Action]:
    """Every action of a parsed file, in groups, timers, handlers and opaque bodies too."""
    stack = list(lf.actions) if lf is not None else []
    while stack:
        action = stack.pop()
        yield action
        stack.extend(getattr(action, "actions", ()))


def has_include(lf: Any) -> bool:
    """Whether a parsed launch file has an include action anywhere."""
    return any(isinstance(a, ir.Include) for a in actions_of(lf))


def _last_text(value: Any) -> str | None:
    """The literal text a path value ends with (through ``PathJoin``), or None."""
    if not value:
        return None
    part = value[-1]
    if isinstance(part, v.Text):
        return part.text
    if isinstance(part, v.PathJoin) and part.parts:
        return _last_text(part.parts[-1])
    return None


def _first_package(value: Any) -> str | None:
    """The literal package a path value starts in (``$(find-pkg-share p)/...``,
    ``PathJoinSubstitution([FindPackageShare('p'), ...])``), or None."""
    if not value:
        return None
    part = value[0]
    if isinstance(part, v.FindPackage):
        return v.literal_of(part.package)
    if isinstance(part, v.PathJoin) and part.parts:
        return _first_package(part.parts[0])
    return None


def included_targets(lf: Any) -> set[tuple[str | None, str]]:
    """(package or None, file name) of this file's include actions whose last part is literal;
    the package where the path starts with a literal ``find-pkg`` of one."""
    out = set()
    for a in actions_of(lf):
        if isinstance(a, ir.Include):
            tail = _last_text(a.path)
            if tail:
                name = posixpath.basename(tail)
                if name:
                    out.add((_first_package(a.path), name))
    return out


def included_names(lf: Any) -> set[str]:
    """File names this file's include actions end with, where the last part is literal."""
    return {name for _, name in included_targets(lf)}


def nodes_on_cycles(graph: dict[str, set[str]]) -> set[str]:
    """Nodes of ``graph`` on a cycle (strongly connected components larger than one, self-loops)."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    on_stack: set[str] = set()
    stack: list[str] = []
    out: set[str] = set()
    counter = 0
    for start in sorted(graph):
        if start in index:
            continue
        # Iterative Tarjan: (node, iterator over its successors).
        work = [(start, iter(sorted(graph[start])))]
        index[start] = low[start] = counter
        counter += 1
        stack.append(start)
        on_stack.add(start)
        while work:
            node, succ = work[-1]
            advanced = False
            for nxt in succ:
                if nxt not in index:
                    index[nxt] = low[nxt] = counter
                    counter += 1
                    stack.append(nxt)
                    on_stack.add(nxt)
                    work.append((nxt, iter(sorted(graph.get(nxt, ())))))
                    advanced = True
                    break
                if nxt in on_stack:
                    low[node] = min(low[node], index[nxt])
            if advanced:
                continue
            work.pop()
            if work:
                low[work[-1][0]] = min(low[work[-1][0]], low[node])
            if low[node] == index[node]:
                comp = []
                while True:
                    top = stack.pop()
                    on_stack.discard(top)
                    comp.append(top)
                    if top == node:
                        break
                if len(comp) > 1 or node in graph.get(node, ()):
                    out.update(comp)
    return out


def _reach(graph: dict[str, set[str]], start: str, limit: int = 200) -> int:
    """How many includers ``start`` may include, directly or not (by the guess ``graph``)."""
    seen = {start}
    todo = [start]
    while todo and len(seen) < limit:
        for q in graph.get(todo.pop(), ()):
            if q not in seen:
                seen.add(q)
                todo.append(q)
    return len(seen)


def choose_roots(launch_files: list[str], load: Callable[[str], Any], resolve: Callable[[str], Any],
                 advance: Callable[[int], None],
                 resolve_many: Callable[[list[str], bool], list[Any]] | None = None,
                 package_of: Callable[[str], str | None] | None = None) -> list[Any]:
    """The resolved roots, in the order of ``launch_files``. ``resolve(path)`` resolves one entry;
    ``resolve_many(paths, leaves)`` resolves several independent ones, in order (in parallel with
    ``--jobs``; by default one after the other), ``leaves`` when none of them includes a file
    (each resolves in a fraction of a millisecond); ``advance(n)`` counts entries that were settled
    without resolving them. ``package_of(path)``: the workspace package holding a file, if known;
    an include that names its package then guesses only that package's file of the name (many
    packages have a ``bringup.launch.py``: by name alone, they would all guess each other, a cycle,
    and every one of them would be resolved)."""
    many = resolve_many or (lambda paths, leaves: [resolve(p) for p in paths])
    parsed = {p: load(p) for p in launch_files}
    leaves = {p for p in launch_files if not has_include(parsed[p])}
    includers = [p for p in launch_files if p not in leaves]
    by_name: dict[str, list[str]] = {}
    for p in includers:
        by_name.setdefault(posixpath.basename(p), []).append(p)
    owner = {p: package_of(p) for p in includers} if package_of is not None else {}

    def named(pkg: str | None, name: str) -> Iterator[str]:
        for q in by_name.get(name, ()):
            if pkg is None or owner.get(q) in (None, pkg):
                yield q

    # The guess: which includers each includer names (itself included: a cycle of one).
    targets = {p: included_targets(parsed[p]) for p in includers}
    graph = {p: {q for pkg, n in targets[p] for q in named(pkg, n)} for p in includers}
    cyclic = nodes_on_cycles(graph)
    guessed = {q for p, qs in graph.items() if p not in cyclic for q in qs if q != p} - cyclic
    first = [p for p in includers if p not in guessed]
    # Leaves that no includer names are almost surely entries of their own: resolved with the
    # first wave (in front: with --jobs this process takes them, between the helpers' items),
    # not alone after it; one that an unnamed include reaches is dropped below like any other.
    names = {n for ts in targets.values() for _, n in ts}
    early = sorted(p for p in leaves if posixpath.basename(p) not in names)
    # Heaviest first by the includers each may reach (its resolution walks them): with --jobs this
    # process takes the wave from the front and a helper from the back, so the two meet among
    # light entries and neither waits long for the other's last one. Results keep their places.
    wave = early + sorted(first, key=lambda p: -_reach(graph, p))
    by_entry: dict[str, Any] = dict(zip(wave, many(wave, False)))
    included = {f for r in by_entry.values() for f in r.files[1:] if f != r.entry}
    for p in sorted(guessed):  # guesses that did not come true, includers by path
        if p in included:
            continue
        r = by_entry[p] = resolve(p)
        included.update(f for f in r.files[1:] if f != r.entry)
    alone = sorted(leaves - included - by_entry.keys())
    by_entry.update(zip(alone, many(alone, True)))
    launches = [by_entry[p] for p in launch_files if p in by_entry and p not in included]
    if not launches:  # every file is included by another (include cycles): all of them are roots
        rest = sorted(set(launch_files) - set(by_entry))
        by_entry.update(zip(rest, many(rest, False)))
        return [by_entry[p] for p in launch_files]
    advance(len(set(launch_files) - set(by_entry)))  # settled without resolving them
    return launches
