"""Launch-side parameter typing (SEMANTICS §4a, launch_ros ``normalize_parameters`` and
``evaluate_parameter_dict``): Python literals keep their type (a ``str`` is ``yaml.dump``-ed and
re-loaded, so it stays a string), substitution values are evaluated and typed by PyYAML."""
from __future__ import annotations

import functools
from collections.abc import Callable
from typing import Any

from physai_lint.model import values as v
from physai_lint.resolve.model import ParamValue, ResolvedParam

MAX_YAML_TEXT = 100_000


_TYPED_TEXT = 200  # yaml_type memoises texts up to this long (_short_yaml_type)


def yaml_type(text: str) -> ParamValue:
    """What ``yaml.safe_load`` makes of an evaluated substitution string; None when launch rejects it."""
    if text == "":
        return ""
    if len(text) > _TYPED_TEXT:
        return _yaml_type(text)
    value = _short_yaml_type(text)
    return list(value) if isinstance(value, list) else value  # callers own their lists


@functools.lru_cache(maxsize=4096)
def _short_yaml_type(text: str) -> ParamValue:
    """``_yaml_type`` by text: a workspace gives hundreds of nodes the same few values ("true",
    "false", "0.5"), and a libyaml loader costs more to build than such a value to read."""
    return _yaml_type(text)


def _yaml_type(text: str) -> ParamValue:
    if len(text) > MAX_YAML_TEXT:
        return text if "\n" not in text else None
    if "*" in text:
        from physai_lint.params.typing import has_alias

        if has_alias(text):  # "['.*']" is a list; an alias (perhaps a bomb) is not worked out
            return None
    import yaml

    loader = getattr(yaml, "CSafeLoader", yaml.SafeLoader)
    try:
        value = yaml.load(text, Loader=loader)
    except yaml.YAMLError:
        return None
    return _plain(value)


def _plain(value: Any) -> ParamValue:
    if isinstance(value, (bool, int, float, str)):
        return value
    if isinstance(value, (list, tuple)) and value:
        first = type(value[0])
        if first in (bool, int, float, str) and all(type(x) is first for x in value):
            return list(value)
    return None


def _normalize_list(items: tuple[Any, ...]) -> ParamValue:
    kinds = {type(x) for x in items}
    if not items:
        return None
    if kinds == {int}:
        return [int(x) for x in items]
    if kinds <= {int, float}:
        return [float(x) for x in items]
    if kinds == {bool}:
        return [bool(x) for x in items]
    if kinds == {str}:
        return [str(x) for x in items]
    return [str(x) for x in items]  # mixed: yaml.dump-ed into strings


def resolve_pvalue(
    name: str, pv: v.PValue, evaluate: Callable[[v.Value], str | None], span: Any
) -> ResolvedParam:
    if isinstance(pv, v.PLit):
        value = pv.value
        if isinstance(value, tuple):
            return ResolvedParam(name, _normalize_list(value), span, None, "python",
                                 pv.item_spans)
        if isinstance(value, bytes):
            return ResolvedParam(name, None, span, None, "python")
        return ResolvedParam(name, value, span, None, "python")
    if isinstance(pv, v.PSubst):
        text = evaluate(pv.value)
        if text is None:
            return ResolvedParam(name, None, span, None, "yaml", wrapped=pv.wrapped)
        scalar = (pv.value_type or "")[len("list_of_"):] if (pv.value_type or "").startswith("list_of_") \
            else pv.value_type
        if pv.sep is not None:
            parts = text.split(pv.sep)
            if scalar == "str":
                return ResolvedParam(name, parts, span, text, "forced")
            if scalar in _COERCE:
                coerced = [_coerce(x, scalar) for x in parts]
                if any(x is None for x in coerced):
                    return ResolvedParam(name, None, span, text, "forced")  # launch raises ValueError
                return ResolvedParam(name, coerced, span, text, "forced")
            typed = [yaml_type(x) for x in parts]
            return ResolvedParam(name, _plain(typed), span, text, "yaml")
        if pv.value_type == "str":
            return ResolvedParam(name, text, span, text, "forced")
        if pv.value_type in _COERCE:
            return ResolvedParam(name, _coerce(text, pv.value_type), span, text, "forced")
        return ResolvedParam(name, yaml_type(text), span, text, "yaml", wrapped=pv.wrapped)
    if isinstance(pv, v.PList):
        items = [resolve_pvalue(name, item, evaluate, span).value for item in pv.items]
        if any(x is None or isinstance(x, list) for x in items):
            return ResolvedParam(name, None, span, None, "python")
        return ResolvedParam(name, _normalize_list(tuple(items)), span, None, "python")
    return ResolvedParam(name, None, span, None, "python")


# ``ParameterValue(..., value_type=float)`` / XML ``type="float"``: launch's ``coerce_to_type``
# converts the performed text with ``float()`` / ``int()``, a bool by YAML rules (launch
# utilities/type_utils.py); text that does not convert raises ValueError (the value is unknown here).
_COERCE = ("float", "int", "bool")


def _coerce(text: str, kind: str) -> Any:
    if kind == "bool":
        value = yaml_type(text)
        return value if isinstance(value, bool) else None
    try:
        return float(text) if kind == "float" else int(text)
    except ValueError:
        return None


def rcl_cli_text(value: ParamValue) -> str | None:
    """``-p name:=str(value)`` as ``SetParameter`` writes it (a list becomes its Python repr)."""
    if value is None:
        return None
    if isinstance(value, list):
        return repr(tuple(value))
    return str(value)
