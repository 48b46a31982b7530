"""Which class's code holds an offset of a C++ source: the scopes at namespace level.

An executable that links a library of several node classes runs only those its own code names
(``interfaces/linked.py``); to know which endpoint belongs to which class, every item extraction
finds is tagged with the class whose code holds it. That code is a class body (in-class member
definitions, a header's inline code, the base clause naming ``LifecycleNode``) or a member
function defined outside its class (``Foo::Foo(...) : init_(...) {``, ``Foo<T>::bar(...) {``),
with its head, parameters and constructor initialisers.

The scopes come from the braces outside comments, strings and preprocessor lines (the skim of
``extract_cpp._Windows`` says where those are) and the text before each brace at namespace
level: a few regular expressions on that head, no tokenizing. Namespaces and ``extern "C"`` are
transparent; a brace that only initialises (``member_{x}``, ``= {...}``, a lambda inside a call)
is part of the code around it.
"""
from __future__ import annotations

import bisect
import re
from dataclasses import dataclass, field

from physai_lint.model.span import Span

from .model import Endpoint, ParamDecl

Scope = tuple[str | None, int, int]  # (class or None, start offset, end offset)

_BRACES = re.compile(r"[{}]")
_NAMESPACE_END = re.compile(r"(?:\bnamespace(?:\s+[\w:]+)?|\bextern)\s*$")
_CLASS_WORD = re.compile(r"\b(?:class|struct|union)\b")
# from the keyword to the "{": attribute macros, the name, "final", specialisation, bases
_CLASS_HEAD = re.compile(r"(?:class|struct|union)\s+(?:\w+\s+)*?(\w+)\s*(?:final\s*)?"
                         r"(?:<[^{]*>\s*)?(?::(?!:)[^{]*)?$")
# ``Foo::bar(``, ``Foo<T>::~Foo(``: the class qualifying a function's name
_QUALIFIED_HEAD = re.compile(r"(?<!\w)(\w+)\s*(?:<[^<>;{}()]*(?:<[^<>;{}()]*>[^<>;{}()]*)*>)?"
                             r"\s*::\s*(?:~\s*)?\w+\s*\(")
_LAST_WORD = re.compile(r"(\w+)$")
_FUNCTION_QUALIFIERS = frozenset({"const", "override", "final", "noexcept", "mutable", "try",
                                  "volatile"})


@dataclass
class CppFacts:
    """What one C++ source declares, each item with the class whose code holds it (None: code
    outside any class, or a file read without its scopes), and every class's code in it."""

    endpoints: list[tuple[str, Endpoint, str | None]] = field(default_factory=list)  # kind, ., class
    unnamed: list[tuple[str, str | None, str | None]] = field(default_factory=list)  # kind, type, class
    parameters: list[tuple[ParamDecl, str | None]] = field(default_factory=list)  # each declaration
    lifecycle: list[str | None] = field(default_factory=list)  # a class making a lifecycle node
    classes: tuple[tuple[str, int, int], ...] = ()  # (class, start, end) of its code pieces
    # message_filters subscribers this file declares (a header's members): name -> message type
    filters: dict[str, str | None] = field(default_factory=dict)
    # where the code makes a node (``: Node("talker")``): name or None, passed on, span, class,
    # namespace ("" none, None not known)
    node_sites: list[tuple[str | None, bool, Span | None, str | None, str | None]] = field(default_factory=list)
    # ``make_shared<LifecycleTalker>("lc_talker")``: class, its first argument's literal (None:
    # not a literal), span
    makes: list[tuple[str, str | None, Span | None]] = field(default_factory=list)

    def empty(self) -> bool:
        return not (self.endpoints or self.unnamed or self.parameters or self.lifecycle)


def scopes(text: str, starts: list[int], ends: list[int]) -> list[Scope]:
    """The scopes at namespace level, in order: class bodies and function definitions with their
    heads (class None for a free function), from the brace structure outside the skimmed
    ``starts``/``ends`` (comments, strings, preprocessor lines). A brace a preprocessor branch
    leaves unmatched leaves the rest of the file in one scope; an unclosed one runs to the end."""
    out: list[Scope] = []
    stack: list[tuple[str, str | None, int]] = []  # (kind, class, head start) per open brace
    depth = 0  # braces open inside the innermost scope or initialiser (not on the stack)
    region = 0  # where the current run of namespace-level declarations starts
    inits: list[tuple[int, int]] = []  # initialising braces since ``region``
    n_skim, k = len(starts), 0
    for m in _BRACES.finditer(text):
        q = m.start()
        while k < n_skim and ends[k] <= q:
            k += 1
        if k < n_skim and starts[k] <= q:
            continue  # in a comment, string or preprocessor line
        if depth:  # inside a scope or an initialiser: only its end matters
            depth += 1 if text[q] == "{" else -1
            if depth:
                continue
            kind, cls, head = stack.pop()
            if kind == "init":
                inits.append((head, q))
                continue
            out.append((cls, head, q + 1))
            region, inits = q + 1, []
        elif text[q] == "{":
            head = _head_start(text, region, q, starts, ends, inits)
            kind, cls = _classify(blank_code(text, head, q, starts, ends))
            stack.append((kind, cls, head))
            if kind == "namespace":
                region, inits = q + 1, []
            else:
                depth = 1
        elif stack:  # a namespace's end
            stack.pop()
            region, inits = q + 1, []
    out.extend((cls, head, len(text)) for kind, cls, head in stack if kind == "scope")
    out.sort(key=lambda s: s[1])
    return out


def owner_at(found: list[Scope], firsts: list[int], p: int) -> str | None:
    """The class of the scope holding offset ``p`` (``firsts``: the scopes' starts)."""
    k = bisect.bisect_right(firsts, p) - 1
    if k >= 0 and p < found[k][2]:
        return found[k][0]
    return None


def _inside(p: int, starts: list[int], ends: list[int]) -> bool:
    k = bisect.bisect_right(starts, p) - 1
    return k >= 0 and p < ends[k]


def _head_start(text: str, region: int, q: int, starts: list[int], ends: list[int],
                inits: list[tuple[int, int]]) -> int:
    """Where the declaration whose brace is at ``q`` starts: after the last ";" at namespace
    level since ``region``."""
    j = text.rfind(";", region, q)
    while j >= 0 and (_inside(j, starts, ends) or any(a <= j < b for a, b in inits)):
        j = text.rfind(";", region, j)
    return region if j < 0 else j + 1


def blank_code(text: str, a: int, b: int, starts: list[int], ends: list[int],
               keep_offsets: bool = False) -> str:
    """``text[a:b]`` with each comment, string and preprocessor line in it (``starts``/``ends``:
    the skim's) made one blank, and no blanks at its end; with ``keep_offsets``, made blanks of
    its length instead, the end kept (offsets into the result are those into ``text``, less a)."""
    k = bisect.bisect_right(starts, a) - 1
    if k < 0 or ends[k] <= a:
        k += 1
    parts, pos = [], a
    while k < len(starts) and starts[k] < b:
        parts.append(text[pos:max(starts[k], a)])
        end = min(ends[k], b)
        parts.append(" " * (end - max(starts[k], a)) if keep_offsets else " ")
        pos = end
        k += 1
    parts.append(text[pos:b])
    return "".join(parts) if keep_offsets else "".join(parts).rstrip()


def _depth0(h: str, p: int) -> bool:
    return h.count("(", 0, p) == h.count(")", 0, p)


def _classify(h: str) -> tuple[str, str | None]:
    """What the brace after the head ``h`` opens: ("namespace", None), ("init", None) or
    ("scope", class or None)."""
    if not h:
        return "scope", None
    if _NAMESPACE_END.search(h):
        return "namespace", None
    if h.count("(") > h.count(")"):
        return "init", None  # inside a call's parentheses: a lambda, a braced argument
    c = h[-1]
    if c.isalnum() or c in "_>":
        for m in _CLASS_WORD.finditer(h):
            p = m.start()
            if h.count("<", 0, p) == h.count(">", 0, p) and _depth0(h, p) \
                    and not h[:p].rstrip().endswith("enum"):
                head = _CLASS_HEAD.match(h, p)
                if head:
                    return "scope", head.group(1)
                break
        last = _LAST_WORD.search(h)
        if last is None or last.group(1) not in _FUNCTION_QUALIFIERS:
            return "init", None  # ``member_{``, ``Type name{``, ``enum E {``
    elif c not in ")}":
        return "init", None  # ``= {``
    for m in _QUALIFIED_HEAD.finditer(h):
        if _depth0(h, m.start()):  # the function's own name, not one in its parameters
            return "scope", m.group(1)
    return "scope", None


# ---- blocks that run under a condition ----------------------------------------------------------

_CONDITION_WORDS = frozenset({"if", "switch", "constexpr"})  # (``if constexpr (...)``)
_LAST_IDENT = re.compile(r"(\w+)\s*$")
_BRACELESS = re.compile(r"\s*(?:else\b|if\b)")


def conditional_blocks(code: str) -> list[tuple[int, int]]:
    """The (open, close) offsets in ``code`` (``blank_code``'s, offsets kept) of the blocks that run only when a
    condition the code tests holds: the bodies of ``if``, ``else`` and ``switch``."""
    out: list[tuple[int, int]] = []
    stack: list[tuple[int, bool]] = []
    for m in _BRACES.finditer(code):
        q = m.start()
        if code[q] == "{":
            stack.append((q, _conditional_head(code, q)))
        elif stack:
            start, conditional = stack.pop()
            if conditional:
                out.append((start, q))
    return out


def _conditional_head(code: str, q: int) -> bool:
    """Whether the brace at ``q`` opens the body of an ``if``/``else``/``switch``."""
    j = q - 1
    while j >= 0 and code[j].isspace():
        j -= 1
    if j < 0:
        return False
    if code[j] == ")":
        depth = 0
        while j >= 0:  # back to the matching "("
            c = code[j]
            depth += c == ")"
            depth -= c == "("
            if depth == 0:
                break
            j -= 1
        word = _LAST_IDENT.search(code, max(0, j - 40), max(j, 0))
        return word is not None and word.group(1) in _CONDITION_WORDS
    return code[max(0, j - 3):j + 1] == "else" and (j < 4 or not (code[j - 4].isalnum() or code[j - 4] == "_"))


def braceless_conditional(code: str, p: int) -> bool:
    """Whether the statement holding offset ``p`` of ``code`` is an ``if (...)`` or ``else`` without
    braces, or a conditional expression (``a ? create_...(...) : nullptr``)."""
    s = max(code.rfind(";", 0, p), code.rfind("{", 0, p), code.rfind("}", 0, p)) + 1
    return _BRACELESS.match(code, s, p) is not None or "?" in code[s:p]


_DIRECTIVE = re.compile(r"#\s*(\w+)\s*(\w*)")


def preprocessor_branches(text: str, starts: list[int], ends: list[int]) -> list[tuple[int, int]]:
    """The (start, end) offsets of the code between ``#if``/``#ifdef``/``#ifndef`` and its
    ``#endif``: compiled only under a condition (``#ifdef WITH_APRILTAG_MSGS``). A header's include
    guard (``#ifndef X`` followed by ``#define X``) is not one."""
    directives = []
    for s, e in zip(starts, ends):
        if text[s] == "#":
            m = _DIRECTIVE.match(text, s, e)
            if m:
                directives.append((s, m.group(1), m.group(2)))
    out: list[tuple[int, int]] = []
    stack: list[tuple[int, bool]] = []
    for i, (s, word, arg) in enumerate(directives):
        if word in ("if", "ifdef", "ifndef"):
            guard = word == "ifndef" and i + 1 < len(directives) and directives[i + 1][1] == "define" \
                and directives[i + 1][2] == arg
            stack.append((s, guard))
        elif word == "endif" and stack:
            start, guard = stack.pop()
            if not guard:
                out.append((start, s))
    return out
