"""Shared pieces of the evaluator: limits, control-flow signals, scopes, truthiness."""
from __future__ import annotations

import ast
import builtins
import operator
from collections.abc import Callable
from typing import Any

from . import symbolic
from .positions import SpanMaker
from .runtime import Opaque, SymBool

MAX_STEPS = 400_000
MAX_LOOP = 10_000
MAX_DEPTH = 50

BUILTIN_NAMES = frozenset(dir(builtins)) | {"__file__", "__name__", "__doc__", "__spec__", "__package__"}
NO = object()


class Abort(Exception):
    def __init__(self, reason: str) -> None:
        super().__init__(reason)
        self.reason = reason


class Signal(Exception):
    """Control flow of the evaluated code (return/break/continue/raise)."""


class Return(Signal):
    def __init__(self, value: Any) -> None:
        self.value = value


class Break(Signal):
    pass


class Continue(Signal):
    pass


class Raise(Signal):
    pass


class Scope:
    __slots__ = ("globals_decl", "module", "nonlocal_decl", "parent", "vars")

    def __init__(self, parent: Scope | None, module: ModuleCtx | None) -> None:
        self.vars: dict[str, Any] = {}
        self.parent = parent
        self.module = module
        self.globals_decl: set[str] = set()
        self.nonlocal_decl: set[str] = set()

    def set(self, name: str, value: Any) -> None:
        if name in self.globals_decl and self.module is not None:
            self.module.scope.vars[name] = value
            return
        if name in self.nonlocal_decl:
            s = self.parent
            while s is not None and s.parent is not None:  # the module scope is not a nonlocal target
                if name in s.vars:
                    s.vars[name] = value
                    return
                s = s.parent
        self.vars[name] = value


class ModuleCtx:
    def __init__(self, path: str, spans: SpanMaker, prefix: str) -> None:
        self.path = path
        self.spans = spans
        self.prefix = prefix  # id prefix for actions created in helper modules
        self.scope = Scope(None, self)


BINOPS: dict[type, Callable[[Any, Any], Any]] = {
    ast.Add: operator.add, ast.Sub: operator.sub, ast.Mult: operator.mul, ast.Div: operator.truediv,
    ast.FloorDiv: operator.floordiv, ast.Mod: operator.mod, ast.Pow: operator.pow,
    ast.BitAnd: operator.and_, ast.BitOr: operator.or_, ast.BitXor: operator.xor,
    ast.LShift: operator.lshift, ast.RShift: operator.rshift,
}
CMPOPS: dict[type, Callable[[Any, Any], Any]] = {
    ast.Eq: operator.eq, ast.NotEq: operator.ne, ast.Lt: operator.lt, ast.LtE: operator.le,
    ast.Gt: operator.gt, ast.GtE: operator.ge, ast.Is: operator.is_, ast.IsNot: operator.is_not,
    ast.In: lambda a, b: a in b, ast.NotIn: lambda a, b: a not in b,
}
_CONCRETE = (str, int, float, bool, bytes, type(None), list, tuple, dict, set, frozenset)


def is_concrete(v: Any) -> bool:
    if isinstance(v, (list, tuple, set, frozenset)):
        return all(is_concrete(x) for x in v)
    if isinstance(v, dict):
        return all(is_concrete(k) and is_concrete(x) for k, x in v.items())
    return isinstance(v, _CONCRETE)


def truth(v: Any) -> bool | None:
    """Python truthiness when known, else None."""
    if isinstance(v, (Opaque, SymBool)) or symbolic.is_symstr(v):
        return None
    if isinstance(v, (str, int, float, bool, bytes, type(None), list, tuple, dict, set)):
        return bool(v)
    return True

