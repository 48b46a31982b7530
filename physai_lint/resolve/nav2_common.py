"""The ``nav2_common.launch`` substitutions, as nav2 implements them, over data only.

``RewrittenYaml`` (``nav2_common/launch/rewritten_yaml.py :: perform``): ``yaml.safe_load`` the
source, rewrite leaf keys anywhere and dotted paths (``substitute_params``), add missing paths that
contain ``ros__parameters`` (``add_params``), rename keys (``substitute_keys``), replace values by
their ``str()`` (``substitute_values``), wrap under a non-empty ``root_key``, then ``yaml.dump`` the
result to a temporary file that rcl parses again. We run the same steps on the loaded data and
re-parse the dumped text with our rcl loader, so PyYAML's YAML 1.1 typing of the source and rcl's
typing of the dump both apply (``"y"`` quoted in the source is dumped plain and read as a bool,
``1_000`` becomes 1000, an empty value becomes the string "null" ...). Positions are mapped back to
the source YAML (or to the rewrite in the launch file). A rewrite value that is unknown makes the
values it writes unknown; an unknown source, root key, key rewrite or dict makes the file unknown.

``ReplaceString`` replaces strings line by line; ``HasNodeParams`` tests a top-level key;
``LaunchConfigAsBool`` maps true/1/yes/on to "True" and anything else to "False".
"""
from __future__ import annotations

import dataclasses
import hashlib
from collections import OrderedDict
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import yaml

from physai_lint.model import values as v
from physai_lint.model.fields import ATOMS, field_names
from physai_lint.model.span import Span

if TYPE_CHECKING:
    from physai_lint.params.model import ParamFileModel
    from physai_lint.resolve.evaluate import Evaluator, Scope

VIRTUAL_DIR = "/tmp/physai-lint-virtual"
UNKNOWN_PREFIX = "__physai_lint_unknown_value_"
MAX_SOURCE = 2_000_000
TRUE_WORDS = ("true", "1", "yes", "on")


@dataclass
class VirtualFile:
    """A temporary file a substitution writes at launch time: its text, where each position of
    it comes from (``(line, col)`` -> span), and the span to use for anything else."""

    path: str
    text: str
    origin: dict[tuple[int, int], Span]
    fallback: Span
    source: str | None  # the workspace file it was made from
    line_origin: Callable[[int, int], Span | None] | None = None
    models: dict[str, ParamFileModel | None] = field(default_factory=dict)
    # RewrittenYaml's param_rewrites keys that changed nothing: no key of the source has the name,
    # no path is the dotted key, and it is no path through "ros__parameters" (add_params)
    unused_rewrites: tuple[str, ...] = ()

    def span_of(self, line: int, col: int) -> Span:
        hit = self.origin.get((line, col))
        if hit is not None:
            return hit
        if self.line_origin is not None:
            got = self.line_origin(line, col)
            if got is not None:
                return got
        return self.fallback

    def param_model(self, distro: str) -> ParamFileModel | None:
        """The model rcl builds from this file, spans mapped back; None when unknown."""
        if distro not in self.models:
            self.models[distro] = _param_model(self, distro)
        return self.models[distro]


# ---- reading the source -----------------------------------------------------------------------


_SAFE_LOADER = getattr(yaml, "CSafeLoader", yaml.SafeLoader)


class _RecordingLoader(_SAFE_LOADER):  # type: ignore[misc]
    """PyYAML's SafeLoader, remembering which node made which object (to keep positions). The
    libyaml parser when available: same nodes and marks, and the pure-Python one made resolving
    navigation2 take 160 s of CPU (47 RewrittenYaml loads of nav2_params.yaml per entry)."""

    def __init__(self, stream: str) -> None:
        super().__init__(stream)
        self.made: dict[int, tuple[Any, Any]] = {}

    def construct_object(self, node: Any, deep: bool = False) -> Any:
        obj = super().construct_object(node, deep)
        self.made[id(node)] = (node, obj)
        return obj


def _mark_span(file: str, node: Any) -> Span:
    sm, em = node.start_mark, node.end_mark
    end = (em.line + 1, em.column + 1)
    if end <= (sm.line + 1, sm.column + 1):
        end = (sm.line + 1, sm.column + 2)
    return Span(file, sm.line + 1, sm.column + 1, end[0], end[1])


def _load(text: str, path: str, span_of: Callable[[Any], Span]
          ) -> tuple[Any, dict[int, dict[Any, tuple[Span, Span]]]] | None:
    """``yaml.safe_load`` of ``text`` plus, per container object id, key -> (key span, value span)."""
    loader = _RecordingLoader(text)
    try:
        node = loader.get_single_node()
        data = loader.construct_document(node) if node is not None else None
    except (yaml.YAMLError, ValueError, TypeError, RecursionError, MemoryError):
        return None
    finally:
        loader.dispose()
    spans: dict[int, dict[Any, tuple[Span, Span]]] = {}
    seen: set[int] = set()

    # Recursion goes through the ``rec`` argument: a nested function naming itself is a reference
    # cycle that would keep the loader and its nodes until the cyclic collector runs.
    def walk(n: Any, rec: Any) -> None:
        if id(n) in seen:
            return
        seen.add(id(n))
        obj = loader.made.get(id(n), (None, None))[1]
        if isinstance(n, yaml.MappingNode) and isinstance(obj, dict):
            table = spans.setdefault(id(obj), {})
            for kn, vn in n.value:
                key = loader.made.get(id(kn), (None, None))[1]
                try:
                    table[key] = (span_of(kn), span_of(vn))
                except TypeError:  # unhashable key: PyYAML would have failed already
                    continue
                rec(vn, rec)
        elif isinstance(n, yaml.SequenceNode) and isinstance(obj, list):
            table = spans.setdefault(id(obj), {})
            for i, item in enumerate(n.value):
                table[i] = (span_of(item), span_of(item))
                rec(item, rec)

    if node is not None:
        walk(node, walk)
    return data, spans


# ---- RewrittenYaml, step by step as nav2 writes it ----------------------------------------------


class _Rewriter:
    def __init__(self, convert_types: bool, spans: dict[int, dict[Any, tuple[Span, Span]]],
                 rewrite_spans: dict[str, Span]) -> None:
        self.convert_types = convert_types
        self.spans = spans
        self.rewrite_spans = rewrite_spans

    def _set(self, d: Any, key: Any, value: Any, span: Span | None) -> None:
        d[key] = value
        if span is not None and isinstance(d, (dict, list)):
            old = self.spans.setdefault(id(d), {}).get(key)
            self.spans[id(d)][key] = (old[0] if old else span, span)

    def convert(self, text_value: str) -> Any:
        if self.convert_types:
            try:
                return float(text_value) if "." in text_value else int(text_value)
            except ValueError:
                pass
        if text_value.lower() == "true":
            return True
        if text_value.lower() == "false":
            return False
        return text_value

    def leaf_keys(self, data: Any) -> Any:
        if not isinstance(data, dict):
            return
        for key, child in data.items():
            if isinstance(child, dict):
                yield from self.leaf_keys(child)
            yield data, key

    def pathify(self, d: Any, p: str | None = None, paths: dict[str, Any] | None = None) -> dict[str, Any]:
        if p is None:
            paths = {}
            self.pathify(d, "", paths)
            return paths
        assert paths is not None
        pn = p + "." if p != "" else p
        if isinstance(d, dict):
            for k, x in d.items():
                self.pathify(x, str(pn) + str(k), paths)
        elif isinstance(d, list):
            for idx, e in enumerate(d):
                self.pathify(e, pn + str(idx), paths)
        else:
            paths[p] = d
        return paths

    def update_path(self, data: Any, keys: list[str], value: Any, span: Span | None) -> Any:
        for key in keys:
            if key == keys[-1]:
                self._set(data, key, value, span)
                break
            key = keys.pop(0)
            if isinstance(data, list):
                data[int(key)] = self.update_path(data[int(key)], keys, value, span)
            else:
                data[key] = self.update_path(data.get(key, {}), keys, value, span)
        return data

    def substitute_params(self, data: Any, rewrites: dict[str, str]) -> None:
        for d, key in list(self.leaf_keys(data)):
            if key in rewrites:
                self._set(d, key, self.convert(rewrites[key]), self.rewrite_spans.get(key))
        for path in self.pathify(data):
            if path in rewrites:
                data = self.update_path(data, path.split("."), self.convert(rewrites[path]),
                                        self.rewrite_spans.get(path))

    def add_params(self, data: Any, rewrites: dict[str, str]) -> None:
        paths = self.pathify(data)
        for path in rewrites:  # noqa: PLC0206 - mirrors nav2 (keys snapshot, dict mutated)
            if path not in paths:
                keys = path.split(".")
                if "ros__parameters" in keys:
                    data = self.update_path(data, keys, self.convert(rewrites[path]),
                                            self.rewrite_spans.get(path))

    def substitute_keys(self, data: Any, rewrites: dict[str, str]) -> None:
        if len(rewrites) != 0:
            for key in list(data.keys()):
                val = data[key]
                if key in rewrites:
                    new_key = rewrites[key]
                    data[new_key] = data[key]
                    old = self.spans.get(id(data), {}).get(key)
                    if old is not None:
                        self.spans[id(data)][new_key] = old
                    del data[key]
                if isinstance(val, dict):
                    self.substitute_keys(val, rewrites)

    def substitute_values(self, data: Any, rewrites: dict[str, str]) -> None:
        def process(value: Any, rec: Any) -> Any:  # recursion through ``rec``: no cycle
            if isinstance(value, dict):
                for k, x in list(value.items()):
                    new = rec(x, rec)
                    if new is not x and str(x) in rewrites and not isinstance(x, (dict, list)):
                        self._set(value, k, new, self.rewrite_spans.get("=" + str(x)))
                    else:
                        value[k] = new
                return value
            if isinstance(value, list):
                out = [rec(x, rec) for x in value]
                table = self.spans.get(id(value))
                if table is not None:
                    self.spans[id(out)] = dict(table)
                return out
            if str(value) in rewrites:
                return self.convert(rewrites[str(value)])
            return value

        for key in list(data.keys()):
            data[key] = process(data[key], process)


# ---- evaluation ---------------------------------------------------------------------------------


def _read_source(ev: Evaluator, path: str) -> tuple[str, str, VirtualFile | None] | None:
    """(text, file for spans, the virtual file it is) of a file a substitution opens."""
    virtual = ev.virtual.get(path)
    if virtual is not None:
        return virtual.text, virtual.path, virtual
    pk = ev.packages
    if pk is None:
        return None
    loc = pk.locate(path)
    if loc.status in ("missing", "not_installed"):
        ev.unopened[path] = (loc.status, loc.source)
    if loc.status != "ok":
        return None
    real = loc.source or path
    text = pk.read_text(real)
    if text is None or len(text) > MAX_SOURCE:
        return None
    return text, real, None


def _node_spans(file: str, virtual: VirtualFile | None) -> Callable[[Any], Span]:
    if virtual is None:
        return lambda n: _mark_span(file, n)
    return lambda n: virtual.span_of(n.start_mark.line + 1, n.start_mark.column + 1)


def _rewrites(ev: Evaluator, items: tuple[v.Rewrite, ...], scope: Scope, counter: list[int],
              unknowns: bool) -> tuple[dict[str, str], dict[str, Span]] | None:
    """Evaluated rewrites; an unknown value becomes a placeholder when ``unknowns`` allows it."""
    out: dict[str, str] = {}
    spans: dict[str, Span] = {}
    missing = False
    for item in items:
        text = ev.eval(item.value, scope)
        if text is None:
            if not unknowns:
                missing = True
                continue
            counter[0] += 1
            text = f"{UNKNOWN_PREFIX}{counter[0]}"
        out[item.key] = text
        if item.span is not None:
            spans[item.key] = item.span
    return None if missing else (out, spans)


def rewritten_yaml(ev: Evaluator, p: v.RewrittenYaml, scope: Scope) -> str | None:
    path = ev.eval(p.path, scope)
    counter = [0]
    params = _rewrites(ev, p.param_rewrites or (), scope, counter, True)
    keys = _rewrites(ev, p.key_rewrites or (), scope, counter, False)
    values = _rewrites(ev, p.value_rewrites or (), scope, counter, True)
    root = ev.eval(p.root_key, scope) if p.root_key is not None else ""
    if (path is None or params is None or keys is None or values is None or root is None
            or p.param_rewrites is None or p.key_rewrites is None or p.value_rewrites is None
            or p.convert_types is None):
        return None
    # The same RewrittenYaml with the same inputs writes the same file: nav2 hands one to every
    # server (47 evaluations per bringup entry, ~0.1 s each, before this memo).
    memo = ev.file_memo
    key = ("RewrittenYaml", p.span, path, tuple(params[0].items()), tuple(keys[0].items()), tuple(values[0].items()),
           root, p.convert_types)
    if key not in memo:
        memo[key] = _rewritten_yaml(ev, p, path, params, keys, values, root)
    written = memo[key]
    vf = ev.virtual.get(written) if written is not None else None
    if vf is not None and ev.on_unused_rewrite is not None:  # every evaluation: the first may be inactive
        for name in vf.unused_rewrites:
            span = params[1].get(name)
            if span is not None:
                ev.on_unused_rewrite(span, name, vf.source or path)
    return written


def _rewritten_yaml(ev: Evaluator, p: v.RewrittenYaml, path: str, params: Any, keys: Any, values: Any,
                    root: str) -> str | None:
    src = _read_source(ev, path)
    if src is None:
        return None
    text, file, virtual = src
    fallback = p.span or Span.whole_file(file)
    root_span = (v.span_of(p.root_key) or fallback) if root else None
    # Everything the written file and its positions depend on; the file itself then serves every
    # entry of the run that asks for the same rewrite (nav2: each bringup entry, ~0.1 s each).
    key = ("RewrittenYaml", text, file, virtual.path if virtual else None, tuple(params[0].items()),
           tuple(params[1].items()), tuple(keys[0].items()), tuple(values[0].items()), tuple(values[1].items()),
           root, root_span, p.convert_types, fallback)

    def make(vpath: str) -> VirtualFile | None:
        loaded = _loaded_copy(text, file, virtual)
        if loaded is None:
            return None
        data, spans = loaded
        rewrite_spans = dict(params[1])
        for k, span in values[1].items():
            rewrite_spans["=" + k] = span
        rw = _Rewriter(p.convert_types, spans, rewrite_spans)
        unused = _unused_rewrites(rw, data, params[0])
        try:
            rw.substitute_params(data, params[0])
            rw.add_params(data, params[0])
            rw.substitute_keys(data, keys[0])
            rw.substitute_values(data, values[0])
        except Exception:  # noqa: BLE001 - RewrittenYaml raises here too: the launch fails
            return None
        if root:
            data = {root: data}
            spans[id(data)] = {root: (root_span, root_span)}
        try:
            dumped = yaml.dump(data, Dumper=_Dumper)
        except yaml.YAMLError:
            return None
        out = VirtualFile(vpath, dumped, {}, fallback, virtual.source if virtual else file,
                          unused_rewrites=unused)
        _map_positions(out, dumped, data, spans)
        return out

    out = _shared(ev, key, make)
    return out.path if out is not None else None


def _unused_rewrites(rw: _Rewriter, data: Any, rewrites: dict[str, str]) -> tuple[str, ...]:
    """The ``param_rewrites`` keys RewrittenYaml will not write into ``data`` (before rewriting):
    ``substitute_params`` replaces keys of that name at any depth and existing dotted paths,
    ``add_params`` adds only missing paths through "ros__parameters" (navigation2#3111)."""
    if not rewrites or not isinstance(data, dict):
        return ()
    names = {key for _, key in rw.leaf_keys(data)}
    paths = rw.pathify(data)
    return tuple(k for k in rewrites if k not in names and k not in paths
                 and "ros__parameters" not in k.split("."))


def _cached(cache: OrderedDict[Any, Any], size: int, key: Any, make: Callable[[], Any]) -> Any:
    """``cache[key]``, made by ``make()`` on a miss; the least recently used entry beyond ``size``
    is dropped."""
    if key in cache:
        cache.move_to_end(key)
        return cache[key]
    value = cache[key] = make()
    if len(cache) > size:
        cache.popitem(last=False)
    return value


_LOADED: OrderedDict[tuple[str, str, str | None], Any] = OrderedDict()


def _loaded(text: str, file: str, virtual: VirtualFile | None
            ) -> tuple[Any, dict[int, dict[Any, tuple[Span, Span]]]] | None:
    """``_load`` of a source, once per process: the caller must not change it."""
    return _cached(_LOADED, 32, (text, file, virtual.path if virtual else None),
                   lambda: _load(text, file, _node_spans(file, virtual)))


def _loaded_copy(text: str, file: str, virtual: VirtualFile | None
                 ) -> tuple[Any, dict[int, dict[Any, tuple[Span, Span]]]] | None:
    """``_loaded`` handed out as a fresh copy (the rewrite changes it in place): one
    nav2_params.yaml serves every distinct rewrite of it. Objects that YAML aliases share stay
    shared in the copy, as in ``yaml.safe_load``'s result."""
    loaded = _loaded(text, file, virtual)
    if loaded is None:
        return None
    data, spans = loaded
    out_spans: dict[int, dict[Any, tuple[Span, Span]]] = {}
    made: dict[int, Any] = {}

    def copy(obj: Any, rec: Any) -> Any:  # recursion through ``rec``: no reference cycle
        if not isinstance(obj, (dict, list)):
            return obj
        if id(obj) in made:
            return made[id(obj)]
        new: Any = {} if isinstance(obj, dict) else []
        made[id(obj)] = new
        if isinstance(obj, dict):
            for k, x in obj.items():
                new[k] = rec(x, rec)
        else:
            new.extend(rec(x, rec) for x in obj)
        table = spans.get(id(obj))
        if table is not None:
            out_spans[id(new)] = dict(table)
        return new

    return copy(data, copy), out_spans


# The dumped files of one process repeat the same few thousand scalars (47 rewrites of one
# nav2_params.yaml): what PyYAML computes from a scalar's text alone is computed once.
_MEMO_SIZE = 200_000
# A scalar mapping key's value by (tag, text), as ``construct_object`` makes it: immutable values
# (str, int, float, bool, None, bytes, dates), None where construction fails.
_KEYS: dict[tuple[str, str], Any] = {}


def _resolve_memo(base: Any) -> Callable[..., str]:
    """``base.resolve``, memoised for scalars: with no path resolvers registered, the tag of a
    scalar depends on its text and implicit flags only. One table per class (each class may have
    its own implicit resolvers)."""
    resolve: Callable[..., str] = base.resolve
    memo: dict[tuple[str, Any], str] = {}

    def cached(self: Any, kind: Any, value: Any, implicit: Any) -> str:
        if kind is not yaml.ScalarNode or self.yaml_path_resolvers:
            return resolve(self, kind, value, implicit)
        key = (value, implicit)
        tag = memo.get(key)
        if tag is None:
            if len(memo) > _MEMO_SIZE:
                memo.clear()
            tag = memo[key] = resolve(self, kind, value, implicit)
        return tag

    return cached


# ``yaml.dump``'s Dumper with libyaml's emitter where installed: the same representer and resolver
# choose tags and styles, and on the ~900 YAML files of public ROS 2 repositories the text is the
# same except the ``...`` after a bare scalar document, which a RewrittenYaml never writes.
_BASE_DUMPER = getattr(yaml, "CDumper", yaml.Dumper)
_STR, _INT, _BOOL, _NULL = ("tag:yaml.org,2002:str", "tag:yaml.org,2002:int", "tag:yaml.org,2002:bool",
                            "tag:yaml.org,2002:null")
_SEQ, _MAP = "tag:yaml.org,2002:seq", "tag:yaml.org,2002:map"


class _Dumper(_BASE_DUMPER):  # type: ignore[misc,valid-type]
    """``_BASE_DUMPER`` with ``represent_data`` spelled out for exactly-typed ``str``, ``int``,
    ``float``, ``bool``, ``None``, ``dict`` and ``list`` (the same nodes, anchors and styles as the
    representers it inherits, which still handle every other type) and ``resolve`` memoised:
    the same nodes, so the same text, for a quarter less than ``yaml.dump`` with ``CDumper``."""

    resolve = _resolve_memo(_BASE_DUMPER)

    def represent_data(self, data: Any) -> Any:
        kind = type(data)
        if kind is str:
            self.alias_key = None
            return yaml.ScalarNode(_STR, data, style=self.default_style)
        if kind is dict or kind is list:
            return self._container(data, kind is dict)
        if kind is int:
            self.alias_key = None
            return yaml.ScalarNode(_INT, str(data), style=self.default_style)
        if kind is float:
            self.alias_key = None
            return self.represent_float(data)
        if kind is bool:
            self.alias_key = None
            return yaml.ScalarNode(_BOOL, "true" if data else "false", style=self.default_style)
        if data is None:
            self.alias_key = None
            return yaml.ScalarNode(_NULL, "null", style=self.default_style)
        return super().represent_data(data)

    def _container(self, data: Any, mapping: bool) -> Any:
        # BaseRepresenter.represent_data + represent_mapping / represent_sequence
        alias_key = id(data)
        self.alias_key = alias_key  # type: ignore[assignment]
        known = self.represented_objects
        if alias_key in known:
            return known[alias_key]
        self.object_keeper.append(data)
        value: list[Any] = []
        best_style = True
        represent = self.represent_data
        if mapping:
            node = known[alias_key] = yaml.MappingNode(_MAP, value, flow_style=None)
            items = list(data.items())
            if self.sort_keys:
                try:
                    items = sorted(items)
                except TypeError:
                    pass
            for item_key, item_value in items:
                node_key = represent(item_key)
                node_value = represent(item_value)
                if not (isinstance(node_key, yaml.ScalarNode) and not node_key.style):
                    best_style = False
                if not (isinstance(node_value, yaml.ScalarNode) and not node_value.style):
                    best_style = False
                value.append((node_key, node_value))
        else:
            node = known[alias_key] = yaml.SequenceNode(_SEQ, value, flow_style=None)
            for item in data:
                node_item = represent(item)
                if not (isinstance(node_item, yaml.ScalarNode) and not node_item.style):
                    best_style = False
                value.append(node_item)
        node.flow_style = self.default_flow_style if self.default_flow_style is not None else best_style
        return node



# The temporary files of one process, by everything that decides their text and positions: the
# same input gives the same file (and the same parsed model) to every entry and every run.
_SHARED: OrderedDict[tuple[Any, ...], VirtualFile | None] = OrderedDict()


def _shared(ev: Evaluator, key: tuple[Any, ...], make: Callable[[str], VirtualFile | None]) -> VirtualFile | None:
    """The virtual file for ``key``, made once; registered with ``ev`` so that later substitutions
    of this entry find it by path. Its path is named by the key's digest, so it is the same in every
    entry and in every process (``--jobs``)."""
    def named() -> VirtualFile | None:
        digest = hashlib.sha256(repr(key).encode("utf-8", "surrogatepass")).hexdigest()[:16]
        return make(f"{VIRTUAL_DIR}/{key[0]}-{digest}.yaml")

    vf: VirtualFile | None = _cached(_SHARED, 512, key, named)
    if vf is not None:
        ev.virtual[vf.path] = vf
    return vf


class _PositionLoader(_SAFE_LOADER):  # type: ignore[misc,valid-type]
    """The safe loader with ``resolve`` memoised (a third of ``_map_positions``' compose)."""

    resolve = _resolve_memo(_SAFE_LOADER)


def _map_positions(vf: VirtualFile, dumped: str, data: Any,
                   spans: dict[int, dict[Any, tuple[Span, Span]]]) -> None:
    """Map each node of the dumped text to where the same value came from."""
    # Composed only (libyaml): the values are ``data`` already; only mapping keys are constructed.
    loader = _PositionLoader(dumped)
    try:
        node = loader.get_single_node()
    except (yaml.YAMLError, ValueError, TypeError, RecursionError):
        loader.dispose()
        return

    def key_of(kn: Any) -> Any:
        if type(kn) is yaml.ScalarNode:
            memo = (kn.tag, kn.value)
            got = _KEYS.get(memo, _KEYS)
            if got is not _KEYS:
                return got
        try:
            got = loader.construct_object(kn, deep=True)
        except (yaml.YAMLError, ValueError, TypeError, RecursionError):
            got = None
        if type(kn) is yaml.ScalarNode:
            if len(_KEYS) > _MEMO_SIZE:
                _KEYS.clear()
            _KEYS[memo] = got
        return got

    def at(n: Any) -> tuple[int, int]:
        return n.start_mark.line + 1, n.start_mark.column + 1

    def walk(n: Any, obj: Any, rec: Any) -> None:  # recursion through ``rec``: no reference cycle
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
                rec(vn, child, rec)
        elif isinstance(n, yaml.SequenceNode) and isinstance(obj, list):
            for i, item in enumerate(n.value):
                hit = table.get(i)
                if hit is not None:
                    vf.origin[at(item)] = hit[1]
                if i < len(obj):
                    rec(item, obj[i], rec)

    if node is not None:
        walk(node, data, walk)
    loader.dispose()


def replace_string(ev: Evaluator, p: v.ReplaceString, scope: Scope) -> str | None:
    path = ev.eval(p.path, scope)
    reps = _rewrites(ev, p.replacements or (), scope, [0], False)
    if p.condition is not None:
        truth = ev.condition(p.condition[0], p.condition[1], scope)
        if truth is None:
            return None
        if not truth:
            return path
    if path is None or reps is None or p.replacements is None:
        return None
    src = _read_source(ev, path)
    if src is None:
        return None
    text, file, virtual = src
    lines = []
    for line in text.splitlines(keepends=True):
        for key, value in reps[0].items():
            if key in line:
                line = line.replace(key, value)
        lines.append(line)
    out = _derive(ev, "ReplaceString", "".join(lines), text, file, virtual, p.span)
    return out.path if out is not None else None


def _derive(ev: Evaluator, kind: str, new: str, text: str, file: str, virtual: VirtualFile | None,
            span: Span | None) -> VirtualFile | None:
    """A temporary copy of a file with some lines changed: positions stay those of the source on
    unchanged lines; a changed line points at the last value written on it. The same file with
    the same lines changed is one temporary file (and one model)."""
    if new.count("\n") != text.count("\n"):
        return None  # a replacement added lines: positions cannot be kept (rare); stay silent
    fallback = span or Span.whole_file(file)

    def make(vpath: str) -> VirtualFile:
        out = VirtualFile(vpath, new, {}, fallback, virtual.source if virtual else file)
        changed = {i + 1 for i, (a, b) in enumerate(zip(text.splitlines(), new.splitlines())) if a != b}
        by_line: dict[int, list[tuple[int, Span]]] = {}
        if virtual is not None:
            for (ln, col), sp in virtual.origin.items():
                by_line.setdefault(ln, []).append((col, sp))

        def line_origin(line: int, col: int) -> Span | None:
            if virtual is None:
                return Span(file, line, col, line, col + 1) if line not in changed else Span(file, line, 1, line, 2)
            if line not in changed:
                return virtual.span_of(line, col)
            hits = sorted(by_line.get(line, []))
            return hits[-1][1] if hits else virtual.span_of(line, 1)

        out.line_origin = line_origin
        return out

    return _shared(ev, (kind, new, text, file, virtual.path if virtual else None, fallback), make)


def _substitutions_of(ev: Evaluator, text: str, file: str) -> Any:
    """The ``$(...)`` parse of a whole file's text, once per file (None when malformed)."""
    memo = ev.file_memo
    key = ("substitutions", file, text)
    if key not in memo:
        from physai_lint.frontends.substitutions import parse_substitutions

        value, diags = parse_substitutions(text, Span(file, 1, 1, 1, 2))
        memo[key] = None if diags else value
    return memo[key]


def with_substitutions(ev: Evaluator, path: str, span: Span, scope: Scope) -> VirtualFile | None | bool:
    """``ParameterFile(..., allow_substs=True)`` / ``<param from=... allow_substs="true"/>``: launch_ros
    performs the ``$(...)`` of the whole text (comments included) into another temporary file.

    Works on a workspace file or on a temporary file another substitution wrote. False when there
    is nothing to do (unreadable here, or no ``$(`` in it); None when the substitutions cannot be
    performed statically (then its values are unknown).
    """
    src = _read_source(ev, path)
    if src is None or "$(" not in src[0]:
        return False
    text, file, virtual = src
    value = _substitutions_of(ev, text, file)
    if value is None:
        return None
    new = ev.eval(value, scope)
    if new is None:
        return None
    return _derive(ev, "ParameterFile", new, text, file, virtual, virtual.fallback if virtual else span)


def has_node_params(ev: Evaluator, p: v.HasNodeParams, scope: Scope) -> str | None:
    path = ev.eval(p.path, scope)
    if path is None or p.node_name is None:
        return None
    src = _read_source(ev, path)
    if src is None:
        return None
    loaded = _loaded(*src)
    if loaded is None:
        return None
    data = loaded[0]
    return "True" if isinstance(data, dict) and p.node_name in data else "False"


def launch_config_as_bool(ev: Evaluator, p: v.LaunchConfigAsBool, scope: Scope) -> str | None:
    value = ev.eval(p.name, scope)
    if value is None:
        return None
    return "True" if value.strip().lower() in TRUE_WORDS else "False"


def evaluate(ev: Evaluator, p: Any, scope: Scope) -> str | None:
    if isinstance(p, v.RewrittenYaml):
        return rewritten_yaml(ev, p, scope)
    if isinstance(p, v.ReplaceString):
        return replace_string(ev, p, scope)
    if isinstance(p, v.HasNodeParams):
        return has_node_params(ev, p, scope)
    return launch_config_as_bool(ev, p, scope)


# ---- the params model of a virtual file ---------------------------------------------------------


def _param_model(vf: VirtualFile, distro: str) -> ParamFileModel | None:
    from physai_lint.params.loader import load_param_file
    from physai_lint.params.model import FileParam, NodeBlock, ParamFileModel

    model = load_param_file(vf.path, vf.text, distro)
    path = vf.path
    span_of = vf.span_of
    memo: dict[int, Any] = {}

    def span(s: Span) -> Span:
        if s.file != path:
            return s
        return span_of(s.line, s.col)

    if type(model) is not ParamFileModel or not _model_shapes_known() or model.op_segments is not None:
        return _param_model_generic(vf, model, span, memo)
    # ``_remap`` of the model, spelled out for the shapes the loader builds (a fifth of the cost of
    # a nav2 rewrite went into the generic walk). Values are scalars or lists of scalars: kept as
    # they are instead of copied. Placeholders become unknown values in the same pass.
    params: dict[int, Any] = {}

    def param(p: Any) -> Any:
        got = params.get(id(p))
        if got is None:
            if type(p) is FileParam:
                got = FileParam(p.name, p.value, p.kind, p.raw, span(p.value_span), span(p.key_span),
                                p.quoted, p.launch_value,
                                tuple(span(x) for x in p.item_spans) if p.item_spans else None)
            else:
                got = _remap(p, span, memo)
            params[id(p)] = got
        return got

    def unknown(p: Any) -> Any:
        if type(p) is FileParam:
            return FileParam(p.name, None, p.kind, p.raw, p.value_span, p.key_span, p.quoted, None, p.item_spans)
        return dataclasses.replace(p, value=None, launch_value=None)

    ops = []
    for op in model.ops:
        tag = op[0] if type(op) is tuple and op else None
        if tag == "set" and len(op) == 4:
            fp = op[3]
            fp = param(fp) if fp is not None else None
            if _has_placeholder(op[2]):
                op = ("set", "unknown", None, unknown(fp) if fp is not None else None)
            else:
                op = (tag, op[1], op[2], fp)
        elif tag == "node" and len(op) == 3 and type(op[2]) is Span:
            op = (tag, op[1], span(op[2]))
        elif (tag == "param" or tag == "rename") and len(op) == 2 and type(op[1]) is str:
            pass
        else:
            op = _remap(op, span, memo)
            if type(op) is tuple and op and op[0] == "set" and _has_placeholder(op[2]):
                fp = op[3]
                op = ("set", "unknown", None, unknown(fp) if fp is not None else None)
        ops.append(op)
    blocks = []
    for b in model.blocks:
        if type(b) is NodeBlock:
            pks = b.params_key_span
            b = NodeBlock(b.key, span(b.key_span), tuple(
                unknown(prm) if _has_placeholder(prm.value) else prm for prm in map(param, b.params)),
                b.nested, span(pks) if pks is not None else None, b.params_key_exact)
        else:
            b = _remap(b, span, memo)
            b = dataclasses.replace(b, params=tuple(
                unknown(prm) if _has_placeholder(prm.value) else prm for prm in b.params))
        blocks.append(b)
    model.ops = ops
    model.blocks = blocks
    if model.flat is not None:  # a rewritten file with no ros__parameters key (rare): generic
        flat = _remap(model.flat, span, memo)
        model.flat = dataclasses.replace(flat, params=tuple(
            unknown(prm) if _has_placeholder(prm.value) else prm for prm in flat.params))
    model.diagnostics = _remap(model.diagnostics, span, memo)
    model.merged_keys = _remap(model.merged_keys, span, memo)
    model.path = vf.source or vf.path
    return model


def _param_model_generic(vf: VirtualFile, model: Any, span: Callable[[Span], Span],
                         memo: dict[int, Any]) -> Any:
    """``_param_model`` by the generic ``_remap``: for shapes the fast path does not know."""
    model = _remap(model, span, memo)
    model.path = vf.source or vf.path
    ops = []
    for op in model.ops:
        if op[0] == "set" and _has_placeholder(op[2]):
            fp = op[3]
            fp = dataclasses.replace(fp, value=None, launch_value=None) if fp is not None else None
            op = ("set", "unknown", None, fp)
        ops.append(op)
    model.ops = ops
    def blanked(b: Any) -> Any:
        return dataclasses.replace(b, params=tuple(
            dataclasses.replace(prm, value=None, launch_value=None) if _has_placeholder(prm.value) else prm
            for prm in b.params))

    model.blocks = [blanked(b) for b in model.blocks]
    if getattr(model, "flat", None) is not None:
        model.flat = blanked(model.flat)
    return model


_SHAPES: list[bool] = []


def _model_shapes_known() -> bool:
    """The params model still has the fields ``_param_model``'s fast path rebuilds (a field added
    later, which might hold a span, sends models through the generic ``_remap``)."""
    if not _SHAPES:
        from physai_lint.params.model import FileParam, NodeBlock, ParamFileModel

        def names(cls: type) -> tuple[str, ...]:
            return tuple(f.name for f in dataclasses.fields(cls))

        _SHAPES.append(
            names(FileParam) == ("name", "value", "kind", "raw", "value_span", "key_span", "quoted",
                                 "launch_value", "item_spans")
            and names(NodeBlock) == ("key", "key_span", "params", "nested", "params_key_span",
                                     "params_key_exact")
            and names(ParamFileModel) == ("path", "blocks", "diagnostics", "ops", "ok",
                                          "has_ros_parameters", "distro", "merged_keys", "op_segments",
                                          "flat"))
    return _SHAPES[0]


def _has_placeholder(value: Any) -> bool:
    if isinstance(value, str):
        return value.startswith(UNKNOWN_PREFIX)
    if isinstance(value, list):
        return any(_has_placeholder(x) for x in value)
    return False


def _remap(obj: Any, fn: Callable[[Span], Span], memo: dict[int, Any]) -> Any:
    """``obj`` with every ``Span`` passed through ``fn`` (dataclasses, tuples and lists)."""
    kind = type(obj)
    if kind is Span:
        return fn(obj)
    if kind in ATOMS:
        return obj
    if id(obj) in memo:
        return memo[id(obj)]
    out: Any = obj
    if isinstance(obj, tuple):
        out = tuple(x if type(x) in ATOMS else _remap(x, fn, memo) for x in obj)
    elif isinstance(obj, list):
        out = [x if type(x) in ATOMS else _remap(x, fn, memo) for x in obj]
    elif dataclasses.is_dataclass(obj) and not isinstance(obj, type):
        changes = {}
        for name in field_names(kind):
            old = getattr(obj, name)
            if type(old) in ATOMS:
                continue
            new = _remap(old, fn, memo)
            if new is not old:
                changes[name] = new
        if changes:
            if kind.__dataclass_params__.frozen:  # type: ignore[attr-defined]
                out = dataclasses.replace(obj, **changes)
            else:
                for k, x in changes.items():
                    setattr(obj, k, x)
    memo[id(obj)] = out
    return out

