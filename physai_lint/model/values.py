"""Launch values: a value is a tuple of substitutions, never a plain string.

The frontends (Python, XML, YAML) turn what they read into these; ``physai_lint.resolve`` evaluates
them into ``str`` or an ``Unknown``. Nothing here is ever executed: ``Command`` and ``PythonExpr``
are kept as data (``PythonExpr`` is evaluated by our own safe evaluator when its parts are known).
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Literal, Union

from physai_lint.model.pickling import fast_init, fast_pickle_module

from .span import Span


@fast_init
@dataclass(frozen=True, slots=True)
class Text:
    text: str
    span: Span | None = None


@fast_init
@dataclass(frozen=True, slots=True)
class LaunchConfig:
    """``LaunchConfiguration('name', default=...)`` / ``$(var name [default])``."""

    name: "Value"
    default: "Value | None"
    span: Span | None = None


@dataclass(frozen=True, slots=True)
class EnvVar:
    """``EnvironmentVariable`` / ``$(env NAME [default])``."""

    name: "Value"
    default: "Value | None"
    span: Span | None = None


@dataclass(frozen=True, slots=True)
class FindPackage:
    """``FindPackageShare``/``$(find-pkg-share)`` (kind "share"), ``FindPackagePrefix`` ("prefix"),
    ``get_package_share_directory`` ("share", evaluated at description time: ``eager=True``)."""

    package: "Value"
    kind: Literal["share", "prefix"]
    span: Span | None = None
    eager: bool = False


@dataclass(frozen=True, slots=True)
class ExecInPackage:
    """``$(exec-in-pkg EXE PKG)`` / ``ExecutableInPackage``."""

    executable: "Value"
    package: "Value"
    span: Span | None = None


@dataclass(frozen=True, slots=True)
class FindExecutable:
    """``FindExecutable(name=)`` / ``$(find-exec NAME)``: depends on the machine's PATH -> unknown."""

    name: "Value"
    span: Span | None = None


@dataclass(frozen=True, slots=True)
class PathJoin:
    """``PathJoinSubstitution([...])`` or ``os.path.join`` over substitutions (joined with ``/``)."""

    parts: tuple["Value", ...]
    span: Span | None = None


@dataclass(frozen=True, slots=True)
class ThisFileDir:
    """``ThisLaunchFileDir()`` / ``$(dirname)``: the *current* launch file directory local, which an
    include sets and never restores (SEMANTICS §1)."""

    span: Span | None = None


@dataclass(frozen=True, slots=True)
class ThisFile:
    """``ThisLaunchFile()`` / ``$(filename)``."""

    span: Span | None = None


@dataclass(frozen=True, slots=True)
class Command:
    """``Command([...])`` / ``$(command ...)``: never run; always unknown."""

    command: "Value"
    span: Span | None = None


@dataclass(frozen=True, slots=True)
class PythonExpr:
    """``PythonExpression([...])`` / ``$(eval EXPR [MODULES])``: evaluated by the safe evaluator only."""

    expression: "Value"
    modules: tuple[str, ...] | None = ("math",)  # None: not known statically
    span: Span | None = None
    modules_value: "Value | None" = None  # the modules argument when it is not a literal


@dataclass(frozen=True, slots=True)
class Anon:
    """``AnonName`` / ``$(anon NAME)``: a random suffix at run time -> unknown name."""

    name: "Value"
    span: Span | None = None


@dataclass(frozen=True, slots=True)
class BoolOp:
    """``$(not)``, ``$(and)``, ``$(or)``, ``$(any)``, ``$(all)``, ``NotSubstitution``,
    ``AndSubstitution``, ``OrSubstitution``, ``AnySubstitution``, ``AllSubstitution``."""

    op: Literal["not", "and", "or", "any", "all"]
    operands: tuple["Value", ...]
    span: Span | None = None


# What LaunchConfigurationEquals/NotEquals compare an unset configuration as (the default of their
# LaunchConfig): no value launch gives is this text
UNSET_CONFIGURATION = "\x00(unset)"


@dataclass(frozen=True, slots=True)
class Compare:
    """``EqualsSubstitution``/``$(equals A B)`` and ``NotEqualsSubstitution``/``$(not-equals A B)``."""

    op: Literal["equals", "not-equals"]
    left: "Value"
    right: "Value"
    span: Span | None = None


@dataclass(frozen=True, slots=True)
class IfElse:
    """``IfElseSubstitution`` / ``$(if COND A [B])``; a missing value is ``()``, the empty string."""

    condition: "Value"
    if_value: "Value"
    else_value: "Value"
    span: Span | None = None


@dataclass(frozen=True, slots=True)
class StrMethod:
    """A Python launch file's ``.lower()`` (``.upper()``, ``.strip()``, ...) of a string only known
    at launch time, e.g. ``LaunchConfiguration('x').perform(context).lower() == 'true'``."""

    method: Literal["lower", "upper", "casefold", "strip", "lstrip", "rstrip"]
    value: "Value"
    span: Span | None = None


@dataclass(frozen=True, slots=True)
class ParamRef:
    """``$(param NAME [DEFAULT])``: the value of a ``SetParameter`` in scope (DEFAULT since jazzy)."""

    name: "Value"
    span: Span | None = None
    default: "Value | None" = None


@dataclass(frozen=True, slots=True)
class FileContent:
    """``FileContent`` / ``$(file-content PATH)`` (jazzy+): unknown unless the file is read."""

    path: "Value"
    span: Span | None = None


# ---- nav2_common.launch helpers (data-only substitutions, modelled as nav2 implements them) ----


@dataclass(frozen=True, slots=True)
class Rewrite:
    """One entry of a ``RewrittenYaml``/``ReplaceString`` dict: a literal key and its value."""

    key: str
    value: "Value"
    span: Span | None = None


@dataclass(frozen=True, slots=True)
class RewrittenYaml:
    """``nav2_common.launch.RewrittenYaml``: the path of a temporary params file that is
    ``yaml.dump`` of the rewritten ``yaml.safe_load`` of ``path``. A dict given as something that
    cannot be evaluated statically is ``None``; ``convert_types`` is ``None`` when unknown."""

    path: "Value"
    param_rewrites: tuple[Rewrite, ...] | None
    root_key: "Value | None" = None
    key_rewrites: tuple[Rewrite, ...] | None = ()
    value_rewrites: tuple[Rewrite, ...] | None = ()
    convert_types: bool | None = False
    span: Span | None = None


@dataclass(frozen=True, slots=True)
class ReplaceString:
    """``nav2_common.launch.ReplaceString``: a temporary copy of ``path`` with every key replaced
    line by line; ``condition`` ("if"/"unless", value) false -> the source path itself."""

    path: "Value"
    replacements: tuple[Rewrite, ...] | None
    condition: "tuple[str, Value] | None" = None
    span: Span | None = None


@dataclass(frozen=True, slots=True)
class LaunchConfigAsBool:
    """``nav2_common.launch.LaunchConfigAsBool(name)``: "True" when the configuration's value
    ``.strip().lower()`` is one of true/1/yes/on, else "False". ``name`` holds the
    ``LaunchConfig`` it reads."""

    name: "Value"
    span: Span | None = None


@dataclass(frozen=True, slots=True)
class HasNodeParams:
    """``nav2_common.launch.HasNodeParams``: "True" when ``yaml.safe_load`` of ``path`` is a dict
    with the top-level key ``node_name``."""

    path: "Value"
    node_name: str | None
    span: Span | None = None


@dataclass(frozen=True, slots=True)
class Unknown:
    """Something that cannot be known statically. Rules stay silent on it."""

    reason: str
    span: Span | None = None


Subst = Union[
    Text, LaunchConfig, EnvVar, FindPackage, ExecInPackage, FindExecutable, PathJoin, ThisFileDir,
    ThisFile, Command, PythonExpr, Anon, BoolOp, Compare, IfElse, ParamRef, FileContent, Unknown,
    RewrittenYaml, ReplaceString, LaunchConfigAsBool, HasNodeParams, StrMethod,
]
Value = tuple[Subst, ...]


def text(s: str, span: Span | None = None) -> Value:
    """A value holding one literal string."""
    return (Text(s, span),)


def literal_of(value: Value | None) -> str | None:
    """The string a value stands for when it is made only of ``Text`` parts, else ``None``."""
    if value is None:
        return None
    out: list[str] = []
    for part in value:
        if not isinstance(part, Text):
            return None
        out.append(part.text)
    return "".join(out)


def span_of(value: Value | None) -> Span | None:
    """The span covering a value's parts (first part's start to last part's end) when known."""
    if not value:
        return None
    spans = [p.span for p in value if p.span is not None]
    if not spans:
        return None
    first, last = spans[0], spans[-1]
    if first.file != last.file:
        return first
    return Span(first.file, first.line, first.col, last.end_line, last.end_col)


# ---- parameter values -------------------------------------------------------------------------
# Parameter values are typed differently depending on where they come from (SEMANTICS §4a):
# a Python literal keeps its Python type; a string built from substitutions is typed by PyYAML
# (``yaml.safe_load``) after evaluation unless a ``value_type`` forces it.

PyScalar = Union[bool, int, float, str, bytes]


@dataclass(frozen=True, slots=True)
class PLit:
    """A Python literal (``0.3``, ``True``, ``'abc'``, ``[1, 2]``) given in a launch ``.py`` dict."""

    value: PyScalar | tuple[PyScalar, ...]
    span: Span | None = None
    item_spans: tuple[Span, ...] | None = None  # for a list literal: where each item is written


@dataclass(frozen=True, slots=True)
class PSubst:
    """A value made of substitutions (or an XML/YAML ``value=`` string): evaluated, then YAML-typed.

    ``value_type`` is ``"str"`` for ``ParameterValue(..., value_type=str)`` / ``type="str"``, or another
    declared type name, or ``None`` for YAML typing. ``sep`` is XML/YAML ``value-sep``. ``wrapped``:
    a Python ``ParameterValue(...)`` without a type, which launch's ``coerce_to_type`` reads (it
    raises ValueError where a bare substitution gets launch_ros's TypeError).
    """

    value: Value
    value_type: str | None = None
    span: Span | None = None
    sep: str | None = None
    wrapped: bool = False


@dataclass(frozen=True, slots=True)
class PList:
    """A Python list whose items are not all literals (e.g. ``[LaunchConfiguration('a'), 'b']``)."""

    items: tuple["PValue", ...]
    span: Span | None = None


@dataclass(frozen=True, slots=True)
class PUnknown:
    reason: str
    span: Span | None = None


PValue = Union[PLit, PSubst, PList, PUnknown]


fast_pickle_module(globals())  # tuples instead of dataclasses.fields() per object (model/pickling.py)
