"""Operations mixing known Python data with launch-time (symbolic) values, plus the recorder of
facts the evaluator collects while it runs (created objects, container spans, concatenations)."""
from __future__ import annotations

import ast
import os
from typing import Any

from physai_lint.model.launch import EVERY_CONFIGURATION, ConcatFact, LateFact, TypeFact
from physai_lint.model.span import Span
from physai_lint.model.values import BoolOp, Compare, FindPackage, IfElse, PathJoin, Value

from . import api, bounds
from .convert_values import to_value
from .runtime import KPath, LaunchConfigsSym, LObj, Opaque, SymBool, SymStr

MAX_SIZE = 100_000


class Recorder:
    def __init__(self) -> None:
        self.containers: dict[int, tuple[Any, Any]] = {}
        self.objects: list[LObj] = []
        self.site_counts: dict[tuple[str, int, int], int] = {}
        self.concats: dict[tuple[str, Span], ConcatFact] = {}
        self.kw_kinds: dict[tuple[int, str], str] = {}
        self.read_files: list[str] = []
        self.wrong_types: dict[tuple[str, Span], TypeFact] = {}
        # Values substituted eagerly (``lc.perform(context)``): read when the OpaqueFunction runs,
        # wherever the result goes.
        self.performed: list[Value] = []
        # ``context.launch_configurations.get(name)`` / ``[name]`` read the same way (``_peeked``).
        self.peeked: list[Value] = []
        # ``context.launch_configurations[name] = value`` in an OpaqueFunction: the live mapping,
        # so a set as ``SetLaunchConfiguration`` makes, before the actions the function returns.
        self.config_sets: list[tuple[str, Any, Span]] = []
        # ``if``s and conditional expressions decided neither way by a value that is not a launch
        # condition (``make = "Hesai" if model[:6] == "pandar" else ...``): an OpaqueFunction body
        # that counted some lost values its performed substitutions may decide (``convert_actions``).
        self.undecided = 0
        # What the resolver found for performed values, when a function is evaluated again for one
        # include (``frontends.python.specialize``): there they are these strings.
        self.known: dict[Value, str] = {}
        # Launch configurations handed to code the evaluator cannot follow (a library's builder,
        # an unknown function): that code may read them.
        self.escaped: set[str] = set()
        self.tests: dict[tuple[str, Span], ConcatFact] = {}
        # Calls of the file's own functions with arguments their signature refuses (TypeError).
        self.call_errors: dict[Span, ConcatFact] = {}
        # Package lookups made while the description is built (``get_package_share_directory``):
        # ``lookup`` keeps those that surely run (``PythonFacts.lookups``). ``guarded``: inside a
        # ``try`` body (the error may be caught), a function launch calls later (an OpaqueFunction,
        # an event handler's), or a branch the evaluator could not decide.
        self.lookups: list[Value] = []
        self.opens: list[tuple[Value, Span]] = []
        self.guarded = 0
        # Functions launch calls later whose bodies read variables of an enclosing function
        # (``calls.late_bindings``): (the action, the function, [(scope, name, value when made)],
        # run it again, the owner: (id, run) of the function whose body made it, or None).
        self.late_calls: list[tuple[LObj, Any, list[tuple[Any, str, Any]], Any, tuple[int, int] | None]] = []
        self.late_bound: dict[tuple[Span, str], LateFact] = {}
        self.late_runs: dict[int, int] = {}  # id of the action -> how many times its function ran
        self.late_owner: tuple[int, int] | None = None

    def lookup(self, found: FindPackage) -> None:
        if not self.guarded and not getattr(self, "cond_stack", None):
            self.lookups.append((found,))

    def opened(self, path: Any, span: Span) -> None:
        """``open(path)`` / ``Path(path).read_text()`` of a path known only symbolically (in a
        package's share directory): it surely runs unless ``guarded`` (``PythonFacts.opens``)."""
        if isinstance(path, KPath):
            path = path.path
        if isinstance(path, SymStr) and not self.guarded and not getattr(self, "cond_stack", None):
            self.opens.append((path.value, span))

    def escape(self, values: Any, depth: int = 0) -> None:
        """Note the launch configurations (by literal name) in ``values``: arguments of a call the
        evaluator cannot follow, searched through lists, tuples, dicts and launch objects."""
        if depth > 8:
            return
        for v in values:
            if isinstance(v, LaunchConfigsSym):
                self.escaped.add(EVERY_CONFIGURATION)
            elif isinstance(v, LObj):
                if v.qual == "launch.substitutions.LaunchConfiguration":
                    name = v.arg(0, "variable_name")
                    if isinstance(name, str):
                        self.escaped.add(str(name))
                        # its default is read when the configuration is unset (``default=dof``)
                        self.escape([v.kwargs[k] for k in ("default",) if k in v.kwargs], depth + 1)
                        continue
                self.escape([*v.args, *v.kwargs.values()], depth + 1)
            elif isinstance(v, (list, tuple)):
                self.escape(v, depth + 1)
            elif isinstance(v, dict):
                self.escape([*v.keys(), *v.values()], depth + 1)

    def register(self, obj: Any, spans: Any) -> Any:
        self.containers[id(obj)] = (obj, spans)
        return obj

    def item_spans(self, obj: Any) -> Any:
        entry = self.containers.get(id(obj))
        return entry[1] if entry is not None and entry[0] is obj else None

    def concat(self, how: str, span: Span, detail: str) -> None:
        key = (how, span)
        if key not in self.concats:
            self.concats[key] = ConcatFact(how, span, detail)  # type: ignore[arg-type]

    def substitution_tested(self, how: str, span: Span, subst: Any, other: Any = None) -> None:
        """A substitution object tested as a Python value (``if lc:``, ``lc == 'true'``)."""
        key = (how, span)
        if key in self.tests:
            return
        if how == "condition":
            shown = shown_condition(subst)
        else:
            shown = shown_subst(subst)
            if how != "truth":
                shown += (" == " if how == "equals" else " != ") + repr_text(other)
        self.tests[key] = ConcatFact(how, span, shown)  # type: ignore[arg-type]

    def wrong_type(self, kind: str, call: str, value: Any, span: Span) -> None:
        key = (call, span)
        if key not in self.wrong_types:
            # an action given where an event belongs: named in full (launch.actions.Shutdown)
            text = f"{value.qual}(...)" if kind == "event" and isinstance(value, LObj) else shown_value(value)
            if len(text) > 60:
                text = text[:57] + "..."
            kind_name = "substitution" if is_subst(value) else \
                "string" if isinstance(value, str) else type(value).__name__
            self.wrong_types[key] = TypeFact(kind, call, text, kind_name, span)  # type: ignore[arg-type]


def shown_value(value: Any) -> str:
    """A value as the launch file wrote it, for messages: strings, numbers and bools as Python
    literals, anything else as ``...``; a dict by its keys."""
    if isinstance(value, dict):
        return "{" + ", ".join(f"{shown_value(k)}: ..." for k in value) + "}"
    if isinstance(value, (list, tuple)):
        inner = ", ".join(shown_value(x) for x in value)
        return f"[{inner}]" if isinstance(value, list) else f"({inner}{',' if len(value) == 1 else ''})"
    if isinstance(value, str):
        return repr(str(value))
    if type(value) in (bool, int, float):
        return repr(value)
    if is_subst(value):
        args = ", ".join(shown_value(a) for a in value.args)
        return f"{api.short(value.qual)}({args})"
    return "..."


def is_subst(v: Any) -> bool:
    return isinstance(v, LObj) and api.is_substitution(v.qual)


def is_condition(v: Any) -> bool:
    """A launch condition object (``IfCondition(...)``): like a substitution, always true in Python."""
    return isinstance(v, LObj) and v.qual.startswith("launch.conditions.")


def shown_condition(v: Any) -> str:
    """``IfCondition(LaunchConfiguration("x"))``, ``LaunchConfigurationEquals("mode", "sim")``."""
    name = _subst_name(v)
    if name in ("LaunchConfigurationEquals", "LaunchConfigurationNotEquals"):
        parts = [v.arg(0, "launch_configuration_name"), v.arg(1, "expected_value")]
        return f"{name}({', '.join(repr_text(p) for p in parts)})"
    arg = v.arg(0, "predicate_expression") if isinstance(v, LObj) else None
    return f"{name}({repr_text(arg)})"


def repr_text(v: Any) -> str:
    """A string quoted, a substitution as ``shown_subst`` shows it, anything else as ``...``."""
    return f'"{v}"' if isinstance(v, str) else shown_subst(v) if is_subst(v) else "..."


def is_symstr(v: Any) -> bool:
    return isinstance(v, SymStr)


def is_textlike(v: Any) -> bool:
    return isinstance(v, (str, SymStr)) or is_subst(v)


def shown_subst(v: Any) -> str:
    """``LaunchConfiguration("x")`` for a configuration with a literal name, else the class name."""
    name = v.arg(0, "variable_name") if isinstance(v, LObj) and v.qual.endswith(".LaunchConfiguration") else None
    return f'LaunchConfiguration("{name}")' if isinstance(name, str) else _subst_name(v)


def _subst_name(v: Any) -> str:
    return api.short(v.qual) if isinstance(v, LObj) else "value"


def binop(rec: Recorder, op: ast.operator, left: Any, right: Any, span: Span) -> Any:
    if isinstance(op, ast.Add) and is_textlike(left) and is_textlike(right):
        if not (isinstance(left, str) and isinstance(right, str)):
            for v in (left, right):
                if is_subst(v):
                    rec.concat("plus", span, shown_subst(v))
                    break
            return SymStr(to_value(left, span) + to_value(right, span))
        return None
    if isinstance(op, ast.Div) and isinstance(left, KPath):
        if is_subst(right):  # PurePath.__truediv__ takes str or os.PathLike: TypeError
            rec.concat("path", span, shown_subst(right))
            return Opaque("a substitution joined to a pathlib.Path", span)
        return path_join([left, right], span)  # a KPath again: the next / joins on
    if isinstance(op, ast.Mod) and isinstance(left, str):
        args = right if isinstance(right, tuple) else (right,)
        if any(is_textlike(a) and not isinstance(a, str) for a in args):
            for a in args:
                if is_subst(a):
                    rec.concat("percent", span, shown_subst(a))
            return Opaque("string formatting of a launch-time value", span)
    return None


def path_join(parts: list[Any], span: Span) -> Any:
    """``os.path.join``/``Path /`` over strings or symbolic strings (no facts recorded here)."""
    for p in parts:
        if isinstance(p, Opaque):
            return Opaque(p.reason, span)
    flat = [p.path if isinstance(p, KPath) else p for p in parts]
    if all(isinstance(p, str) for p in flat):
        return KPath(os.path.join(*flat)) if isinstance(parts[0], KPath) else os.path.join(*flat)
    if not all(is_textlike(p) for p in flat):
        return Opaque("path join of values that cannot be evaluated statically", span)
    value = (PathJoin(tuple(to_value(p, span) for p in flat), span),)
    sym = SymStr(value)
    return KPath(sym) if isinstance(parts[0], KPath) else sym  # type: ignore[arg-type]


def small_enough(op: ast.operator, left: Any, right: Any) -> bool:
    if isinstance(op, ast.Mult):
        for a, b in ((left, right), (right, left)):
            if isinstance(a, (str, bytes, list, tuple)) and isinstance(b, int):
                return len(a) * b <= MAX_SIZE
        return not bounds.int_op_too_big("mul", left, right)
    if isinstance(op, ast.Pow):
        return not (isinstance(right, int) and right > 256) and not bounds.int_op_too_big("pow", left, right)
    if isinstance(op, ast.LShift):
        return not (isinstance(right, int) and right > 4096) and not bounds.int_op_too_big("lshift", left, right)
    if isinstance(op, ast.Mod) and isinstance(left, str):
        star_args = right if isinstance(right, tuple) else (right,)
        return not (bounds.wide_format(left) or "*" in left and any(
            isinstance(a, int) and a > bounds.MAX_WEIGHT for a in star_args))
    return True


def compare(op: ast.cmpop, left: Any, right: Any, span: Span) -> SymBool | None:
    if not isinstance(op, (ast.Eq, ast.NotEq)):
        return None
    sides = (left, right)
    if not any(isinstance(s, SymStr) for s in sides):  # a substitution object: identity (ex_Compare)
        return None
    conv = []
    for s in sides:
        if isinstance(s, (bool, int, float)):
            s = str(s)
        if not is_textlike(s):
            return None
        conv.append(to_value(s, span))
    kind = "equals" if isinstance(op, ast.Eq) else "not-equals"
    return SymBool((Compare(kind, conv[0], conv[1], span),))  # type: ignore[arg-type]


def bool_value(s: SymBool) -> Value:
    if s.negated:
        return (BoolOp("not", (s.value,)),)
    return s.value


def combine(syms: list[SymBool], op: str, span: Span) -> SymBool:
    return SymBool((BoolOp(op, tuple(bool_value(s) for s in syms), span),))  # type: ignore[arg-type]


def if_else(rec: Recorder, test: Any, a: Any, b: Any, span: Span) -> Any:
    if isinstance(test, SymBool) and is_textlike(a) and is_textlike(b):
        return SymStr((IfElse(bool_value(test), to_value(a, span), to_value(b, span), span),))
    if a is b:
        return a
    return Opaque("value depends on a condition known only at launch time", span)


def format_value(rec: Recorder, x: Any, conversion: int, spec: Any, span: Span) -> Any:
    if isinstance(x, Opaque):
        return x
    if is_textlike(x) and not isinstance(x, str):
        if is_subst(x):
            rec.concat("f-string", span, shown_subst(x))
        return x
    if isinstance(x, KPath):
        return x.path
    from .core import is_concrete

    if not is_concrete(x):
        return Opaque("f-string of a value that cannot be evaluated statically", span)
    if not isinstance(spec, str):
        return Opaque("f-string with an unknown format spec", span)
    if bounds.wide_format(spec):
        return Opaque("f-string field too wide", span)
    try:
        if conversion == ord("r"):
            x = repr(x)
        elif conversion == ord("a"):
            x = ascii(x)
        elif conversion == ord("s"):
            x = str(x)
        if isinstance(x, str) and not spec:
            return str(x)
        return format(x, spec)
    except Exception:  # noqa: BLE001
        return Opaque("f-string formatting fails", span)


def join_parts(rec: Recorder, parts: list[Any], span: Span) -> Any:
    for p in parts:
        if isinstance(p, Opaque):
            return Opaque(p.reason, span)
    if all(isinstance(p, str) for p in parts):
        return "".join(parts)
    value: Value = ()
    for p in parts:
        value = value + to_value(p, span)
    return SymStr(value)
