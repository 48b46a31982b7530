"""Decorators and simple classes for the evaluator.

Launch files sometimes cache a helper (``@functools.lru_cache``/``@cache``), wrap it in their own
decorator, or keep robot data in a small class or dataclass whose methods return actions. Those
are evaluated like the rest of the file (single inheritance from another such class, with
zero-argument ``super()``); anything whose behaviour a class could change behind our back
(metaclasses, foreign or multiple bases, special methods other than ``__init__``/
``__post_init__``/``__repr__``/``__str__``, unknown decorators) makes the class or function
``Opaque`` with a reason, never a guess.
"""
from __future__ import annotations

import ast
from collections.abc import Iterator
from typing import TYPE_CHECKING, Any

from physai_lint.model.span import Span

from . import api
from .core import Raise, Scope
from .runtime import (
    BoundUser,
    ClassValue,
    Decorator,
    FieldSpec,
    Instance,
    MethodKind,
    Opaque,
    Ref,
    SuperProxy,
    UserFunc,
)

if TYPE_CHECKING:
    from .evaluator import Evaluator

LRU_DEFAULT = 128
_SIMPLE_DUNDERS = frozenset(["__init__", "__post_init__", "__repr__", "__str__", "__doc__", "__module__",
                             "__qualname__"])
_DATACLASS_OPTIONS = frozenset(["frozen", "eq", "order", "repr", "unsafe_hash", "match_args"])
# Decorators that give back the function itself (launch_testing's keep_alive marks it; its
# ready_to_test_action_timeout(seconds) sets an attribute on it).
_MARKERS = frozenset(["launch_testing.markers.keep_alive", "launch_testing.ready_to_test_action_timeout",
                      "launch_testing.ready_to_test_action_timeout.ready_to_test_action_timeout"])
_METHOD_KINDS = {"builtins.staticmethod": "static", "builtins.classmethod": "class", "builtins.property": "property"}


class ClassScope(Scope):
    """A class body's namespace: functions defined in it close over the enclosing scope, as in Python."""

    __slots__ = ("outer",)

    def __init__(self, outer: Scope) -> None:
        super().__init__(outer, outer.module)
        self.outer = outer


def decorator_call(qual: str, args: list[Any], kwargs: dict[str, Any], span: Span) -> Any:
    """``functools.lru_cache(...)``, ``functools.cache(f)``, ``dataclasses.dataclass(...)``,
    ``dataclasses.field(...)`` called in the file; None for any other function."""
    if qual in ("functools.lru_cache", "functools.cache"):
        if args and isinstance(args[0], UserFunc) and not kwargs:
            return cached(args[0], None if qual == "functools.cache" else LRU_DEFAULT)
        maxsize = kwargs.get("maxsize", args[0] if args else LRU_DEFAULT)
        if qual == "functools.lru_cache" and (maxsize is None or type(maxsize) is int) \
                and set(kwargs) <= {"maxsize", "typed"} and len(args) <= 2:
            return Decorator("cache", None if maxsize is None else max(maxsize, 0))
        return Opaque(f"{qual} with arguments that cannot be evaluated statically", span)
    if qual == "dataclasses.dataclass":
        if args or not set(kwargs) <= _DATACLASS_OPTIONS:
            return Opaque("dataclass options that cannot be evaluated statically", span)
        return Decorator("dataclass", options=dict(kwargs))
    if qual == "dataclasses.field":
        if args or not set(kwargs) <= {"default", "default_factory", "repr", "hash", "compare", "metadata"}:
            return Opaque("dataclasses.field options that cannot be evaluated statically", span)
        return FieldSpec(kwargs.get("default", _MISSING), kwargs.get("default_factory", _MISSING))
    return None


_MISSING = Opaque("no default")


def cached(f: UserFunc, maxsize: int | None) -> UserFunc:
    return UserFunc(f.node, f.closure, f.module, f.defaults, f.kw_defaults, {}, maxsize)


def decorate(ev: Evaluator, dec: ast.expr, value: Any, scope: Scope, span: Span) -> Any:
    """Apply one function decorator the way Python would, or make the function unknown."""
    from .calls import call_user

    target = dec.func if isinstance(dec, ast.Call) else dec
    marker = ev.ev(target, scope)
    if isinstance(marker, Ref) and (marker.qual.startswith("pytest.mark.") or marker.qual in _MARKERS):
        return value  # pytest marks and launch_testing's keep_alive give back the function itself
    d = ev.ev(dec, scope) if target is not dec else marker
    if isinstance(value, Opaque):
        return value
    name = ast.unparse(dec) if len(ast.unparse(dec)) < 60 else "..."
    if isinstance(d, Ref):
        qual = api.canonical(d.qual) or d.qual
        if qual in ("functools.cache", "functools.lru_cache") and isinstance(value, UserFunc):
            return cached(value, None if qual == "functools.cache" else LRU_DEFAULT)
        if qual in _METHOD_KINDS and isinstance(scope, ClassScope):
            return MethodKind(_METHOD_KINDS[qual], value)
    if isinstance(d, Decorator) and d.kind == "cache" and isinstance(value, UserFunc):
        return cached(value, d.maxsize)
    if isinstance(d, UserFunc):
        return call_user(ev, d, [value], {}, span)
    why = f" ({d.reason})" if isinstance(d, Opaque) else ""
    return Opaque(f'decorator "@{name}" cannot be evaluated statically{why}', span)


def memo_key(args: list[Any], kwargs: dict[str, Any]) -> Any:
    """The lru_cache key of a call; ``TypeError`` for unhashable arguments (as lru_cache raises)."""
    key = (tuple(args), tuple(kwargs.items()))
    hash(key)
    return key


# ---- classes ----------------------------------------------------------------------------------


def define_class(ev: Evaluator, s: ast.ClassDef, scope: Scope) -> Any:
    span = ev.span(s, scope)

    def refuse(why: str) -> Opaque:
        return Opaque(f'class "{s.name}" cannot be evaluated statically: {why}', span)

    if s.keywords:
        return refuse("it has a metaclass or class keywords")
    bases = [ev.ev(b, scope) for b in s.bases]
    base: ClassValue | None = None
    unknown_base: str | None = None
    for b in bases:
        if isinstance(b, Ref) and b.qual == "builtins.object":
            continue
        if isinstance(b, ClassValue) and base is None and len(bases) == 1:
            base = b
            continue
        if isinstance(b, ClassValue):
            return refuse("it derives from a class that is not a simple class of this file")
        # A base imported from elsewhere (IsaacROSLaunchFragment): Python finds what the class body
        # defines before looking in any base, so that much is known; the rest is not.
        unknown_base = (f'it derives from a class that cannot be evaluated statically '
                        f'("{ast.unparse(s.bases[bases.index(b)])}")')
    decorators = [ev.ev(d, scope) for d in s.decorator_list]
    data: Decorator | None = None
    for d in decorators:
        if isinstance(d, Ref) and d.qual == "dataclasses.dataclass":
            d = Decorator("dataclass")
        if not (isinstance(d, Decorator) and d.kind == "dataclass") or data is not None:
            return refuse("it has a decorator other than @dataclass")
        data = d
    if unknown_base is not None and data is not None:
        return refuse(unknown_base)  # a dataclass's fields and __init__ come from its bases too
    cscope = ClassScope(scope)
    ev.exec_block(s.body, cscope)
    attrs = cscope.vars
    cls = ClassValue(s.name, attrs, base, unknown_base=unknown_base)
    for v in attrs.values():
        func = v.func if isinstance(v, MethodKind) else v
        if isinstance(func, UserFunc) and func.owner is None:
            func.owner = cls
    odd = sorted(k for k in attrs if k.startswith("__") and k.endswith("__") and k not in _SIMPLE_DUNDERS)
    if odd:
        return refuse(f'it defines "{odd[0]}"')
    if base is not None and (base.fields is not None) != (data is not None):
        return refuse("it mixes dataclasses and plain classes")
    if data is None:
        return cls
    fields = list(base.fields or ()) if base is not None else []
    for stmt in s.body:
        if isinstance(stmt, ast.AnnAssign) and isinstance(stmt.target, ast.Name):
            note = ast.unparse(stmt.annotation)
            if any(w in note for w in ("ClassVar", "InitVar", "KW_ONLY")):
                return refuse(f'field annotation "{note}"')
            if stmt.target.id not in fields:
                fields.append(stmt.target.id)
    defaults: dict[str, FieldSpec] = dict(base.defaults) if base is not None else {}
    for f in fields:
        if f in attrs:
            own = attrs[f]
            spec = own if isinstance(own, FieldSpec) else FieldSpec(own, _MISSING)
            if isinstance(spec.default, (list, dict, set)):
                return refuse(f'mutable default for field "{f}"')  # ValueError in Python
            defaults[f] = spec
            if spec.default is not _MISSING:
                attrs[f] = spec.default
            else:
                attrs.pop(f)
    seen_default = False
    for f in fields:
        if seen_default and f not in defaults:
            return refuse(f'field "{f}" without a default follows a field with one')  # TypeError
        seen_default = seen_default or f in defaults
    cls.fields, cls.frozen, cls.defaults = tuple(fields), bool(data.options.get("frozen")), defaults
    return cls


def chain(cls: ClassValue | None) -> Iterator[ClassValue]:
    while cls is not None:
        yield cls
        cls = cls.base


def _unknown_base(cls: ClassValue) -> str | None:
    """Why a base class of ``cls`` cannot be followed (``ClassValue.unknown_base``), if one cannot."""
    return next((c.unknown_base for c in chain(cls) if c.unknown_base), None)


def lookup(cls: ClassValue, name: str) -> Any:
    for c in chain(cls):
        if name in c.attrs:
            return c.attrs[name]
    return None


def instantiate(ev: Evaluator, cls: ClassValue, args: list[Any], kwargs: dict[str, Any], span: Span,
                written: bool = False) -> Any:
    """``cls(*args, **kwargs)``; ``written``: a call the file writes (``call_user``)."""
    from .calls import call_user

    hidden = _unknown_base(cls)
    if hidden is not None:  # its base's __init__ (or __new__) may run: what it builds is unknown
        ev.escape([*args, *kwargs.values()])  # and it may read the configurations it is given
        return Opaque(f'class "{cls.name}" cannot be evaluated statically: {hidden}', span)
    inst = Instance(cls)
    init = lookup(cls, "__init__")
    try:
        if isinstance(init, UserFunc):
            r = call_user(ev, init, [inst, *args], dict(kwargs), span, written)
            if r is not None:
                return Opaque(r.reason if isinstance(r, Opaque) else f"{cls.name}.__init__ returns a value", span)
        elif init is not None:
            return Opaque(f'"{cls.name}.__init__" cannot be evaluated statically', span)
        elif cls.fields is not None:
            specs = cls.defaults
            if len(args) > len(cls.fields) or set(kwargs) - set(cls.fields):
                return Opaque(f'{cls.name}() with unexpected arguments', span)
            for i, name in enumerate(cls.fields):
                if i < len(args):
                    if name in kwargs:
                        return Opaque(f'{cls.name}() got "{name}" twice', span)
                    value = args[i]
                elif name in kwargs:
                    value = kwargs[name]
                elif name in specs and specs[name].factory is not _MISSING:
                    value = call_value(ev, specs[name].factory, span)
                elif name in specs:
                    value = specs[name].default
                else:
                    return Opaque(f'{cls.name}() missing argument "{name}"', span)
                inst.attrs[name] = value
            post = lookup(cls, "__post_init__")
            if isinstance(post, UserFunc):
                r = call_user(ev, post, [inst], {}, span)
                if r is not None:
                    return Opaque(r.reason if isinstance(r, Opaque) else "__post_init__ returns a value", span)
        elif args or kwargs:
            return Opaque(f"{cls.name}() takes no arguments", span)
    except Raise:
        return Opaque(f"{cls.name}() raises an exception", span)
    return inst


def call_value(ev: Evaluator, func: Any, span: Span) -> Any:
    """``func()`` for a dataclass ``default_factory``."""
    from .calls import call_ref, call_user

    if isinstance(func, UserFunc):
        return call_user(ev, func, [], {}, span)
    if isinstance(func, ClassValue):
        return instantiate(ev, func, [], {}, span)
    if isinstance(func, Ref) and func.qual.startswith("builtins."):
        return call_ref(ev, func.qual, [], {}, span)
    return Opaque("a default_factory that cannot be evaluated statically", span)


def zero_arg_super(ev: Evaluator, span: Span) -> Any:
    """``super()`` in a method of a simple class with a simple base class."""
    if not ev.frames:
        return Opaque("super() outside a method", span)
    f, fscope = ev.frames[-1]
    owner = f.owner
    params = f.node.args.posonlyargs + f.node.args.args
    if not isinstance(owner, ClassValue) or owner.base is None or not params:
        return Opaque("super() without a base class of this file", span)
    return SuperProxy(owner.base, fscope.vars.get(params[0].arg))


def get_attr(ev: Evaluator, obj: ClassValue | Instance | SuperProxy, attr: str, span: Span) -> Any:
    from .calls import call_user

    if isinstance(obj, Instance) and attr in obj.attrs:
        return obj.attrs[attr]
    if isinstance(obj, SuperProxy):
        cls, obj = obj.start, obj.obj
        if not isinstance(obj, (Instance, ClassValue)):
            return Opaque("super() of a value that cannot be evaluated statically", span)
    else:
        cls = obj.cls if isinstance(obj, Instance) else obj
    v = lookup(cls, attr)
    if v is None and not any(attr in c.attrs for c in chain(cls)):
        hidden = _unknown_base(cls)
        if hidden is not None:
            return Opaque(f'"{attr}" of class "{cls.name}" may come from its base: {hidden}', span)
        return Opaque(f'"{cls.name}" has no attribute "{attr}" known statically', span)
    if isinstance(v, MethodKind):
        if v.kind == "static":
            return v.func
        if v.kind == "class":
            return BoundUser(v.func, cls) if isinstance(v.func, UserFunc) else v.func
        if isinstance(obj, Instance) and isinstance(v.func, UserFunc):
            return call_user(ev, v.func, [obj], {}, span)
        return Opaque(f'property "{attr}" of a class', span)
    if isinstance(v, UserFunc) and isinstance(obj, Instance):
        return BoundUser(v, obj)
    return v


def set_attr(obj: Any, attr: str, value: Any) -> bool:
    """``obj.attr = value`` on a simple class or instance; False for other objects, which are left
    as they are."""
    if isinstance(obj, Instance):
        if obj.cls.frozen:
            raise Raise()  # dataclasses.FrozenInstanceError
        obj.attrs[attr] = value
    elif isinstance(obj, ClassValue):
        obj.attrs[attr] = value
    else:
        return False
    return True
