"""A bounded interpreter for ``PythonExpression`` / ``$(eval)`` strings.

Nothing is compiled to code or executed: the string is parsed with ``ast.parse(mode="eval")`` and a
whitelist of node types is interpreted. Anything outside the whitelist (attribute access on
arbitrary objects, calls of unknown functions, comprehensions, lambdas ...) gives
``SafeEvalUnknown``; so do oversized inputs and results. ``safe_eval`` never raises.
"""
from __future__ import annotations

import ast
import builtins
import functools
import math
import operator
import re
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

from physai_lint.model.pickling import fast_pickle_module

MAX_EXPR_CHARS = 10_000
MAX_ELEMENTS = 10**6
MAX_DEPTH = 100


@dataclass(frozen=True, slots=True)
class SafeEvalUnknown:
    reason: str


@dataclass(frozen=True, slots=True)
class SafeEvalError(SafeEvalUnknown):
    """``eval`` raises on this text, whatever the values of the names it could not know: a
    SyntaxError, or a NameError (a name that is neither a builtin, nor math's, nor a module's)."""


class _Unknown(Exception):
    pass


class _NameError(Exception):
    pass


# What ``eval(text, {}, locals)`` finds besides ``locals``: the builtins (``{}`` as globals gets
# ``__builtins__``)
_BUILTIN_NAMES = frozenset(dir(builtins)) | {"__builtins__"}
_MATH_NAMES = frozenset(dir(math))


_BINOPS: dict[type[ast.operator], Callable[[Any, Any], Any]] = {
    ast.Add: operator.add, ast.Sub: operator.sub, ast.Mult: operator.mul,
    ast.Div: operator.truediv, ast.FloorDiv: operator.floordiv, ast.Mod: operator.mod,
    ast.Pow: operator.pow,
}
_CMPOPS: dict[type[ast.cmpop], Callable[[Any, Any], Any]] = {
    ast.Eq: operator.eq, ast.NotEq: operator.ne, ast.Lt: operator.lt, ast.LtE: operator.le,
    ast.Gt: operator.gt, ast.GtE: operator.ge, ast.In: lambda a, b: a in b,
    ast.NotIn: lambda a, b: a not in b, ast.Is: operator.is_, ast.IsNot: operator.is_not,
}
_STR_METHODS = frozenset({
    "lower", "upper", "strip", "lstrip", "rstrip", "startswith", "endswith", "replace", "split",
    "join", "format", "capitalize", "title", "isdigit", "isalpha",
})
_SIMPLE = (bool, int, float, str, type(None))
_MATH_FUNCS = frozenset({
    "sqrt", "sin", "cos", "tan", "asin", "acos", "atan", "atan2", "radians", "degrees", "floor",
    "ceil", "fabs", "hypot", "exp", "log", "log10", "log2", "isclose", "copysign", "fmod", "trunc",
})
_MATH_CONSTS = {"pi": math.pi, "e": math.e, "tau": math.tau, "inf": math.inf, "nan": math.nan}


def _size(value: Any) -> int:
    if isinstance(value, int) and not isinstance(value, bool):
        return max(1, value.bit_length() * 30103 // 100000)  # decimal digits
    if isinstance(value, (str, list, tuple, dict, set, frozenset)):
        return len(value)
    return 1


def _check(value: Any) -> Any:
    if _size(value) > MAX_ELEMENTS:
        raise _Unknown("result too large")
    return value


def _len(x: Any) -> int:
    return len(x)


def _deep_size(value: Any, budget: int) -> int:
    """Number of scalars inside ``value`` (shared sub-lists counted each time), capped."""
    if isinstance(value, dict):
        value = [*value.keys(), *value.values()]
    if isinstance(value, (set, frozenset)):
        value = list(value)
    if not isinstance(value, (list, tuple)):
        return _size(value)
    total = 0
    for item in value:
        total += _deep_size(item, budget - total)
        if total > budget:
            return total
    return total


def _str(*args: Any) -> str:
    if args and _deep_size(args[0], MAX_ELEMENTS) > MAX_ELEMENTS // 10:
        raise _Unknown("str() of a huge value")
    if args and isinstance(args[0], (set, frozenset)) and len(args[0]) > 1:
        raise _Unknown("str() of a set: its order depends on the interpreter's hash seed")
    return str(*args)


def _items(value: Any) -> list[Any]:
    """The items of an iterable ``list()``/``set()``/``sorted()`` take; a set's in sorted order (one
    order Python may give: which one depends on the hash seed, and the linter's output must not)."""
    if isinstance(value, (set, frozenset)):
        try:
            return sorted(value)
        except TypeError:
            raise _Unknown("items of a set of mixed types") from None
    if isinstance(value, dict):
        return list(value)
    if isinstance(value, (str, list, tuple)):
        return list(value)
    raise _Unknown("items of a non-iterable")


def _list(*args: Any) -> list[Any]:
    return _items(args[0]) if args else []


def _tuple(*args: Any) -> tuple[Any, ...]:
    return tuple(_items(args[0])) if args else ()


def _set(*args: Any) -> set[Any]:
    try:
        return set(_items(args[0])) if args else set()
    except TypeError:  # unhashable items
        raise _Unknown("set of unhashable items") from None


def _sorted(value: Any, reverse: bool = False) -> list[Any]:
    return sorted(_items(value), reverse=bool(reverse))


_BUILTINS: dict[str, Callable[..., Any]] = {
    "len": _len, "str": _str, "int": int, "float": float, "bool": bool, "abs": abs,
    "min": min, "max": max, "round": round, "list": _list, "tuple": _tuple, "set": _set,
    "sorted": _sorted,
}
# Methods of a set: what Autoware's pose_twist_estimator.launch.xml computes its pose sources with
# (``list(set('$(var pose_source)'.split('_')).intersection([...]))``).
_SET_METHODS = frozenset({"intersection", "union", "difference", "symmetric_difference", "issubset",
                          "issuperset", "isdisjoint"})


class _Interp:
    def __init__(self, modules: tuple[str, ...] | None) -> None:
        self.modules_known = modules is not None  # else any name may be a module's
        modules = modules or ()
        self.math_flat = "math" in modules  # humble evaluates with math.__dict__ as globals
        self.modules = modules

    def run(self, node: ast.AST, depth: int = 0) -> Any:
        if depth > MAX_DEPTH:
            raise _Unknown("expression nested too deeply")
        handler = getattr(self, "_" + type(node).__name__, None)
        if handler is None:
            raise _Unknown(f"unsupported syntax {type(node).__name__}")
        return handler(node, depth + 1)

    def _Expression(self, node: ast.Expression, d: int) -> Any:
        return self.run(node.body, d)

    def _Constant(self, node: ast.Constant, d: int) -> Any:
        if not isinstance(node.value, _SIMPLE):
            raise _Unknown("unsupported constant")
        return _check(node.value)

    def _Name(self, node: ast.Name, d: int) -> Any:
        names = {"True": True, "False": False, "None": None}
        if node.id in names:
            return names[node.id]
        if self.math_flat and node.id in _MATH_CONSTS:
            return _MATH_CONSTS[node.id]
        self._defined(node.id)
        raise _Unknown(f"unknown name {node.id!r}")

    def _defined(self, name: str) -> None:
        """Raise ``_NameError`` when ``eval`` would not find ``name``: not a builtin, not one of
        math's names (humble evaluates with ``math.__dict__`` as locals; later distros add each
        module's names when it is math, and each module by its name)."""
        if not self.modules_known or name in _BUILTIN_NAMES or (self.math_flat and name in _MATH_NAMES) or \
                any(name == m.split(".")[0] for m in self.modules):
            return
        raise _NameError(f"NameError: name {name!r} is not defined")

    def _seq(self, elts: list[ast.expr], d: int) -> list[Any]:
        return [self.run(e, d) for e in elts]

    def _List(self, node: ast.List, d: int) -> Any:
        return self._seq(node.elts, d)

    def _Tuple(self, node: ast.Tuple, d: int) -> Any:
        return tuple(self._seq(node.elts, d))

    def _Dict(self, node: ast.Dict, d: int) -> Any:
        if any(k is None for k in node.keys):
            raise _Unknown("dict unpacking")
        return {self.run(k, d): self.run(v, d) for k, v in zip(node.keys, node.values)
                if k is not None}

    def _BinOp(self, node: ast.BinOp, d: int) -> Any:
        op = _BINOPS.get(type(node.op))
        if op is None:
            raise _Unknown("unsupported operator")
        left, right = self.run(node.left, d), self.run(node.right, d)
        if isinstance(node.op, ast.Pow):
            self._bound_pow(left, right)
        if isinstance(node.op, ast.Mult):
            self._bound_mult(left, right)
        if isinstance(node.op, ast.Mod) and isinstance(left, str):
            raise _Unknown("string formatting with %")
        return _check(op(left, right))

    @staticmethod
    def _bound_pow(left: Any, right: Any) -> None:
        if isinstance(left, (int, float)) and isinstance(right, (int, float)):
            base = abs(float(left))
            if base > 1 and abs(float(right)) * math.log10(base) > MAX_ELEMENTS:
                raise _Unknown("power too large")

    @staticmethod
    def _bound_mult(left: Any, right: Any) -> None:
        if isinstance(left, int) and isinstance(right, int):
            if _size(left) + _size(right) > MAX_ELEMENTS:
                raise _Unknown("product too large")
        for seq, count in ((left, right), (right, left)):
            if isinstance(seq, (str, list, tuple)) and isinstance(count, int):
                if len(seq) * max(count, 0) > MAX_ELEMENTS:
                    raise _Unknown("sequence repetition too large")

    def _UnaryOp(self, node: ast.UnaryOp, d: int) -> Any:
        value = self.run(node.operand, d)
        if isinstance(node.op, ast.Not):
            return not value
        if isinstance(node.op, ast.USub):
            return -value
        if isinstance(node.op, ast.UAdd):
            return +value
        raise _Unknown("unsupported unary operator")

    def _BoolOp(self, node: ast.BoolOp, d: int) -> Any:
        is_and = isinstance(node.op, ast.And)
        value: Any = None
        for item in node.values:
            value = self.run(item, d)
            if bool(value) != is_and:
                return value
        return value

    def _Compare(self, node: ast.Compare, d: int) -> Any:
        left = self.run(node.left, d)
        for op, comp in zip(node.ops, node.comparators):
            right = self.run(comp, d)
            if not _CMPOPS[type(op)](left, right):
                return False
            left = right
        return True

    def _IfExp(self, node: ast.IfExp, d: int) -> Any:
        return self.run(node.body if self.run(node.test, d) else node.orelse, d)

    def _Subscript(self, node: ast.Subscript, d: int) -> Any:
        value = self.run(node.value, d)
        if not isinstance(value, (str, list, tuple, dict)):
            raise _Unknown("subscript of a non-container")
        return value[self.run(node.slice, d)]

    def _Slice(self, node: ast.Slice, d: int) -> Any:
        parts = [None if p is None else self.run(p, d) for p in (node.lower, node.upper, node.step)]
        return slice(*parts)

    def _Attribute(self, node: ast.Attribute, d: int) -> Any:
        if isinstance(node.value, ast.Name) and node.value.id == "math" and "math" in self.modules:
            if node.attr in _MATH_CONSTS:
                return _MATH_CONSTS[node.attr]
        raise _Unknown(f"attribute {node.attr!r}")

    def _Call(self, node: ast.Call, d: int) -> Any:
        if any(isinstance(a, ast.Starred) for a in node.args) or any(
                k.arg is None for k in node.keywords):
            raise _Unknown("argument unpacking")
        func = self._callee(node.func, d)
        args = [self.run(a, d) for a in node.args]
        kwargs = {k.arg: self.run(k.value, d) for k in node.keywords if k.arg is not None}
        return _check(func(*args, **kwargs))

    def _callee(self, func: ast.expr, d: int) -> Callable[..., Any]:
        if isinstance(func, ast.Name):
            if func.id in _BUILTINS:
                return _BUILTINS[func.id]
            if self.math_flat and func.id in _MATH_FUNCS:
                return getattr(math, func.id)  # type: ignore[no-any-return]
            self._defined(func.id)
            raise _Unknown(f"call of {func.id!r}")
        if isinstance(func, ast.Attribute):
            if isinstance(func.value, ast.Name) and func.value.id == "math":
                if "math" in self.modules and func.attr in _MATH_FUNCS:
                    return getattr(math, func.attr)  # type: ignore[no-any-return]
                raise _Unknown(f"call of math.{func.attr}")
            if func.attr in _SET_METHODS:
                target = self.run(func.value, d)
                if isinstance(target, (set, frozenset)):
                    method = getattr(target, func.attr)
                    return lambda *others: method(*(_items(o) for o in others))
                raise _Unknown(f"call of .{func.attr}() of a non-set")
            if func.attr in _STR_METHODS:
                target = self.run(func.value, d)
                if isinstance(target, str):
                    if func.attr == "format":
                        return _safe_format(target)
                    if func.attr == "replace":
                        return _safe_replace(target)
                    if func.attr == "join":
                        return _safe_join(target)
                    return getattr(target, func.attr)  # type: ignore[no-any-return]
            raise _Unknown(f"call of .{func.attr}()")
        raise _Unknown("call of an expression")


def _safe_replace(target: str) -> Callable[..., str]:
    def replace(old: Any, new: Any, count: int = -1) -> str:
        if not isinstance(old, str) or not isinstance(new, str):
            raise _Unknown("replace of a non-string")
        hits = target.count(old) if old else len(target) + 1
        if len(target) + hits * max(len(new) - len(old), 0) > MAX_ELEMENTS:
            raise _Unknown("result too large")
        return target.replace(old, new, count)
    return replace


def _safe_join(sep: str) -> Callable[..., str]:
    def join(items: Any) -> str:
        if not isinstance(items, (list, tuple)) or not all(isinstance(i, str) for i in items):
            raise _Unknown("join of non-strings")
        if sum(len(i) for i in items) + len(sep) * len(items) > MAX_ELEMENTS:
            raise _Unknown("result too large")
        return sep.join(items)
    return join


_FIELD = re.compile(r"\{[^{}]*\}")


def _safe_format(template: str) -> Callable[..., str]:
    def fmt(*args: Any, **kwargs: Any) -> str:
        # attribute/index access in a field could reach arbitrary objects; widths could be huge
        for field in _FIELD.findall(template):
            name, _, spec = field[1:-1].partition(":")
            if "." in name or "[" in name or re.search(r"\d{5,}", spec):
                raise _Unknown("format field with attribute, index or huge width")
        if not all(isinstance(a, _SIMPLE) for a in (*args, *kwargs.values())):
            raise _Unknown("format of a non-scalar")
        return template.format(*args, **kwargs)
    return fmt


@functools.lru_cache(maxsize=2048)
def _parse(expr: str) -> ast.Expression | SafeEvalUnknown:
    """The expression's tree (only read by ``_Interp``), or why it does not parse: a SyntaxError is
    eval's own (``SafeEvalError``), a parser that runs out of stack or memory here says nothing
    of what eval would do. Once per text: the same conditions are evaluated in every entry that
    includes their file."""
    try:
        return ast.parse(expr, mode="eval")
    except SyntaxError as err:
        return SafeEvalError(f"SyntaxError: {err.msg}")
    except (ValueError, MemoryError, RecursionError) as err:
        return SafeEvalUnknown(f"not a Python expression: {err}")


def safe_eval(expr: str, modules: tuple[str, ...] | None = ("math",)) -> object | SafeEvalUnknown:
    """Evaluate ``expr`` like ``PythonExpression`` would, or say why it cannot be known
    (``SafeEvalError`` when eval would raise)."""
    if len(expr) > MAX_EXPR_CHARS:
        return SafeEvalUnknown("expression too long")
    tree = _parse(expr.strip())
    if isinstance(tree, SafeEvalUnknown):
        return tree
    try:
        return _Interp(modules).run(tree)
    except _Unknown as err:
        return SafeEvalUnknown(str(err))
    except _NameError as err:
        return SafeEvalError(str(err))
    except (ArithmeticError, ValueError, TypeError, LookupError, RecursionError,
            MemoryError) as err:
        return SafeEvalUnknown(f"evaluation failed: {type(err).__name__}: {err}")


fast_pickle_module(globals())  # tuples instead of dataclasses.fields() per object (model/pickling.py)
