"""The fast paths of nav2_common's RewrittenYaml against the slow ones they replace: the dumper
writes the text ``yaml.dump(data, Dumper=CDumper)`` writes, the memoised resolver and key
construction map the same positions, and the spelled-out span mapping of a virtual file's params
model builds the model the generic ``_remap`` builds."""
from __future__ import annotations

import datetime
import io
import math
from collections import OrderedDict
from typing import Any

import yaml
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from physai_lint.model.span import Span
from physai_lint.params.loader import load_param_file
from physai_lint.resolve import nav2_common as nc

CDUMPER = getattr(yaml, "CDumper", yaml.Dumper)
CLOADER = getattr(yaml, "CSafeLoader", yaml.SafeLoader)

# Texts that YAML 1.1 resolves to other types, or that the emitter must quote or escape.
TRICKY = ["", " ", "y", "Yes", "off", "~", "null", "NULL", "1_000", "0x1F", "0o17", "017", "1e3",
          "1.5e+3", ".inf", "-.Inf", ".nan", "2001-12-14", "2001-12-14 21:59:43.10 -5", "=", "<<",
          ":", "a: b", "- a", "#c", "a #c", "'", '"', "*x", "&y", "!t", "%", "@", "`", "{a}", "[1]",
          "a\nb", "tab\tx", "trailing ", "\x85", "\u2028", "é", "日本", "\U0001f600", "x" * 130,
          "UNKNOWN_" + nc.UNKNOWN_PREFIX + "1", nc.UNKNOWN_PREFIX + "2"]

scalars = st.one_of(
    st.none(), st.booleans(), st.integers(), st.integers(min_value=-(10 ** 30), max_value=10 ** 30),
    st.floats(allow_nan=True, allow_infinity=True), st.sampled_from(TRICKY), st.text(max_size=12),
)
keys = st.one_of(st.sampled_from(TRICKY), st.text(max_size=8), st.integers(-5, 5), st.booleans(),
                 st.none(), st.floats(allow_nan=False, allow_infinity=True))
data = st.recursive(scalars, lambda inner: st.one_of(
    st.lists(inner, max_size=4), st.dictionaries(keys, inner, max_size=5)), max_leaves=30)


def _with_shared(value: Any) -> Any:
    """``value`` and containers of it that hold one object twice (the dump writes anchors)."""
    return {"a": value, "b": value, "c": [value, {"d": value}]}


# ---- the dumper ----------------------------------------------------------------------------------


def _same_dump(value: Any) -> None:
    try:
        expected = yaml.dump(value, Dumper=CDUMPER)
    except Exception as exc:  # the fast dumper must fail the same way
        try:
            yaml.dump(value, Dumper=nc._Dumper)
        except Exception as got:  # noqa: BLE001
            assert type(got) is type(exc)
            return
        raise AssertionError(f"CDumper raised {exc!r}, the fast dumper did not") from exc
    assert yaml.dump(value, Dumper=nc._Dumper) == expected


@settings(max_examples=400, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(data)
def test_fast_dumper_writes_what_cdumper_writes(value: Any) -> None:
    _same_dump(value)
    _same_dump(_with_shared(value))
    _same_dump({"root": {"ros__parameters": value}})


def test_fast_dumper_on_other_types_and_shapes() -> None:
    shared_list = [1, 2.5, "x"]
    shared_map: dict[str, Any] = {"k": shared_list}
    for value in [
        None, "", "y", 1, -0.0, 1e17, 1e-7, 3.0, math.nan, math.inf, -math.inf, 10 ** 40, True,
        [], {}, [[]], [{}], {"a": []}, {"a": {}}, {1: "a", "b": 2},  # mixed keys: not sorted
        {None: 1, True: 2}, {2.5: "x", 1: "y"}, {"s": {1, 2}}, {"t": (1, 2)}, (1, "a"),
        {"d": datetime.date(2024, 1, 2), "t": datetime.datetime(2024, 1, 2, 3, 4, 5)},
        {"b": b"\x00\x01bytes"}, OrderedDict([("z", 1), ("a", [1, 2])]),
        {"m": shared_map, "n": shared_map, "l": shared_list}, [shared_list, shared_list],
        {"x" * 200: 1, "a\nb": [1, {"k": "v"}]}, {"deep": [[[1, [2, {"a": [3]}]]]]},
        {"node": {"ros__parameters": {"rate": 10, "names": ["a", "b"], "on": "on", "v": 1.5}}},
    ]:
        _same_dump(value)


def test_fast_dumper_keeps_the_standard_representers() -> None:
    """The fast path spells out these representers: it is only right while they are the ones in
    use (a representer registered for one of these types would be skipped)."""
    sr = yaml.representer.SafeRepresenter
    table = nc._Dumper.yaml_representers
    assert table[str] is sr.represent_str and table[int] is sr.represent_int
    assert table[float] is sr.represent_float and table[bool] is sr.represent_bool
    assert table[type(None)] is sr.represent_none and table[dict] is sr.represent_dict
    assert table[list] is sr.represent_list
    assert not nc._Dumper.yaml_path_resolvers and not CLOADER.yaml_path_resolvers


# ---- the memoised resolver -----------------------------------------------------------------------


@settings(max_examples=300, deadline=None)
@given(st.one_of(st.sampled_from(TRICKY), st.text(max_size=10)), st.booleans(), st.booleans())
def test_memoised_resolve_is_resolve(text: str, plain: bool, quoted: bool) -> None:
    for memo, base in ((nc._PositionLoader(""), CLOADER), (nc._Dumper(io.StringIO()), CDUMPER)):
        for _ in range(2):  # computed, then memoised
            got = memo.resolve(yaml.ScalarNode, text, (plain, quoted))
            assert got == base.resolve(memo, yaml.ScalarNode, text, (plain, quoted))


# ---- positions -----------------------------------------------------------------------------------


def _map_positions_reference(vf: nc.VirtualFile, dumped: str, data: Any, spans: Any) -> None:
    """``_map_positions`` before the memoised resolver and key construction (the plain loader)."""
    loader = CLOADER(dumped)
    try:
        node = loader.get_single_node()
    except (yaml.YAMLError, ValueError, TypeError, RecursionError):
        loader.dispose()
        return

    def key_of(kn: Any) -> Any:
        try:
            return loader.construct_object(kn, deep=True)
        except (yaml.YAMLError, ValueError, TypeError, RecursionError):
            return None

    def at(n: Any) -> tuple[int, int]:
        return n.start_mark.line + 1, n.start_mark.column + 1

    def walk(n: Any, obj: Any) -> None:
        table = spans.get(id(obj), {})
        if isinstance(n, yaml.MappingNode) and isinstance(obj, dict):
            for kn, vn in n.value:
                key = key_of(kn)
                try:
                    hit = table.get(key)
                    child = obj.get(key)
                except TypeError:
                    continue
                if hit is not None:
                    vf.origin[at(kn)] = hit[0]
                    vf.origin[at(vn)] = hit[1]
                walk(vn, child)
        elif isinstance(n, yaml.SequenceNode) and isinstance(obj, list):
            for i, item in enumerate(n.value):
                hit = table.get(i)
                if hit is not None:
                    vf.origin[at(item)] = hit[1]
                if i < len(obj):
                    walk(item, obj[i])

    if node is not None:
        walk(node, data)
    loader.dispose()


def _same_positions(source: str) -> None:
    loaded = nc._load(source, "/src/params.yaml", lambda n: nc._mark_span("/src/params.yaml", n))
    if loaded is None:
        return
    value, spans = loaded
    try:
        dumped = yaml.dump(value, Dumper=CDUMPER)
    except yaml.YAMLError:
        return
    fallback = Span.whole_file("/src/params.yaml")
    got = nc.VirtualFile("/v.yaml", dumped, {}, fallback, None)
    want = nc.VirtualFile("/v.yaml", dumped, {}, fallback, None)
    nc._map_positions(got, dumped, value, spans)
    _map_positions_reference(want, dumped, value, spans)
    assert got.origin == want.origin


@settings(max_examples=300, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(data, st.booleans())
def test_memoised_positions_are_the_same(value: Any, flow: bool) -> None:
    for v in (value, _with_shared(value)):
        try:
            source = yaml.dump(v, Dumper=CDUMPER, default_flow_style=flow)
        except yaml.YAMLError:
            continue
        _same_positions(source)


def test_memoised_positions_on_written_sources() -> None:
    for source in [
        "a: 1\nb:\n  c: [1, 2]\n  d: {e: f}\n",
        "base: &b {x: 1, y: [1, 2]}\nother: *b\nmore:\n  <<: *b\n  z: 3\n",  # aliases and merge
        ".nan: 1\n.inf: 2\n1.0: 3\n2001-12-14: 4\n2001-13-45: 5\n? [1, 2]\n: 6\n",
        "!!binary aGVsbG8=: 1\n'1': a\n1: b\nnull: c\n~: d\ntrue: e\nyes: f\n",
        "n:\n  ros__parameters:\n    list:\n    - a\n    - {b: c}\n    -\n      - d\n    s: |\n      x\n",
        "- 1\n- [2, 3]\n- {a: b}\n",
        "plain",
    ]:
        _same_positions(source)


# ---- the params model of a virtual file ----------------------------------------------------------


PARAM_TEXTS = [
    "/**:\n  ros__parameters:\n    a: 1\n    b: [1, 2]\n    c: {d: 2.5, e: [x, y]}\n",
    f"n:\n  ros__parameters:\n    u: {nc.UNKNOWN_PREFIX}1\n    l: [a, {nc.UNKNOWN_PREFIX}2]\n    k: 3\n",
    "ns:\n  n:\n    ros__parameters:\n      a: 1\n      a: 2\n      empty: []\n",  # X006, empty array
    "n:\n  ros__parameters:\n    mixed: [1, a]\n",  # P106
    "n:\n  value_first: 1\n",  # P104
    "n:\n  ros__parameters:\n    a: &x 1\n    b: *x\n",  # alias
    "n: [\n",  # X001
    "n:\n  ros__parameters:\n    gpio:\n    - interfaces: [a, b]\n    q: ''\n",
    "n:\n  ros__parameters:\n    e: []\n    e: [1]\n",
    "",
]


def _fast_and_generic(vf: nc.VirtualFile, distro: str) -> None:
    got = nc._param_model(vf, distro)

    def span(s: Span) -> Span:
        return s if s.file != vf.path else vf.span_of(s.line, s.col)

    want = nc._param_model_generic(vf, load_param_file(vf.path, vf.text, distro), span, {})
    assert got == want
    # the same FileParam objects are shared between ops and blocks
    got_ops = {id(op[3]) for op in got.ops if op[0] == "set"}
    want_ops = {id(op[3]) for op in want.ops if op[0] == "set"}
    assert ([id(p) in got_ops for b in got.blocks for p in b.params]
            == [id(p) in want_ops for b in want.blocks for p in b.params])


def _virtual(text: str, every: int) -> nc.VirtualFile:
    origin = {}
    for i, line in enumerate(text.splitlines(), start=1):
        for col in range(1, len(line) + 2):
            if (i * 31 + col) % every == 0:
                origin[(i, col)] = Span("/src/p.yaml", i + 100, col, i + 100, col + 1)
    return nc.VirtualFile("/tmp/physai-lint-virtual/x.yaml", text,
                          origin, Span("/launch.py", 3, 1, 3, 9), "/src/p.yaml")


def test_param_model_fast_path_knows_the_model() -> None:
    """A field added to the params model sends every model through the generic ``_remap`` until
    ``_param_model``'s fast path rebuilds it too."""
    assert nc._model_shapes_known()


def test_param_model_fast_path_is_the_generic_remap() -> None:
    for text in PARAM_TEXTS:
        for every in (1, 3, 10 ** 6):
            for distro in ("humble", "jazzy"):
                _fast_and_generic(_virtual(text, every), distro)


params_data = st.dictionaries(
    st.sampled_from(["n", "/**", "/ns/n", "a"]),
    st.one_of(st.dictionaries(st.just("ros__parameters"), data, max_size=1), data), max_size=3)


@settings(max_examples=200, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(params_data, st.integers(1, 7))
def test_param_model_fast_path_on_dumped_data(value: Any, every: int) -> None:
    try:
        text = yaml.dump(value, Dumper=CDUMPER)
    except yaml.YAMLError:
        return
    _fast_and_generic(_virtual(text, every), "humble")
