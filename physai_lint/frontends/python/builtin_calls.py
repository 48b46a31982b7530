"""Python builtins over known data (``range``, ``len``, ``zip`` ...) and ``str.format``/``join``."""
from __future__ import annotations

from typing import TYPE_CHECKING, Any

from physai_lint.model.launch import EVERY_CONFIGURATION
from physai_lint.model.span import Span

from . import bounds, symbolic
from .runtime import FileHandle, KPath, LaunchConfigsSym, Opaque, SymStr, UserFunc

if TYPE_CHECKING:
    from .evaluator import Evaluator

_LIMIT = 100_000
_PURE = {
    "len": len, "int": int, "float": float, "bool": bool, "abs": abs, "round": round, "min": min,
    "max": max, "sum": sum, "any": any, "all": all, "chr": chr, "ord": ord, "repr": repr,
    "sorted": sorted, "format": format, "hash": hash,
}


# Builtins that look at a value's kind or size only: they read no launch configuration.
_SHAPE_ONLY = frozenset({"len", "isinstance", "type", "id", "bool", "hasattr", "callable", "issubclass"})


def call_builtin(ev: Evaluator, name: str, args: list[Any], kwargs: dict[str, Any], span: Span) -> Any:
    from .calls import call_user, iterate
    from .evaluator import is_concrete

    if name == "super" and not args and not kwargs:
        from .classes import zero_arg_super

        return zero_arg_super(ev, span)
    if name not in _SHAPE_ONLY and any(isinstance(a, LaunchConfigsSym) for a in [*args, *kwargs.values()]):
        ev.escaped.add(EVERY_CONFIGURATION)  # dict(context.launch_configurations): all of them
    for a in list(args) + list(kwargs.values()):
        if isinstance(a, Opaque) and name not in ("print", "isinstance", "list", "tuple"):
            return Opaque(a.reason, span)
    if name == "print":
        return None
    if name == "range":
        if not all(isinstance(a, int) for a in args) or kwargs:
            return Opaque("range over unknown bounds", span)
        r = range(*args)
        return r if len(r) <= _LIMIT else Opaque("range too large", span)
    if name == "str":
        if not args:
            return ""
        x = args[0]
        if symbolic.is_subst(x):
            ev.concat("str", span, symbolic.shown_subst(x))
            return SymStr(symbolic.to_value(x, span))
        if isinstance(x, SymStr):
            return x
        if isinstance(x, KPath):
            return x.path
        return str(x) if is_concrete(x) else Opaque("str() of an unknown value", span)
    if name in ("list", "tuple", "set", "frozenset", "reversed", "enumerate", "zip", "dict", "map", "filter"):
        return _containers(ev, name, args, kwargs, span, iterate, call_user)
    if name == "open":
        path = args[0] if args else kwargs.get("file")
        mode = args[1] if len(args) > 1 else kwargs.get("mode", "r")
        if isinstance(mode, str) and not set(mode) & set("wax+"):
            ev.opened(path, span)
        return FileHandle(path if isinstance(path, str) else (path.path if isinstance(path, KPath) and isinstance(path.path, str) else None), span)
    if name in _PURE and is_concrete(list(args)) and is_concrete(kwargs):
        if name == "sorted" and "key" in kwargs:
            return Opaque("sorted with a key function", span)
        if name == "format" and any(bounds.wide_format(a) for a in [*args[1:], *kwargs.values()]):
            return Opaque("format() result too large", span)
        try:
            return _PURE[name](*args, **kwargs)
        except Exception:  # noqa: BLE001
            return Opaque(f"{name}() fails statically", span)
    if name == "len" and args and isinstance(args[0], (list, tuple, dict)):
        return len(args[0])
    return Opaque(f'builtin "{name}" on values that cannot be evaluated statically', span)


def _containers(ev: Evaluator, name: str, args: list[Any], kwargs: dict[str, Any], span: Span,
                iterate: Any, call_user: Any) -> Any:
    if name == "dict":
        out: dict[Any, Any] = {}
        if args:
            src = args[0]
            if isinstance(src, dict):
                out.update(src)
            else:
                items = iterate(ev, src)
                if items is None:
                    return Opaque("dict() of an unknown iterable", span)
                for it in items:
                    if not isinstance(it, (list, tuple)) or len(it) != 2:
                        return Opaque("dict() of non-pairs", span)
                    try:
                        out[it[0]] = it[1]
                    except TypeError:
                        return Opaque("dict() with an unhashable key", span)
        out.update(kwargs)
        return out
    if name in ("map", "filter"):
        if len(args) < 2 or not isinstance(args[0], UserFunc) and args[0] is not None:
            return Opaque(f"{name}() with an unknown function", span)
        seqs = [iterate(ev, a) for a in args[1:]]
        if any(s is None for s in seqs):
            return Opaque(f"{name}() of an unknown iterable", span)
        if name == "map":
            return [call_user(ev, args[0], list(xs), {}, span) for xs in zip(*seqs)]
        result = []
        for x in seqs[0]:
            keep = bool(x) if args[0] is None else call_user(ev, args[0], [x], {}, span)
            if isinstance(keep, Opaque):
                return Opaque("filter() with an unknown predicate", span)
            if keep:
                result.append(x)
        return result
    seqs = [iterate(ev, a) for a in args]
    if any(s is None for s in seqs):
        bad = next(a for a, s in zip(args, seqs) if s is None)
        return Opaque(bad.reason if isinstance(bad, Opaque) else f"{name}() of an unknown iterable", span)
    if name == "list":
        return list(seqs[0]) if seqs else []
    if name == "tuple":
        return tuple(seqs[0]) if seqs else ()
    if name in ("set", "frozenset"):
        try:
            return set(seqs[0]) if seqs else set()
        except TypeError:
            return Opaque("set of unhashable values", span)
    if name == "reversed":
        return list(reversed(seqs[0]))
    if name == "enumerate":
        start = kwargs.get("start", args[1] if len(args) > 1 else 0)
        return [(i + start, x) for i, x in enumerate(seqs[0])] if isinstance(start, int) else Opaque("enumerate", span)
    return [tuple(t) for t in zip(*seqs)]


def str_format_join(ev: Evaluator, s: str, name: str, args: list[Any], kwargs: dict[str, Any], span: Span) -> Any:
    from .calls import iterate
    from .evaluator import is_concrete

    if name == "join":
        items = iterate(ev, args[0]) if args else None
        if items is None:
            return Opaque("join of an unknown iterable", span)
        if bounds.join_too_big(str(s), items):
            return Opaque("join result too large", span)
        parts: list[Any] = []
        for i, item in enumerate(items):
            if i:
                parts.append(str(s))
            if symbolic.is_subst(item):
                ev.concat("join", span, symbolic.shown_subst(item))
            parts.append(item)
        if not all(symbolic.is_textlike(p) for p in parts):
            return Opaque("join of values that cannot be evaluated statically", span)
        return symbolic.join_parts(ev, parts, span)
    if bounds.wide_format(str(s)) or any(isinstance(a, int) and a > bounds.MAX_WEIGHT
                                         for a in [*args, *kwargs.values()]):
        return Opaque("str.format result too large", span)
    if is_concrete(list(args)) and is_concrete(kwargs):
        try:
            return str(s).format(*args, **kwargs)
        except Exception:  # noqa: BLE001
            return Opaque("str.format fails statically", span)
    for a in list(args) + list(kwargs.values()):
        if symbolic.is_subst(a):
            ev.concat("format", span, symbolic.shown_subst(a))
            break
    return Opaque("str.format of a value known only at launch time", span)
