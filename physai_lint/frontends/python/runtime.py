"""Runtime values of the partial evaluator.

Known Python data (str, int, list, dict ...) is held as real Python objects; everything else is
one of the symbolic classes below. Nothing here ever runs user code.
"""
from __future__ import annotations

import ast
from dataclasses import dataclass, field
from typing import Any

from physai_lint.model.launch import Condition
from physai_lint.model.span import Span
from physai_lint.model.values import Value


class SStr(str):
    """A string literal remembering where it was written (operations give back plain ``str``)."""

    span: Span | None

    def __new__(cls, s: str, span: Span | None) -> SStr:  # noqa: PYI034
        obj = super().__new__(cls, s)
        obj.span = span
        return obj

    def __reduce__(self) -> tuple[Any, ...]:
        # str's own reduce calls ``SStr(text)`` without the span, which raises: a parse result
        # holding one (a ``ComposableNode``'s ``extra_arguments`` keys) failed to come back from
        # a ``--jobs`` helper, and from the disk cache, and was parsed again every time.
        return SStr, (str(self), self.span)


@dataclass(eq=False)
class Opaque:
    """A value the evaluator cannot know."""

    reason: str
    span: Span | None = None


@dataclass(eq=False)
class Alternatives(Opaque):
    """One of several launch objects, each made in its own branch of an ``if`` the evaluator could
    not decide (``comp = ComposableNode(...A)`` / ``else: comp = ComposableNode(...B)``, used
    after the ``if``). Unknown to everything but the action and description lists, which keep
    every option under the condition of the branch it was made in, as for actions made there."""

    options: tuple[Any, ...] = ()


@dataclass(eq=False)
class SymStr:
    """A Python ``str`` at description time whose content is only known symbolically
    (``get_package_share_directory(...)``, ``LaunchConfiguration('x').perform(context)``)."""

    value: Value


@dataclass(eq=False)
class SymBool:
    """A comparison over launch-time values (``lc.perform(context) == 'true'``): a condition value."""

    value: Value
    negated: bool = False


@dataclass(eq=False)
class Ref:
    """A module, class or function reached through an import, by qualified name."""

    qual: str


@dataclass(eq=False)
class LObj:
    """An instance of a recognised launch/launch_ros class (action, substitution, condition ...)."""

    qual: str
    args: list[Any]
    kwargs: dict[str, Any]
    node: ast.Call
    span: Span
    arg_spans: list[Span]
    kw_spans: dict[str, Span]
    tags: tuple[CondTag, ...] = ()
    extra: dict[str, Any] = field(default_factory=dict)
    index: int = 0  # n-th object created at this call site

    def arg(self, pos: int, name: str, default: Any = None) -> Any:
        if name in self.kwargs:
            return self.kwargs[name]
        if pos >= 0 and pos < len(self.args):
            return self.args[pos]
        return default

    def has(self, pos: int, name: str) -> bool:
        return name in self.kwargs or (pos >= 0 and pos < len(self.args))

    def arg_span(self, pos: int, name: str) -> Span:
        if name in self.kw_spans:
            return self.kw_spans[name]
        if 0 <= pos < len(self.arg_spans):
            return self.arg_spans[pos]
        return self.span


@dataclass(eq=False)
class Branched(Opaque):
    """An item of a list made before an ``if`` the evaluator could not decide that only one
    branch left there: added (``params.append(path)`` under ``if path != '':``), or kept where the
    other branch removed it. Unknown to everything but the action and description lists, which
    keep ``value`` under the condition of that branch."""

    value: Any = None
    tag: Any = None  # CondTag


@dataclass(frozen=True)
class CondTag:
    """Why an object was created conditionally: a symbolic ``Condition`` or an unknown reason."""

    condition: Condition | None
    reason: str = ""


@dataclass(eq=False)
class UserFunc:
    node: ast.FunctionDef | ast.AsyncFunctionDef | ast.Lambda
    closure: Any  # Scope
    module: Any  # ModuleCtx
    defaults: list[Any] = field(default_factory=list)
    kw_defaults: dict[str, Any] = field(default_factory=dict)
    memo: dict[Any, Any] | None = None  # functools.cache / lru_cache results by argument key
    memo_size: int | None = None  # lru_cache(maxsize=N); None is unbounded
    owner: Any = None  # the ClassValue whose body defined it (for zero-argument super())


@dataclass(eq=False)
class Partial:
    """``functools.partial(func, *args, **kwargs)`` of a function of the file."""

    func: UserFunc
    args: list[Any]
    kwargs: dict[str, Any]

    def bind(self, args: list[Any], kwargs: dict[str, Any]) -> tuple[list[Any], dict[str, Any]]:
        return [*self.args, *args], {**self.kwargs, **kwargs}


@dataclass(eq=False)
class BoundMethod:
    obj: Any
    name: str


@dataclass(eq=False)
class FileHandle:
    path: str | None
    span: Span | None = None


@dataclass(eq=False)
class KPath:
    """A ``pathlib.Path`` over a known string."""

    path: str


@dataclass(eq=False)
class ContextSym:
    """The ``context`` argument of an ``OpaqueFunction``."""


@dataclass(eq=False)
class LaunchConfigsSym:
    """``context.launch_configurations``."""



@dataclass(eq=False)
class ModuleValue:
    """A sibling helper module evaluated statically."""

    name: str
    globals: dict[str, Any]


def type_name(v: Any) -> str:
    if isinstance(v, LObj):
        return v.qual.rsplit(".", 1)[-1]
    if isinstance(v, Instance):
        return f"{v.cls.name} object"
    return type(v).__name__


@dataclass(eq=False)
class ClassValue:
    """A class defined in the launch file that stays simple enough to evaluate (``classes.py``)."""

    name: str
    attrs: dict[str, Any]
    base: ClassValue | None = None
    fields: tuple[str, ...] | None = None  # dataclass fields in order; None for a plain class
    frozen: bool = False
    defaults: dict[str, FieldSpec] = field(default_factory=dict)  # dataclass field defaults
    # Why its base class cannot be followed (imported from another package): then only what its
    # own body defines is known, and it is never instantiated (``classes.instantiate``).
    unknown_base: str | None = None


@dataclass(eq=False)
class Instance:
    cls: ClassValue
    attrs: dict[str, Any] = field(default_factory=dict)


@dataclass(eq=False)
class BoundUser:
    """A method of a user class bound to its instance (or a classmethod to its class)."""

    func: UserFunc
    obj: Any


@dataclass(eq=False)
class SuperProxy:
    """``super()`` inside a method: attribute lookup starts after the defining class."""

    start: ClassValue
    obj: Any


@dataclass(eq=False)
class MethodKind:
    """``staticmethod``/``classmethod``/``property`` around a function in a class body."""

    kind: str
    func: Any


@dataclass(eq=False)
class Decorator:
    """A known decorator value: ``functools.lru_cache(maxsize=...)`` or ``dataclass(...)``."""

    kind: str
    maxsize: int | None = None
    options: dict[str, Any] = field(default_factory=dict)


@dataclass(eq=False)
class FieldSpec:
    """``dataclasses.field(default=..., default_factory=...)``."""

    default: Any
    factory: Any
