"""The interface of a C++ executable that links a library: its own code, and of the library only
the classes that run in it.

A library may hold several node classes (robot_localization's one library holds the EKF/UKF
filter and navsat_transform; image_proc's holds every component), and each executable's
``main()`` runs one of them. The classes that run are those the executable's own sources name
(``std::make_shared<robot_localization::NavSatTransform>(options)``), directly or through an
alias in a header they include (``using RosEkf = RosFilter<Ekf>;``), the plugin class of a
component, and, transitively, the classes a running class's code names (a node building its
helper). What the library's code outside any class declares (a free function's subscription)
may or may not run: its endpoints are kept as their kind and type only (``unnamed``: the
dangling-topic rules back off), as is every library endpoint when the executable's code names
no library class that declares something (and it is no component whose class's code is known).
Parameters and lifecycle bases follow the classes too; those of code that may run are kept, as
they were before classes were told apart.

A source's constructors may initialise message_filters members its own header declares
(``odom_sub_(node, "odom/filtered", qos)``, the member in ``ros_robot_localization_listener.hpp``):
that header is read when the source registers a filter's callback.
"""
from __future__ import annotations

import dataclasses
import functools
import posixpath
import re
from collections.abc import Callable, Iterable
from typing import Any

from .cpp_scopes import CppFacts, blank_code
from .extract_cpp import _MAKE, _everything, _file_interface, member_initialisers, merge_facts, skim, tokenize
from .model import NodeInterface

Reader = Callable[[str], "str | None"]

_INCLUDE = re.compile(r'#[ \t]*include[ \t]*[<"]([^">]+\.(?:h|hh|hpp|hxx))[">]')
_INCLUDE_WORD = re.compile(r"#[ \t]*include\b")
_ALIAS = re.compile(r"\busing\s+(\w+)\s*=\s*([^;]*);|\btypedef\s+([^;]*?)\b(\w+)\s*;")
_MAX_INCLUDES = 32  # headers read per executable to find aliases
# a message_filters subscriber's messages reach a callback registered on it, or on a synchroniser
# it is connected to (constructed with it, or ``connectInput``)
_FILTER_OUTPUT = ("registerCallback", "connectInput")
_FILTER_DECLARATION = re.compile(r"message_filters::Subscriber\b|image_transport::SubscriberFilter")
_WORD = re.compile(r"[A-Za-z_]\w*")


def extract_linked(own: list[tuple[str, str]], library: list[tuple[str, str]], roots: list[str],
                   cache: Any = None, read: Reader | None = None, locate: Locate | None = None,
                   package: str = "") -> NodeInterface:
    """The interface of an executable built from ``own`` sources and ``library`` sources (those
    a linked library brings), with ``roots`` the classes known to run (a component's plugin
    class, qualified or not); ``read`` reads the headers the sources include, ``locate`` those
    of other workspace packages (``foreign_bases``)."""
    own_parts = [part for path, text in own for part in _facts(path, text, cache, read)]
    lib_parts = [(text, part) for path, text in library for part in _facts(path, text, cache, read)]
    own_parts += _header_node_sites(own, own_parts + [part for _, part in lib_parts], cache, read)
    extra = foreign_bases(own + library, read, locate, cache, package) if locate is not None else []
    if not library:
        return merge_facts([(part, _everything) for part in own_parts] + extra)
    holders = {owner for _, part in lib_parts for owner in _owners(part) if owner is not None}
    runs = _running_classes(own, lib_parts, roots, read, holders)
    # Sure of what runs: a class that declares something, or a root whose code is known (a
    # component declaring nothing extraction sees still runs no other class).
    sure = bool(runs & holders) or bool(runs & {r.rsplit("::", 1)[-1] for r in roots})

    def keep(owner: str | None) -> bool | str:
        if owner is None or not sure:
            return "unnamed"
        return owner in runs

    return merge_facts([(part, _everything) for part in own_parts] + [(part, keep) for _, part in lib_parts]
                       + extra)


def _header_node_sites(own: list[tuple[str, str]], parts: list[CppFacts], cache: Any,
                       read: Reader | None) -> list[CppFacts]:
    """Where the classes the sources construct (``make_shared<Worker>()``) but do not define make
    their node, read from the package's own headers the sources include: a header-only node
    class (``Worker() : Node("worker")`` in ``include/demo/worker.hpp``) names the node. Only
    those places are taken (the header's other items are not the executable's for sure)."""
    known = {cls for part in parts for cls, _, _ in part.classes}
    # (a main() that only constructs its node has no call word: extraction did not read it)
    wanted = {m.group(1) for _, text in own for m in _MAKE.finditer(text)} - known
    if not wanted or read is None:
        return []
    out: list[CppFacts] = []
    budget = _MAX_INCLUDES
    for path, text in own:
        for include in _INCLUDE.findall(text):
            if budget <= 0 or not wanted:
                return out
            budget -= 1
            found = _read_include(path, include, read)
            if found is None:
                continue
            header = _file_interface(*found, cache)
            defined = wanted & {cls for cls, _, _ in header.classes}
            if defined:
                out.append(CppFacts(node_sites=[s for s in header.node_sites if s[3] in defined],
                                    makes=list(header.makes)))
                wanted -= defined
    return out


def _facts(path: str, text: str, cache: Any, read: Reader | None) -> list[CppFacts]:
    """What a source declares, and the subscriptions its constructors make by initialising the
    message_filters members its own header declares (``foo.cpp`` including ``.../foo.hpp``)."""
    part = _file_interface(path, text, cache)
    if read is None or not part.classes or not any(w in text for w in _FILTER_OUTPUT):
        return [part]  # (a filter's messages reach code only through those calls)
    header = _own_header(path, text, read)
    if header is None or not _FILTER_DECLARATION.search(header[1]):
        return [part]
    members = tuple(sorted((n, t) for n, t in _file_interface(*header, cache).filters.items()
                           if n not in part.filters))
    return [part, member_initialisers(path, text, members)] if members else [part]


def _own_header(path: str, text: str, read: Reader) -> tuple[str, str] | None:
    """The header a source includes that has its name (``src/foo.cpp``: ``"pkg/foo.hpp"``)."""
    stem = posixpath.splitext(posixpath.basename(path))[0]
    if path.endswith((".h", ".hh", ".hpp", ".hxx")):
        return None
    for m in _INCLUDE_WORD.finditer(text):
        line_end = text.find("\n", m.end())
        include = _INCLUDE.match(text, m.start(), len(text) if line_end < 0 else line_end)
        if include and posixpath.splitext(posixpath.basename(include.group(1)))[0] == stem:
            return _read_include(path, include.group(1), read)
    return None


def _owners(part: CppFacts) -> Iterable[str | None]:
    yield from (owner for _, _, owner in part.endpoints)
    yield from (owner for _, _, owner in part.unnamed)
    yield from (owner for _, owner in part.parameters)
    yield from part.lifecycle


def _running_classes(own: list[tuple[str, str]], lib_parts: list[tuple[str, CppFacts]],
                     roots: list[str], read: Reader | None, holders: set[str]) -> set[str]:
    """The library classes that run: named by the own sources (or an alias they include), the
    roots, and the classes their code names, transitively, until every class that declares
    something (``holders``) is reached or no code is left. The code of the classes in library
    files without a call word (not extracted) is read only when they name a holder not reached
    otherwise (a node's helper may build it) or a root whose code is not known yet."""
    code: dict[str, list[tuple[str, int, int]]] = {}  # class -> (text, start, end) of its code
    for text, part in lib_parts:
        for cls, start, end in part.classes:
            code.setdefault(cls, []).append((text, start, end))
    runs = _closure(own, code, roots, read, holders)
    missing = holders - runs | {r.rsplit("::", 1)[-1] for r in roots} - set(code)
    read_texts = {id(text) for text, part in lib_parts if not part.empty() or part.classes}
    # (a class building a holder names it, a root's code names it: only those files are read)
    unread = [text for text, _ in lib_parts if id(text) not in read_texts
              and any(h in text for h in missing)]
    if unread:
        for text in unread:
            for cls, start, end in _classes_of(text):
                code.setdefault(cls, []).append((text, start, end))
        runs = _closure(own, code, roots, read, holders)
    return runs


def _closure(own: list[tuple[str, str]], code: dict[str, list[tuple[str, int, int]]],
             roots: list[str], read: Reader | None, holders: set[str]) -> set[str]:
    names = set(code)
    runs = {r.rsplit("::", 1)[-1] for r in roots} & names
    for _, text in own:
        runs |= names & code_words(text)
    if own and holders - runs and read is not None:
        runs |= _through_aliases(own, names - runs, read)
    todo = sorted(runs)
    while todo and holders - runs:
        for text, start, end in code[todo.pop()]:
            found = (names - runs) & code_words(text, start, end)
            runs |= found
            todo.extend(sorted(found))
    return runs


@functools.lru_cache(maxsize=256)
def _classes_of(text: str) -> list[tuple[str, int, int]]:
    """The classes' code in a source extraction did not read (no call word in it)."""
    view = skim(text)
    if view is None:
        return []
    return [(c, a, b) for c, a, b in view.classes() if c is not None]


@functools.lru_cache(maxsize=1024)
def code_words(text: str, start: int = 0, end: int | None = None) -> frozenset[str]:
    """The identifiers ``text[start:end]`` names in its code (not in a comment, string or
    preprocessor line)."""
    view = skim(text)
    if view is None:  # a source the skim has doubts about: its tokens
        return frozenset(t.text for t in tokenize(text) if t.kind == "id")
    end = len(text) if end is None else end
    return frozenset(_WORD.findall(blank_code(text, start, end, view.starts, view.ends)))


def _through_aliases(own: list[tuple[str, str]], names: set[str], read: Reader) -> set[str]:
    """Classes among ``names`` that an alias (``using A = ...;``, ``typedef ... A;``) in a header
    an own source includes names, when that source names the alias."""
    found: set[str] = set()
    budget = _MAX_INCLUDES
    for path, text in own:
        for include in _INCLUDE.findall(text):
            if budget <= 0:
                return found
            budget -= 1
            found_header = _read_include(path, include, read)
            if found_header is None:
                continue
            for m in _ALIAS.finditer(found_header[1]):
                alias, target = (m.group(1), m.group(2)) if m.group(1) else (m.group(4), m.group(3))
                targets = names & set(re.findall(r"\w+", target))
                if targets - found and alias in code_words(text):
                    found |= targets
    return found


def _read_include(path: str, include: str, read: Reader) -> tuple[str, str] | None:
    """The path and text of ``#include "include"`` as seen from source ``path``: beside it, or
    under the ``include/`` folder of one of its parent folders (a package's usual layout)."""
    folder = posixpath.dirname(path)
    candidates = [posixpath.join(folder, include)]
    for _ in range(4):
        folder = posixpath.dirname(folder)
        candidates.append(posixpath.join(folder, "include", include))
    for candidate in candidates:
        text = read(candidate)
        if text is not None:
            return candidate, text
    return None


# ---- base classes from other workspace packages -------------------------------------------------

# ``class Worker : public base_pkg::BaseClient {``: a class head with its bases
_CLASS_BASES = re.compile(r"\b(?:class|struct)\s+(?:\w+\s+)*?(\w+)\s*(?:final\s*)?:(?!:)\s*([^{;]*)\{")
_BASE = re.compile(r"^(?:\s*(?:public|protected|private|virtual)\b)*\s*((?:::)?[A-Za-z_][\w:]*)")
_MAX_FOREIGN_SOURCES = 16  # sources of another package read per base class
# an include -> (path, text, the sources of its package that hold a word) | None
Locate = Callable[[str], "tuple[str, str, Callable[[str], list[tuple[str, str]]]] | None"]


def foreign_bases(own: list[tuple[str, str]], read: Reader | None, locate: Locate, cache: Any = None,
                  package: str = "") -> list[tuple[CppFacts, Callable[[str | None], bool | str]]]:
    """What base classes defined in another workspace package declare for the classes of
    ``own`` (the sources of an executable of ``package``, with the headers of ``package`` they
    include): a node class deriving from ``base_pkg::BaseClient`` runs its base's constructor,
    and the publishers it makes there (PlanSys2's performers derive their status topics so).

    ``locate(include)``: for ``#include "base_pkg/base_client.hpp"`` of another workspace package,
    (the header's path, its text, a function giving that package's C++ sources that hold a word);
    None otherwise. The base's code is its header and the sources that define its members
    (``BaseClient::``); only the items of that class are taken, and not where it makes its node
    (its subclass passes the name on). Its endpoints are kept as their kind and type only
    (``unnamed``: the dangling-topic rules back off for that type): a base class is often a toolbox its subclasses configure, whose members
    subscribe only when a parameter asks for it (rtabmap_sync's ``CommonDataSubscriber`` has a
    setup function per combination of inputs). Its parameters and lifecycle base are kept."""
    texts = list(own)
    if read is not None:
        seen = {p for p, _ in own}
        for path, text in own:
            # the package's own headers (``"pkg/x.hpp"``), where its classes are
            mine = [i for i in _INCLUDE.findall(text) if i.startswith(package + "/")]
            for include in mine[:_MAX_INCLUDES]:
                found = _read_include(path, include, read)
                if found is not None and found[0] not in seen:
                    seen.add(found[0])
                    texts.append(found)
    heads = [_class_heads(text) for _, text in texts]
    defined = {name for names, _, _ in heads for name in names}
    wanted = sorted({b for _, bases, _ in heads for b in bases} - defined)
    if not wanted:
        return []
    includes = sorted({i for _, _, incs in heads for i in incs})
    out: list[tuple[CppFacts, Callable[[str | None], bool | str]]] = []
    for last in wanted:
        for include in includes:
            found = locate(include)
            if found is None or not _defines_class(found[1], last):
                continue
            header_path, header, sources = found
            files = [(header_path, header)] + sources(last + "::")[:_MAX_FOREIGN_SOURCES]
            for path, text in files:
                part = _file_interface(path, text, cache)
                # (an endpoint of no known type is a base's generic wrapper, ``create_publisher<
                # MessageT>(topic, ...)``: its subclasses' calls of it are extracted as their own)
                out.append((dataclasses.replace(
                    part, node_sites=[], makes=[],
                    endpoints=[e for e in part.endpoints if e[1].type is not None],
                    unnamed=[u for u in part.unnamed if u[1] is not None]),
                    lambda owner, cls=last: "unnamed" if owner == cls else False))
            break
    return out


@functools.lru_cache(maxsize=2048)
def _defines_class(text: str, name: str) -> bool:
    """Whether ``text`` defines class ``name`` (a body, not a declaration)."""
    if name not in text:
        return False
    head = re.compile(r"\b(?:class|struct)\s+(?:\w+\s+)*?" + re.escape(name) + r"\b[^;{]*\{")
    return head.search(_code(text)) is not None


@functools.lru_cache(maxsize=2048)
def _class_heads(text: str) -> tuple[frozenset[str], frozenset[str], tuple[str, ...]]:
    """The classes ``text`` defines with a base clause, the last names of their bases, and the
    headers it includes (when it has any base clause)."""
    # (most sources have no class head with a base clause, and nearly every base clause has an
    # access specifier: a substring test before the regular expression)
    if ("public" not in text and "protected" not in text and "private" not in text) or \
            _CLASS_BASES.search(text) is None:
        return frozenset(), frozenset(), ()
    code = _code(text)
    defined, bases = set(), set()
    for m in _CLASS_BASES.finditer(code):
        defined.add(m.group(1))
        bases.update(b.rsplit("::", 1)[-1] for b in _split_bases(m.group(2)))
    return frozenset(defined), frozenset(bases), tuple(_INCLUDE.findall(text)) if bases else ()


def _split_bases(clause: str) -> list[str]:
    """The class names of a base clause (``public A<T, U>, private b::C``), without template
    arguments."""
    depth, start, parts = 0, 0, []
    for i, ch in enumerate(clause):
        if ch == "<":
            depth += 1
        elif ch == ">":
            depth = max(0, depth - 1)
        elif ch == "," and depth == 0:
            parts.append(clause[start:i])
            start = i + 1
    parts.append(clause[start:])
    out = []
    for part in parts:
        m = _BASE.match(part.split("<", 1)[0])
        if m:
            out.append(m.group(1).lstrip(":"))
    return out


def _code(text: str) -> str:
    """``text`` with its comments, strings and preprocessor lines blanked, as extraction skims it
    (a class head in a comment names no base); the text itself when the skim has doubts."""
    view = skim(text)
    return text if view is None else blank_code(text, 0, len(text), view.starts, view.ends)
