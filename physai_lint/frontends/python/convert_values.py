"""Evaluated Python objects -> IR substitution values, conditions and parameter values."""
from __future__ import annotations

from typing import Any

from physai_lint.model import values as V
from physai_lint.model.launch import (
    Condition,
    ParamDict,
    ParamEntry,
    ParamFile,
    ParamSource,
    ParamsUnknown,
)
from physai_lint.model.span import Span
from physai_lint.model.values import (
    UNSET_CONFIGURATION,
    PList,
    PLit,
    PSubst,
    PUnknown,
    PValue,
    Value,
)

from . import api
from .runtime import KPath, LObj, Opaque, SStr, SymBool, SymStr, type_name

# the registry of container item spans is filled by the evaluator (symbolic.Recorder)
_SPANS: list[Any] = []


def set_recorder(rec: Any) -> None:
    _SPANS.clear()
    _SPANS.append(rec)


def item_spans(obj: Any) -> Any:
    return _SPANS[0].item_spans(obj) if _SPANS else None


def span_at(obj: Any, i: int, default: Span) -> Span:
    spans = item_spans(obj)
    if isinstance(spans, list) and i < len(spans):
        return spans[i]  # type: ignore[no-any-return]
    return default


def to_value(v: Any, span: Span | None) -> Value:
    """A Python object given where a launch value (SomeSubstitutionsType) is expected."""
    if v is None:
        return ()
    if isinstance(v, str):
        return (V.Text(str(v), v.span if isinstance(v, SStr) else span),)
    if isinstance(v, (bool, int, float)):
        return (V.Text(str(v), span),)
    if isinstance(v, SymStr):
        return v.value
    if isinstance(v, SymBool):
        return v.value
    if isinstance(v, KPath):
        return to_value(v.path, span)
    if isinstance(v, LObj):
        if v.qual.endswith(".ParameterValue"):
            return to_value(v.arg(0, "value"), v.arg_span(0, "value"))
        if api.is_substitution(v.qual):
            text = v.arg(0, "text", "") if api.short(v.qual) == "TextSubstitution" else None
            if isinstance(text, (SymStr, KPath)):  # a str at run time, known only in parts here
                return to_value(text, v.span)  # (TextSubstitution(text=get_package_share_directory(..) + ..))
            return (subst(v),)
        return (V.Unknown(f"{api.short(v.qual)} is not a substitution", v.span),)
    if isinstance(v, (list, tuple)):
        out: Value = ()
        for i, item in enumerate(v):
            out = out + to_value(item, span_at(v, i, span) if span else span)
        return out
    if isinstance(v, Opaque):
        return (V.Unknown(v.reason, v.span or span),)
    return (V.Unknown(f"not a launch value ({type_name(v)})", span),)


def opt_value(obj: LObj, pos: int, name: str) -> Value | None:
    if not obj.has(pos, name):
        return None
    v = obj.arg(pos, name)
    if v is None:
        return None
    return to_value(v, obj.arg_span(pos, name))


def _val(obj: LObj, pos: int, name: str) -> Value:
    return opt_value(obj, pos, name) or ()


def subst(o: LObj) -> V.Subst:
    n = api.short(o.qual)
    s = o.span
    if n == "TextSubstitution":
        return V.Text(str(o.arg(0, "text", "")), s) if isinstance(o.arg(0, "text", ""), str) else V.Unknown("text", s)
    if n == "LaunchConfiguration":
        return V.LaunchConfig(_val(o, 0, "variable_name"), opt_value(o, 1, "default"), s)
    if n in ("PathJoinSubstitution", "PathSubstitution"):
        parts = api.path_parts(o)
        if isinstance(parts, (list, tuple)):
            return V.PathJoin(tuple(to_value(p, span_at(parts, i, s)) for i, p in enumerate(parts)), s)
        return V.PathJoin((to_value(parts, s),), s)
    if n in ("FindPackageShare", "FindPackagePrefix"):
        return V.FindPackage(_val(o, 0, "package"), "share" if n.endswith("Share") else "prefix", s)
    if n == "FindExecutable":
        return V.FindExecutable(_val(o, 0, "name"), s)
    if n == "ExecutableInPackage":
        return V.ExecInPackage(_val(o, 0, "executable"), _val(o, 1, "package"), s)
    if n == "EnvironmentVariable":
        return V.EnvVar(_val(o, 0, "name"), opt_value(o, 1, "default_value"), s)
    if n == "ThisLaunchFileDir":
        return V.ThisFileDir(s)
    if n == "ThisLaunchFile":
        return V.ThisFile(s)
    if n == "Command":
        return V.Command(_val(o, 0, "command"), s)
    if n == "PythonExpression":
        mods = o.arg(1, "python_modules", None)
        modules: tuple[str, ...] | None = ("math",) if mods is None else tuple(str(m) for m in mods) \
            if isinstance(mods, (list, tuple)) and all(isinstance(m, str) for m in mods) else None  # None: not known
        return V.PythonExpr(_val(o, 0, "expression"), modules, s)
    if n == "AnonName":
        return V.Anon(_val(o, 0, "name"), s)
    if n == "NotSubstitution":
        return V.BoolOp("not", (_val(o, 0, "value"),), s)
    if n in ("AndSubstitution", "OrSubstitution"):
        return V.BoolOp("and" if n.startswith("And") else "or", (_val(o, 0, "left"), _val(o, 1, "right")), s)
    if n in ("AnySubstitution", "AllSubstitution"):
        ops = tuple(to_value(a, o.arg_span(i, "")) for i, a in enumerate(o.args))
        return V.BoolOp("any" if n.startswith("Any") else "all", ops, s)
    if n in ("EqualsSubstitution", "NotEqualsSubstitution"):
        return V.Compare("equals" if n.startswith("Equals") else "not-equals", _val(o, 0, "left"), _val(o, 1, "right"), s)
    if n == "IfElseSubstitution":
        return V.IfElse(_val(o, 0, "condition"), _val(o, 1, "if_value"), _val(o, 2, "else_value"), s)
    if n == "Parameter":
        return V.ParamRef(_val(o, 0, "name"), s, opt_value(o, 1, "default"))
    if n == "FileContent":
        return V.FileContent(_val(o, 0, "path"), s)
    if o.qual in api.NAV2_SUBSTITUTIONS:
        return _nav2(o, n, s)
    return V.Unknown(f"substitution {n} cannot be evaluated statically", s)


def _rewrites(o: LObj, pos: int, name: str) -> tuple[V.Rewrite, ...] | None:
    """A ``dict[str, SomeSubstitutionsType]`` argument as literal keys and values (None: unknown)."""
    d = o.arg(pos, name)
    if d is None or (isinstance(d, (str, list, tuple)) and not d):
        return ()  # nav2 iterates it: an empty str/list is an empty dict (param_rewrites="")
    if not isinstance(d, dict) or not all(isinstance(k, str) for k in d):
        return None
    spans = item_spans(d) if isinstance(item_spans(d), dict) else {}
    out = []
    for k, val in d.items():
        _kspan, vspan = spans.get(k, (o.arg_span(pos, name),) * 2)
        out.append(V.Rewrite(str(k), to_value(val, vspan), vspan))
    return tuple(out)


def _nav2(o: LObj, n: str, s: Span) -> V.Subst:
    if n == "LaunchConfigAsBool":
        name = _val(o, 0, "name")
        return V.LaunchConfigAsBool((V.LaunchConfig(name, None, s),), s)
    if n == "HasNodeParams":
        node = o.arg(1, "node_name")
        return V.HasNodeParams(_val(o, 0, "source_file"), str(node) if isinstance(node, str) else None, s)
    if n == "ReplaceString":
        cond = o.arg(2, "condition")
        condition = None
        if cond is not None:
            c = to_condition(cond, o.arg_span(2, "condition"))
            condition = (c.kind, c.value) if c is not None else None
        return V.ReplaceString(_val(o, 0, "source_file"), _rewrites(o, 1, "replacements"), condition, s)
    convert = o.arg(5, "convert_types", False)
    return V.RewrittenYaml(
        _val(o, 0, "source_file"), _rewrites(o, 1, "param_rewrites"), opt_value(o, 2, "root_key"),
        _rewrites(o, 3, "key_rewrites"), _rewrites(o, 4, "value_rewrites"),
        convert if isinstance(convert, bool) else None, s)


def to_condition(c: Any, span: Span) -> Condition | None:
    if c is None:
        return None
    if isinstance(c, LObj):
        n = api.short(c.qual)
        raw = f"{n}(...)"
        if n in ("IfCondition", "UnlessCondition"):
            pred = to_value(c.arg(0, "predicate_expression"), c.arg_span(0, "predicate_expression"))
            return Condition("if" if n == "IfCondition" else "unless", pred, c.span, raw)
        if n in ("LaunchConfigurationEquals", "LaunchConfigurationNotEquals"):
            # An unset configuration does not raise here: _predicate_func catches the KeyError and
            # compares "unset" with the expected value, true only for expected_value=None (launch
            # conditions/launch_configuration_equals.py). Both sides use one text no value has.
            name = to_value(c.arg(0, "launch_configuration_name"), c.arg_span(0, "launch_configuration_name"))
            expected = opt_value(c, 1, "expected_value") or (V.Text(UNSET_CONFIGURATION, c.span),)
            op = "equals" if n.endswith("Equals") and "Not" not in n else "not-equals"
            read = V.LaunchConfig(name, (V.Text(UNSET_CONFIGURATION, c.span),), c.span)  # type: ignore[arg-type]
            cmp = V.Compare(op, (read,), expected, c.span)
            return Condition("if", (cmp,), c.span, raw)
        return Condition("if", (V.Unknown(f"condition {n} cannot be evaluated statically", c.span),), c.span, raw)
    reason = c.reason if isinstance(c, Opaque) else f"condition of type {type_name(c)}"
    return Condition("if", (V.Unknown(reason, span),), span, "condition")


# ---- parameters -------------------------------------------------------------------------------
_SCALARS = (bool, int, float, str, bytes)


def to_pvalue(v: Any, span: Span) -> PValue:
    if isinstance(v, _SCALARS) and not isinstance(v, SymStr):
        return PLit(str(v) if isinstance(v, str) else v, v.span if isinstance(v, SStr) and v.span else span)
    if isinstance(v, (list, tuple)):
        if all(isinstance(x, _SCALARS) for x in v):
            spans = item_spans(v)
            items = tuple(spans) if isinstance(spans, list) and len(spans) == len(v) else None
            return PLit(tuple(str(x) if isinstance(x, str) else x for x in v), span, items)
        if _one_string(v):
            # launch_ros normalize_parameter_value: a list with a substitution whose other items are
            # strings (or lists of substitutions) is one string: [FindPackageShare('p'), '/a.yaml']
            return PSubst(to_value(v, span), None, span)
        return PList(tuple(to_pvalue(x, span_at(v, i, span)) for i, x in enumerate(v)), span)
    if isinstance(v, LObj) and v.qual.endswith(".ParameterValue"):
        inner = v.arg(0, "value")
        vt = v.arg(1, "value_type")
        vt_name = vt.qual.rsplit(".", 1)[-1] if hasattr(vt, "qual") else (None if vt is None else str(vt))
        if vt_name is None and isinstance(inner, _SCALARS):
            return to_pvalue(inner, span)
        return PSubst(to_value(inner, v.arg_span(0, "value")), vt_name, v.span, wrapped=vt_name is None)
    if isinstance(v, Opaque):
        return PUnknown(v.reason, v.span or span)
    if isinstance(v, SymStr):
        # A Python str at description time (``.perform(context)``, a share path, an f-string):
        # normalize_parameter_dict yaml.dump-s every str, so it stays a string whatever it reads.
        return PSubst(to_value(v, span), "str", span)
    if isinstance(v, KPath) or (isinstance(v, LObj) and api.is_substitution(v.qual)):
        return PSubst(to_value(v, span), None, span)
    return PUnknown(f"parameter value of type {type_name(v)}", span)


def _is_substitution(x: Any) -> bool:
    return isinstance(x, LObj) and api.is_substitution(x.qual)


def _one_string(v: list[Any] | tuple[Any, ...]) -> bool:
    """Whether a parameter's list value is one string to launch_ros: at least one substitution,
    every other item a str (one at description time too) or a list of substitutions and strs."""
    def text(x: Any) -> bool:
        return isinstance(x, (str, SymStr)) or _is_substitution(x)

    return any(_is_substitution(x) for x in v) and all(
        text(x) or isinstance(x, (list, tuple)) and all(text(y) for y in x) for x in v)


def _flatten(d: dict[Any, Any], prefix: str, span: Span, out: list[ParamEntry]) -> bool:
    spans = item_spans(d) if isinstance(item_spans(d), dict) else {}
    for k, v in d.items():
        if not isinstance(k, str):
            return False
        kspan, vspan = spans.get(k, (span, span))
        name = f"{prefix}.{k}" if prefix else str(k)
        if isinstance(v, dict):
            if not _flatten(v, name, vspan, out):
                return False
        else:
            out.append(ParamEntry(name, to_pvalue(v, vspan), kspan))
    return True


def param_dict(d: dict[Any, Any], span: Span) -> ParamSource:
    entries: list[ParamEntry] = []
    if not _flatten(d, "", span, entries):
        return ParamsUnknown("parameter dict with a key that cannot be evaluated statically", span)
    return ParamDict(tuple(entries), span)


def to_params(v: Any, span: Span) -> tuple[ParamSource, ...]:
    if v is None:
        return ()
    if isinstance(v, dict):
        return (param_dict(v, span),)
    if not isinstance(v, (list, tuple)):
        reason = v.reason if isinstance(v, Opaque) else f"parameters given as {type_name(v)}"
        return (ParamsUnknown(reason, span),)
    out: list[ParamSource] = []
    for i, item in enumerate(v):
        ispan = span_at(v, i, span)
        if isinstance(item, dict):
            out.append(param_dict(item, ispan))
        elif isinstance(item, LObj) and item.qual.endswith(".ParameterFile"):
            allow = item.arg(1, "allow_substs", False)
            out.append(ParamFile(to_value(item.arg(0, "param_file"), item.arg_span(0, "param_file")), ispan, allow is True))
        elif isinstance(item, (str, SymStr, KPath)) or (isinstance(item, LObj) and api.is_substitution(item.qual)) or isinstance(item, list) and all(isinstance(x, (str, SymStr)) or (isinstance(x, LObj) and api.is_substitution(x.qual)) for x in item):
            out.append(ParamFile(to_value(item, ispan), ispan))
        else:
            reason = item.reason if isinstance(item, Opaque) else f"parameter item of type {type_name(item)}"
            out.append(ParamsUnknown(reason, ispan))
    return tuple(out)
