"""Scalar typing of parameter values, as the two ROS 2 parsers do it.

* :func:`rcl_type_scalar` mirrors ``get_value()`` of ``rcl_yaml_param_parser/src/parse.c`` (the
  params-file parser every node uses): bool word list, then C ``strtoll(s, 0)`` consuming the whole
  string, then the ``.nan``/``.inf`` spellings or C ``strtod`` (glibc) consuming the whole string,
  else a string. ``!!str`` forces a string since Iron (rcl PR #999); Humble ignores tags.
* :func:`pyyaml_type` is what ``yaml.safe_load`` (YAML 1.1) makes of a launch ``<param value>``
  or an evaluated substitution string.
"""
from __future__ import annotations

import functools
import math
from typing import Any, Literal

import yaml

Kind = Literal["bool", "integer", "double", "string"]

YAML_STR_TAG = "tag:yaml.org,2002:str"
TAG_AWARE_DISTROS_EXCLUDED = frozenset({"humble", "foxy", "galactic", "eloquent", "dashing"})

_TRUE = frozenset({"Y", "y", "yes", "Yes", "YES", "true", "True", "TRUE", "on", "On", "ON"})
_FALSE = frozenset({"N", "n", "no", "No", "NO", "false", "False", "FALSE", "off", "Off", "OFF"})
_SPECIAL_FLOATS = frozenset({
    ".nan", ".NaN", ".NAN", ".inf", ".Inf", ".INF", "+.inf", "+.Inf", "+.INF",
    "-.inf", "-.Inf", "-.INF",
})
_C_SPACE = " \t\n\v\f\r"
_HEX = "0123456789abcdefABCDEF"
_DEC = "0123456789"
_INT64_MIN = -(2 ** 63)
_INT64_MAX = 2 ** 63 - 1
_DBL_MIN = 2.2250738585072014e-308


def _skip_space(s: str, i: int) -> int:
    while i < len(s) and s[i] in _C_SPACE:
        i += 1
    return i


def c_strtoll(s: str) -> tuple[int, int, bool]:
    """C ``strtoll(s, &end, 0)``: (value, characters consumed, ERANGE)."""
    i = _skip_space(s, 0)
    neg = False
    if i < len(s) and s[i] in "+-":
        neg = s[i] == "-"
        i += 1
    start = i
    if s[i:i + 2] in ("0x", "0X") and i + 2 < len(s) and s[i + 2] in _HEX:
        j = i + 2
        while j < len(s) and s[j] in _HEX:
            j += 1
        mag = int(s[i + 2:j], 16)
    elif s[i:i + 1] == "0":
        j = i + 1
        while j < len(s) and s[j] in "01234567":
            j += 1
        mag = int(s[i:j], 8)
    else:
        j = i
        while j < len(s) and s[j] in _DEC:
            j += 1
        if j == start:
            return 0, 0, False  # no conversion: endptr = s
        mag = int(s[i:j])
    val = -mag if neg else mag
    if val < _INT64_MIN or val > _INT64_MAX:
        return (_INT64_MIN if neg else _INT64_MAX), j, True
    return val, j, False


def c_strtod(s: str) -> tuple[float, int, bool]:
    """glibc ``strtod(s, &end)`` in the C locale: (value, characters consumed, ERANGE)."""
    i = _skip_space(s, 0)
    sign = 1.0
    if i < len(s) and s[i] in "+-":
        sign = -1.0 if s[i] == "-" else 1.0
        i += 1
    low = s[i:].lower()
    if low.startswith("inf"):
        n = 8 if low.startswith("infinity") else 3
        return sign * math.inf, i + n, False
    if low.startswith("nan"):
        j = i + 3
        if j < len(s) and s[j] == "(":
            k = j + 1
            while k < len(s) and (s[k].isascii() and (s[k].isalnum() or s[k] == "_")):
                k += 1
            if k < len(s) and s[k] == ")":
                j = k + 1
        return math.nan, j, False
    # hexadecimal float
    if low.startswith("0x"):
        j = i + 2
        mant_start = j
        digits = 0
        while j < len(s) and s[j] in _HEX:
            j += 1
            digits += 1
        if j < len(s) and s[j] == ".":
            k = j + 1
            while k < len(s) and s[k] in _HEX:
                k += 1
                digits += 1
            if digits:
                j = k
        if digits:
            mant = s[mant_start:j]
            exp_txt = "p0"
            if j < len(s) and s[j] in "pP":
                k = j + 1
                if k < len(s) and s[k] in "+-":
                    k += 1
                e0 = k
                while k < len(s) and s[k] in _DEC:
                    k += 1
                if k > e0:
                    exp_txt = s[j:k]
                    j = k
            try:
                val = float.fromhex("0x" + mant + exp_txt)
            except OverflowError:
                return sign * math.inf, j, True
            erange = val == 0.0 and any(c not in "0." for c in mant)
            erange = erange or (val != 0.0 and abs(val) < _DBL_MIN)
            return sign * val, j, erange
        # "0x" without hex digits: only the "0" is consumed
        return 0.0 * sign, i + 1, False
    # decimal
    j = i
    digits = 0
    while j < len(s) and s[j] in _DEC:
        j += 1
        digits += 1
    if j < len(s) and s[j] == ".":
        k = j + 1
        while k < len(s) and s[k] in _DEC:
            k += 1
            digits += 1
        if digits:
            j = k
    if not digits:
        return 0.0, 0, False
    mant_end = j
    if j < len(s) and s[j] in "eE":
        k = j + 1
        if k < len(s) and s[k] in "+-":
            k += 1
        e0 = k
        while k < len(s) and s[k] in _DEC:
            k += 1
        if k > e0:
            j = k
    text = s[i:j]
    if len(text) > 4096:  # absurdly long numbers: let Python cope via Decimal-free path
        text = text[:4096]
    try:
        val = float(text)
    except (ValueError, OverflowError):
        return 0.0, 0, False
    if math.isinf(val):
        return sign * val, j, True
    nonzero_mant = any(c not in "0." for c in s[i:mant_end])
    erange = (val == 0.0 and nonzero_mant) or (val != 0.0 and abs(val) < _DBL_MIN)
    return sign * val, j, erange


def tags_honoured(distro: str) -> bool:
    """``!!str`` forces a string only since Iron (rcl PR #999)."""
    return (distro or "humble").lower() not in TAG_AWARE_DISTROS_EXCLUDED


def rcl_type_scalar(text: str, quoted: bool = False, tag: str | None = None,
                    distro: str = "humble") -> tuple[Kind, Any]:
    """Type one YAML scalar exactly like rcl ``get_value``.

    ``quoted``: single- or double-quoted style. ``tag``: the resolved tag as libyaml reports it
    (``tag:yaml.org,2002:str`` for ``!!str``), ``None`` when untagged.
    """
    if tag is not None and tags_honoured(distro) and tag in (YAML_STR_TAG, "!!str"):
        return "string", text
    if quoted:
        return "string", text
    return _rcl_type_plain(text)


@functools.lru_cache(maxsize=1 << 16)
def _rcl_type_plain(text: str) -> tuple[Kind, Any]:
    # Memoised: parameter files repeat the same few spellings (true, 0.0, 1, frame names) and the
    # strtoll/strtod mirrors are pure Python; every result is an immutable scalar.
    if text in _TRUE:
        return "bool", True
    if text in _FALSE:
        return "bool", False
    if text:
        ival, n, erange = c_strtoll(text)
        if n > 0 and n == len(text) and not erange:
            return "integer", ival
        if text in _SPECIAL_FLOATS:
            low = text.lower()
            if "nan" in low:
                return "double", math.nan
            return "double", (-math.inf if text.startswith("-") else math.inf)
        dval, n, erange = c_strtod(text)
        if n > 0 and n == len(text) and not erange:
            return "double", dval
    return "string", text


# ---- PyYAML typing (launch frontends, composable nodes) -----------------------------------------

_Loader = getattr(yaml, "CSafeLoader", yaml.SafeLoader)
MAX_PYYAML_TEXT = 65536


def has_alias(text: str) -> bool:
    try:
        for ev in yaml.parse(text, Loader=_Loader):
            if isinstance(ev, yaml.AliasEvent):
                return True
    except yaml.YAMLError:
        return False
    return False


def yaml_syntax_error(text: str) -> str | None:
    """Why ``yaml.safe_load`` cannot read ``text`` (the scanner's or parser's complaint, or "an
    alias", which is not worked out), or None when it can."""
    if len(text) > MAX_PYYAML_TEXT:
        return None
    if "*" in text and has_alias(text):
        return "an alias"
    try:
        yaml.load(text, Loader=_Loader)
    except yaml.YAMLError as exc:
        return str(getattr(exc, "problem", None) or "a syntax error")
    except (ValueError, TypeError, RecursionError, OverflowError):
        return "a syntax error"
    return None


def pyyaml_type(text: str) -> Any:
    """What ``yaml.safe_load(text)`` gives (launch ``coerce_to_type``): bool/int/float/str/None/
    date/list/dict. Syntax errors, aliases and over-long texts keep the string. ``""`` -> ``""``."""
    if not isinstance(text, str):
        return text
    if text == "":
        return ""
    if len(text) > MAX_PYYAML_TEXT or (("*" in text) and has_alias(text)):
        return text
    try:
        return yaml.load(text, Loader=_Loader)
    except (yaml.YAMLError, ValueError, TypeError, RecursionError, OverflowError):
        return text


def pyyaml_kind(value: Any) -> str:
    """Kind name of a PyYAML value: bool, integer, double, string, null, date, list, dict, other."""
    import datetime

    if isinstance(value, bool):
        return "bool"
    if isinstance(value, int):
        return "integer"
    if isinstance(value, float):
        return "double"
    if isinstance(value, str):
        return "string"
    if value is None:
        return "null"
    if isinstance(value, (datetime.date, datetime.datetime)):
        return "date"
    if isinstance(value, list):
        return "list"
    if isinstance(value, dict):
        return "dict"
    return "other"


def pyyaml_scalar(text: str, quoted: bool, tag: str | None) -> Any:
    """PyYAML's typing of one scalar *node* (style and tag known): quoted -> str; explicit tag
    honoured; plain -> the implicit resolver."""
    if quoted or tag == YAML_STR_TAG:
        return text
    if tag is not None and tag not in ("!", "?"):
        node = yaml.ScalarNode(tag, text)
        try:
            return safe_constructor().construct_object(node, deep=True)
        except Exception:  # noqa: BLE001 -- bad tagged scalar: PyYAML would raise; keep text
            return text
    if len(text) > MAX_PYYAML_TEXT:
        return text
    return _pyyaml_plain(text)


_RESOLVER = yaml.resolver.Resolver()  # resolve() reads only class-level tables


def safe_constructor() -> Any:
    """SafeLoader's constructor alone, for one scalar node: ``yaml.SafeLoader("")`` would also make
    a reader, scanner and parser, and leave a reference cycle (its parser state is a bound method)
    for the cyclic collector."""
    constructor = yaml.SafeLoader.__new__(yaml.SafeLoader)
    yaml.constructor.SafeConstructor.__init__(constructor)
    return constructor


@functools.lru_cache(maxsize=1 << 16)
def _pyyaml_plain(text: str) -> Any:
    # Memoised like _rcl_type_plain: the implicit resolver's values (bool, int, float, None,
    # date/datetime, str) are immutable. Only a constructor is needed, not a whole SafeLoader
    # (reader, scanner, parser, composer) per scalar; it is still SafeLoader's constructor table.
    resolved = _RESOLVER.resolve(yaml.ScalarNode, text, (True, False))
    if resolved == YAML_STR_TAG:
        return text
    try:
        return safe_constructor().construct_object(yaml.ScalarNode(resolved, text), deep=True)
    except Exception:  # noqa: BLE001
        return text


def launch_dump_retype(value: str, distro: str = "humble") -> tuple[Kind, Any]:
    """A ``str`` value in a launch parameter dict is written with ``yaml.dump`` into a temporary
    params file and re-read by rcl: plain-dumped strings are re-typed by rcl (``"1e3"`` -> double
    1000.0), quoted ones stay strings."""
    if len(value) > MAX_PYYAML_TEXT:
        return "string", value
    try:
        dumped = yaml.dump(value, Dumper=getattr(yaml, "CSafeDumper", yaml.SafeDumper))
    except yaml.YAMLError:
        return "string", value
    if dumped[:1] in ("'", '"', "|", ">", "!"):
        return "string", value
    return rcl_type_scalar(value, False, None, distro)
