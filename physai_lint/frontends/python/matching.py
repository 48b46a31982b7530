"""``match`` statements for the evaluator.

A pattern over a known subject matches or not, as in Python. A literal pattern over a launch-time
string (``LaunchConfiguration('x').perform(context)``) is a launch condition, like ``==``. Any other
pattern the subject cannot decide is unknown: that case and the cases after it are all kept, each
under an unknown condition, exactly as an ``if``/``elif`` chain on unknown values is.
"""
from __future__ import annotations

import ast
from typing import TYPE_CHECKING, Any

from . import classes, symbolic
from .core import Scope, is_concrete
from .runtime import ClassValue, Instance, Opaque, Ref, SymBool, SymStr

if TYPE_CHECKING:
    from .evaluator import Evaluator

_TYPES: dict[str, type | tuple[type, ...]] = {
    "builtins.str": str, "builtins.int": int, "builtins.float": float, "builtins.bool": bool,
    "builtins.list": list, "builtins.tuple": tuple, "builtins.dict": dict,
}


class MatchRest(ast.stmt):
    """The cases left after one that cannot be decided (a statement the evaluator runs)."""

    _fields = ()

    def __init__(self, subject: Any, cases: list[ast.match_case], like: ast.AST) -> None:
        super().__init__()
        self.subject = subject
        self.cases = cases
        ast.copy_location(self, like)


class Bind(ast.stmt):
    """Bindings of a case whose pattern is undecided, run first in that case's branch."""

    _fields = ()

    def __init__(self, names: dict[str, Any], like: ast.AST) -> None:
        super().__init__()
        self.names = names
        ast.copy_location(self, like)


def run_cases(ev: Evaluator, subject: Any, cases: list[ast.match_case], scope: Scope) -> None:
    for i, case in enumerate(cases):
        binds: dict[str, Any] = {}
        got = match(ev, case.pattern, subject, scope, binds)
        if got is False:
            continue
        if got is True:
            for k, v in binds.items():
                scope.set(k, v)
            if case.guard is None:
                ev.exec_block(case.body, scope)
                return
            test = ev.ev(case.guard, scope)
            t = ev.tested(test, case.guard, scope)
            if t is True:
                ev.exec_block(case.body, scope)
                return
            if t is False:
                continue
            got = test if isinstance(test, SymBool) else Opaque("a match guard that cannot be evaluated statically")
        elif got is None:
            got = Opaque(subject.reason if isinstance(subject, Opaque) else "a match pattern that cannot be decided statically")
            if case.guard is not None:
                got = Opaque("a guarded match case over values that cannot be evaluated statically")
        rest: list[ast.stmt] = [MatchRest(subject, cases[i + 1:], case.pattern)] if cases[i + 1:] else []
        body: list[ast.stmt] = [Bind(binds, case.pattern), *case.body]
        ev.branch_both(got, body, rest, case.pattern, scope)
        return


def match(ev: Evaluator, p: ast.pattern, subject: Any, scope: Scope, binds: dict[str, Any]) -> Any:
    """True, False, a ``SymBool`` (a launch-time condition) or None (cannot be decided)."""
    ev.tick()
    if isinstance(p, ast.MatchAs):
        got: Any = True if p.pattern is None else match(ev, p.pattern, subject, scope, binds)
        if p.name is not None and got is not False:
            binds[p.name] = subject
        return got
    if isinstance(p, ast.MatchValue):
        value = ev.ev(p.value, scope)
        sym = symbolic.compare(ast.Eq(), subject, value, ev.span(p, scope))
        if sym is not None:
            return sym
        return _equal(subject, value)
    if isinstance(p, ast.MatchSingleton):
        return None if _unknown(subject) else subject is p.value
    if isinstance(p, ast.MatchOr):
        return _match_or(ev, p, subject, scope, binds)
    if isinstance(p, ast.MatchSequence):
        return _match_sequence(ev, p, subject, scope, binds)
    if isinstance(p, ast.MatchMapping):
        return _match_mapping(ev, p, subject, scope, binds)
    if isinstance(p, ast.MatchClass):
        return _match_class(ev, p, subject, scope, binds)
    return None


def _unknown(v: Any) -> bool:
    return isinstance(v, (Opaque, SymStr, SymBool)) or symbolic.is_subst(v)


def _equal(a: Any, b: Any) -> bool | None:
    if not (is_concrete(a) and is_concrete(b)):
        return None
    try:
        return bool(a == b)
    except Exception:  # noqa: BLE001 - a failing comparison of user data is undecided
        return None


def _match_or(ev: Evaluator, p: ast.MatchOr, subject: Any, scope: Scope, binds: dict[str, Any]) -> Any:
    syms: list[SymBool] = []
    for alt in p.patterns:
        got = match(ev, alt, subject, scope, binds)
        if got is True and not syms:
            return True
        if isinstance(got, SymBool):
            syms.append(got)
        elif got is not False:
            return None
    if not syms:
        return False
    return syms[0] if len(syms) == 1 else symbolic.combine(syms, "or", ev.span(p, scope))


def _all(results: list[Any]) -> Any:
    if any(r is False for r in results):
        return False
    return True if all(r is True for r in results) else None


def _match_sequence(ev: Evaluator, p: ast.MatchSequence, subject: Any, scope: Scope, binds: dict[str, Any]) -> Any:
    if isinstance(subject, (str, bytes, dict)) or (is_concrete(subject) and not isinstance(subject, (list, tuple))):
        return False
    if not isinstance(subject, (list, tuple)):
        return None
    star = next((i for i, q in enumerate(p.patterns) if isinstance(q, ast.MatchStar)), None)
    n = len(p.patterns)
    if (star is None and len(subject) != n) or (star is not None and len(subject) < n - 1):
        return False
    items = list(subject)
    if star is not None:
        tail = len(items) - (n - star - 1)
        star_p = p.patterns[star]
        assert isinstance(star_p, ast.MatchStar)
        if star_p.name is not None:
            binds[star_p.name] = items[star:tail]
        pairs = list(zip(p.patterns[:star], items[:star])) + list(zip(p.patterns[star + 1:], items[tail:]))
    else:
        pairs = list(zip(p.patterns, items))
    return _all([_only_bool(match(ev, q, x, scope, binds)) for q, x in pairs])


def _only_bool(got: Any) -> Any:
    return got if isinstance(got, bool) else None


def _match_mapping(ev: Evaluator, p: ast.MatchMapping, subject: Any, scope: Scope, binds: dict[str, Any]) -> Any:
    if is_concrete(subject) and not isinstance(subject, dict):
        return False
    if not isinstance(subject, dict):
        return None
    results: list[Any] = []
    for k, q in zip(p.keys, p.patterns):
        key = ev.ev(k, scope)
        try:
            if key not in subject:
                return False
        except TypeError:
            return None
        results.append(_only_bool(match(ev, q, subject[key], scope, binds)))
    if p.rest is not None:
        used = [ev.ev(k, scope) for k in p.keys]
        binds[p.rest] = {k: v for k, v in subject.items() if k not in used}
    return _all(results)


def _match_class(ev: Evaluator, p: ast.MatchClass, subject: Any, scope: Scope, binds: dict[str, Any]) -> Any:
    cls = ev.ev(p.cls, scope)
    if isinstance(cls, Ref) and cls.qual in _TYPES:
        if _unknown(subject) or not is_concrete(subject) or p.kwd_patterns:
            return None
        t = _TYPES[cls.qual]
        if not isinstance(subject, t):
            return False
        if not p.patterns:
            return True
        if len(p.patterns) == 1:  # these builtins match their one positional pattern to the subject
            return _only_bool(match(ev, p.patterns[0], subject, scope, binds))
        return None
    if isinstance(cls, ClassValue):
        if not isinstance(subject, Instance):
            return None if _unknown(subject) or not is_concrete(subject) else False
        if not any(c is cls for c in classes.chain(subject.cls)):
            return False
        names = list(cls.fields or ()) if cls.fields is not None else []
        if len(p.patterns) > len(names):
            return None  # no __match_args__ for these positions: TypeError in Python
        pairs = list(zip(names, p.patterns)) + list(zip(p.kwd_attrs, p.kwd_patterns))
        results = []
        for name, q in pairs:
            value = classes.get_attr(ev, subject, name, ev.span(q, scope))
            if isinstance(value, Opaque) and "has no attribute" in value.reason:
                return False
            results.append(_only_bool(match(ev, q, value, scope, binds)))
        return _all(results)
    return None
