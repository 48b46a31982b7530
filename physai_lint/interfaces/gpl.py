"""generate_parameter_library YAML: declarations with types, defaults and validators.

Format: ``<namespace>:`` then parameters; a mapping with a ``type`` key is a parameter, other
mappings nest (dotted names). ``__map_<param>`` keys repeat their subtree once per element of the
string-array parameter ``<param>``: those subtrees become *patterns* (any name below the prefix is
declared at run time). Validators: ``bounds<>``, ``gt<>``, ``gt_eq<>``, ``lt<>``, ``lt_eq<>``,
``one_of<>``, ``fixed_size<>``, ``size_gt<>``, ``size_lt<>``, ``not_empty<>``, ``unique<>``,
``subset_of<>``, ``element_bounds<>``, ``lower_element_bounds<>``, ``upper_element_bounds<>``
(custom ``ns::fn`` validators are kept but not evaluated).
"""
from __future__ import annotations

import dataclasses
import math
from collections.abc import Callable
from typing import Any

import yaml

from physai_lint.model.findings import Diagnostic
from physai_lint.model.span import Span

from .model import PARAM_TYPES, ParamDecl

_Loader = getattr(yaml, "CSafeLoader", yaml.SafeLoader)
MAX_NODES = 200_000

_GPL_TYPE_ALIASES = {
    "int": "integer", "integer": "integer", "double": "double", "float": "double",
    "bool": "bool", "string": "string", "int_array": "integer_array",
    "integer_array": "integer_array", "double_array": "double_array", "bool_array": "bool_array",
    "string_array": "string_array", "byte_array": "byte_array",
    "string_fixed_10": "string", "double_array_fixed_10": "double_array",
}


def normalize_type(t: Any) -> str | None:
    if not isinstance(t, str):
        return None
    t = t.strip()
    if t in _GPL_TYPE_ALIASES:
        return _GPL_TYPE_ALIASES[t]
    # generate_parameter_library fixed-size types: string_fixed_N, double_array_fixed_N ...
    if "_fixed_" in t:
        base = t.split("_fixed_")[0]
        return _GPL_TYPE_ALIASES.get(base)
    return t if t in PARAM_TYPES else None


def _span(path: str, node: yaml.Node) -> Span:
    sm, em = node.start_mark, node.end_mark
    line, col = sm.line + 1, sm.column + 1
    eline, ecol = em.line + 1, em.column + 1
    if (eline, ecol) <= (line, col):
        eline, ecol = line, col + 1
    return Span(path, line, col, eline, ecol)


class _Budget:
    def __init__(self) -> None:
        self.left = MAX_NODES

    def spend(self) -> None:
        self.left -= 1
        if self.left < 0:
            raise ValueError("document too large")


def to_python(node: yaml.Node, budget: _Budget | None = None) -> Any:
    """Construct a small value from a composed node, bounded (aliases are not expanded twice)."""
    from physai_lint.params.typing import safe_constructor

    budget = budget or _Budget()
    budget.spend()
    if isinstance(node, yaml.ScalarNode):
        try:
            return safe_constructor().construct_object(node, deep=True)
        except Exception:  # noqa: BLE001
            return node.value
    if isinstance(node, yaml.SequenceNode):
        return [to_python(n, budget) for n in node.value]
    if isinstance(node, yaml.MappingNode):
        out = {}
        for k, v in node.value:
            key = to_python(k, budget)
            try:
                out[key] = to_python(v, budget)
            except TypeError:
                pass
        return out
    return None


def compose(path: str, text: str) -> tuple[yaml.Node | None, list[Diagnostic]]:
    try:
        for ev in yaml.parse(text, Loader=_Loader):
            if isinstance(ev, yaml.AliasEvent):
                line = ev.start_mark.line + 1
                return None, [Diagnostic("P104", Span.point(path, line, ev.start_mark.column + 1),
                                         "YAML aliases are not supported in declaration files")]
        return yaml.compose(text, Loader=_Loader), []
    except yaml.MarkedYAMLError as exc:
        mark = exc.problem_mark or exc.context_mark
        line = mark.line + 1 if mark else 1
        col = mark.column + 1 if mark else 1
        msg = " ".join(str(x) for x in (exc.context, exc.problem) if x)
        return None, [Diagnostic("X001", Span.point(path, line, col),
                                 f"YAML syntax error at line {line}, column {col}: {msg}")]
    except (yaml.YAMLError, RecursionError, ValueError) as exc:
        return None, [Diagnostic("X001", Span.whole_file(path), f"YAML error: {exc}")]


def _validators(node: yaml.Node, budget: _Budget) -> list[tuple[str, list[Any]]]:
    out: list[tuple[str, list[Any]]] = []
    if not isinstance(node, yaml.MappingNode):
        return out
    for k, v in node.value:
        if not isinstance(k, yaml.ScalarNode):
            continue
        name = k.value.strip()
        if name.endswith("<>"):
            name = name[:-2]
        args = to_python(v, budget)
        if args is None:
            args = []
        if not isinstance(args, list):
            args = [args]
        out.append((name, args))
    return out


def _decl_from(name: str, node: yaml.MappingNode, path: str, budget: _Budget,
               key: yaml.Node | None = None) -> ParamDecl:
    fields = {k.value: v for k, v in node.value if isinstance(k, yaml.ScalarNode)}
    t = normalize_type(to_python(fields["type"], budget)) if "type" in fields else None
    decl = ParamDecl(name=name, type=t, span=_span(path, key if key is not None else node),
                     source=path)
    if "default_value" in fields:
        decl.default = to_python(fields["default_value"], budget)
        decl.has_default = True
    if "read_only" in fields:
        decl.read_only = bool(to_python(fields["read_only"], budget))
    if "description" in fields:
        d = to_python(fields["description"], budget)
        decl.description = str(d) if d is not None else None
    if "validation" in fields:
        decl.validators = _validators(fields["validation"], budget)
        for vname, args in decl.validators:
            if vname == "one_of" and args and isinstance(args[0], list):
                decl.choices = list(args[0])
            elif vname == "bounds" and len(args) >= 2:
                decl.min, decl.max = _num(args[0]), _num(args[1])
            elif vname in ("gt_eq",) and args:
                decl.min = _num(args[0])
            elif vname in ("lt_eq",) and args:
                decl.max = _num(args[0])
    return decl


def _num(v: Any) -> float | None:
    if isinstance(v, bool):
        return None
    if isinstance(v, (int, float)):
        return v
    return None


def parse_gpl(path: str, text: str) -> tuple[dict[str, ParamDecl], list[str], list[Diagnostic]]:
    """Parse a generate_parameter_library YAML: (declarations by dotted name, ``__map_`` pattern
    prefixes, diagnostics). Never raises."""
    root, diags = compose(path, text)
    decls: dict[str, ParamDecl] = {}
    patterns: list[str] = []
    if root is None:
        return decls, patterns, diags
    if not isinstance(root, yaml.MappingNode):
        diags.append(Diagnostic("P104", _span(path, root),
                                "a generate_parameter_library file is a mapping "
                                "`<namespace>: {<parameter>: {type: ...}}`"))
        return decls, patterns, diags
    budget = _Budget()
    try:
        for _ns_key, ns_node in root.value:
            if isinstance(ns_node, yaml.MappingNode):
                _walk(ns_node, "", path, decls, patterns, budget, 0)
    except (ValueError, RecursionError) as exc:
        diags.append(Diagnostic("X001", Span.whole_file(path), f"cannot read declarations: {exc}"))
    return decls, patterns, diags


def _walk(node: yaml.MappingNode, prefix: str, path: str, decls: dict[str, ParamDecl],
          patterns: list[str], budget: _Budget, depth: int) -> None:
    if depth > 64:
        return
    for k, v in node.value:
        budget.spend()
        if not isinstance(k, yaml.ScalarNode) or not isinstance(v, yaml.MappingNode):
            continue
        key = k.value
        if key.startswith(MAP_MARK):
            if prefix not in patterns:
                patterns.append(prefix)
            # the subtree is declared once per element of the string array it names: kept as
            # templates ("gains.__map_joints.p") that mapped_declaration expands
            _walk(v, f"{prefix}{key}.", path, decls, patterns, budget, depth + 1)
            continue
        name = f"{prefix}{key}"
        keys = {kk.value for kk, _ in v.value if isinstance(kk, yaml.ScalarNode)}
        if "type" in keys:
            decls[name] = _decl_from(name, v, path, budget, k)
        else:
            _walk(v, name + ".", path, decls, patterns, budget, depth + 1)


MAP_MARK = "__map_"


def is_template(name: str) -> bool:
    """A declaration of a ``__map_`` subtree, not a parameter name."""
    return MAP_MARK in name


def mapped_declaration(decls: dict[str, ParamDecl], name: str,
                       keys_of: Callable[[str], list[Any] | None]) -> ParamDecl | None:
    """The ``__map_`` declaration ``name`` is an instance of: generate_parameter_library's
    ParamListener declares ``gains.<j>.p`` for each element ``j`` of the string array ``joints``
    (``gains.__map_joints.p``), with the template's type and validation. ``keys_of(param)`` is
    that array's value for the node (None when unknown: then nothing is matched)."""
    parts = name.split(".")
    for template, decl in decls.items():
        if MAP_MARK not in template:
            continue
        tparts = template.split(".")
        if len(tparts) != len(parts):
            continue
        for t, part in zip(tparts, parts):
            if t.startswith(MAP_MARK):
                keys = keys_of(t[len(MAP_MARK):])
                if keys is None or part not in keys:
                    break
            elif t != part:
                break
        else:
            return dataclasses.replace(decl, name=name)
    return None


# ---- checking values against declarations -------------------------------------------------------

_SCALAR_CHECK = {
    "bool": lambda v: isinstance(v, bool),
    "integer": lambda v: isinstance(v, int) and not isinstance(v, bool),
    "double": lambda v: isinstance(v, float),
    "string": lambda v: isinstance(v, str),
}


def value_kind(value: Any) -> str | None:
    """The ROS parameter type of a Python value (``None`` for an empty list or unknown)."""
    if isinstance(value, bool):
        return "bool"
    if isinstance(value, int):
        return "integer"
    if isinstance(value, float):
        return "double"
    if isinstance(value, str):
        return "string"
    if isinstance(value, (bytes, bytearray)):
        return "byte_array"
    if isinstance(value, (list, tuple)):
        if not value:
            return None
        kinds = {value_kind(v) for v in value}
        if len(kinds) == 1:
            k = next(iter(kinds))
            if k in ("bool", "integer", "double", "string"):
                return f"{k}_array"
    return None


def type_compatible(decl_type: str | None, value: Any) -> bool | None:
    """rclcpp accepts a value for a declared type only when the types are identical (an integer
    for a double parameter raises InvalidParameterTypeException, and vice versa). ``None`` when
    it cannot be told (unknown type, unknown or empty value)."""
    if decl_type is None or value is None:
        return None
    kind = value_kind(value)
    if kind is None:
        return None
    if decl_type == "byte_array" and kind == "integer_array":
        return None
    return kind == decl_type


def _fmt(v: Any) -> str:
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, str):
        return f"\"{v}\""
    return repr(v)


def _cmp_ok(v: Any, op: str, bound: Any) -> bool:
    if not isinstance(v, (int, float)) or isinstance(v, bool) or not isinstance(bound, (int, float)):
        return True
    if isinstance(v, float) and math.isnan(v):
        return False
    return {"gt": v > bound, "gt_eq": v >= bound, "lt": v < bound, "lt_eq": v <= bound}[op]


def validate(decl: ParamDecl, value: Any) -> list[str]:
    """Human messages for every validator/range/choice the value fails (empty when it passes or
    when the value is unknown)."""
    if value is None:
        return []
    out: list[str] = []
    is_seq = isinstance(value, (list, tuple, str))
    elems = list(value) if isinstance(value, (list, tuple)) else None
    for name, args in decl.validators:
        a0 = args[0] if args else None
        if name == "bounds" and len(args) >= 2:
            if not (_cmp_ok(value, "gt_eq", args[0]) and _cmp_ok(value, "lt_eq", args[1])):
                out.append(f"{_fmt(value)} is outside the bounds [{args[0]}, {args[1]}]")
        elif name in ("gt", "gt_eq", "lt", "lt_eq") and args:
            if not _cmp_ok(value, name, a0):
                sym = {"gt": ">", "gt_eq": ">=", "lt": "<", "lt_eq": "<="}[name]
                out.append(f"{_fmt(value)} must be {sym} {a0}")
        elif name == "one_of" and isinstance(a0, list):
            if value not in a0:
                out.append(f"{_fmt(value)} is not one of {a0}")
        elif name == "fixed_size" and is_seq and isinstance(a0, int):
            if len(value) != a0:
                out.append(f"length {len(value)} must be exactly {a0}")
        elif name == "size_gt" and is_seq and isinstance(a0, int):
            if not len(value) > a0:
                out.append(f"length {len(value)} must be greater than {a0}")
        elif name == "size_lt" and is_seq and isinstance(a0, int):
            if not len(value) < a0:
                out.append(f"length {len(value)} must be less than {a0}")
        elif name == "not_empty" and is_seq:
            if len(value) == 0:
                out.append("must not be empty")
        elif name == "unique" and elems is not None:
            seen: list[Any] = []
            for e in elems:
                if e in seen:
                    out.append(f"contains {_fmt(e)} more than once")
                    break
                seen.append(e)
        elif name == "subset_of" and elems is not None and isinstance(a0, list):
            bad = [e for e in elems if e not in a0]
            if bad:
                out.append(f"{', '.join(_fmt(b) for b in bad)} not in {a0}")
        elif name == "element_bounds" and elems is not None and len(args) >= 2:
            bad = [e for e in elems
                   if not (_cmp_ok(e, "gt_eq", args[0]) and _cmp_ok(e, "lt_eq", args[1]))]
            if bad:
                out.append(f"element {_fmt(bad[0])} is outside the bounds [{args[0]}, {args[1]}]")
        elif name == "lower_element_bounds" and elems is not None and args:
            bad = [e for e in elems if not _cmp_ok(e, "gt_eq", a0)]
            if bad:
                out.append(f"element {_fmt(bad[0])} must be >= {a0}")
        elif name == "upper_element_bounds" and elems is not None and args:
            bad = [e for e in elems if not _cmp_ok(e, "lt_eq", a0)]
            if bad:
                out.append(f"element {_fmt(bad[0])} must be <= {a0}")
    if not decl.validators:
        if decl.min is not None and not _cmp_ok(value, "gt_eq", decl.min):
            out.append(f"{_fmt(value)} is below the minimum {decl.min}")
        if decl.max is not None and not _cmp_ok(value, "lt_eq", decl.max):
            out.append(f"{_fmt(value)} is above the maximum {decl.max}")
        if decl.choices is not None and value not in decl.choices:
            out.append(f"{_fmt(value)} is not one of {decl.choices}")
    return out
