"""The parameters a node ends up with, and where each value came from (SEMANTICS.md §4).

Regular nodes (§4b): every params file and dict of the node is merged into one ``rcl_params_t``
(``RclParams``) in command-line order: node keys and entries keep their first-insertion position;
resolution walks the node keys in that order and every matching key overwrites earlier values.
Composable nodes (§4a): launch_ros reads the files with PyYAML; only ``/**`` and the exact key
count, the exact key beats ``/**`` within a file, and the last value wins across sources.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any, Mapping

from physai_lint.model.pickling import fast_init, fast_pickle_module
from physai_lint.model.span import Span
from physai_lint.resolve.model import (
    ParamSourceR,
    ResolvedParam,
    ResolvedParamDict,
    ResolvedParamFile,
    UnknownParams,
)

from .match import composable_key_matches, is_universal_key, key_matches
from .model import NodeBlock, ParamFileModel
from .rcl import RclParams, Write
from .typing import launch_dump_retype, pyyaml_kind


@fast_init
@dataclass(frozen=True, slots=True)
class Blame:
    span: Span | None
    source_desc: str
    value: Any
    overridden: bool
    kind: str | None = None
    node_key: str | None = None


@dataclass
class EffectiveParam:
    """``value``/``kind`` are what the node reads (``kind`` "not_set" for an empty array, ``None``
    with ``value`` None when unknown). ``chain`` lists every write to the parameter under a
    matching key, in resolution order; all but the winner are ``overridden``. ``certain`` is
    False when an unknown source (unknown file, unknown dict, unknown node name) may change it."""

    name: str
    value: Any
    kind: str | None
    origin: Span | None
    chain: list[Blame] = field(default_factory=list)
    certain: bool = True
    node_key: str | None = None
    item_spans: tuple[Span, ...] | None = None  # an array from a file: where each item is written


def _file_for(src: ResolvedParamFile, files: Mapping[str, ParamFileModel]) -> ParamFileModel | None:
    if src.model is not None:
        return src.model  # type: ignore[no-any-return]
    for p in (src.path, src.source):
        if p and p in files:
            return files[p]
    return None


def sources_complete(sources: Any, files: Mapping[str, ParamFileModel]) -> bool:
    """Whether every parameter source of a node is statically known (files read, dicts evaluated).

    A missing file does not count against it: launch drops it with a warning.
    """
    for src in sources:
        if isinstance(src, UnknownParams):
            return False
        if isinstance(src, ResolvedParamFile) and src.status != "missing" and _file_for(src, files) is None:
            return False
    return True


def _launch_slot(value: Any, distro: str) -> tuple[str, Any] | None:
    """How rcl reads a launch dict value after launch_ros dumps it to a temporary YAML file."""
    if isinstance(value, bool):
        return "bool", value
    if isinstance(value, int):
        return "integer", value
    if isinstance(value, float):
        return "double", value
    if isinstance(value, str):
        return launch_dump_retype(value, distro)
    if isinstance(value, bytes):
        return "byte_array", list(value)
    if isinstance(value, (list, tuple)):
        if not value:
            return None
        items = []
        for v in value:
            s = _launch_slot(v, distro)
            if s is None:
                return None
            items.append(s)
        kinds = {k for k, _ in items}
        if kinds == {"integer", "double"}:
            return "double_array", [float(v) for _, v in items]
        if len(kinds) != 1:
            return "unknown", None
        return f"{items[0][0]}_array", [v for _, v in items]
    return "unknown", None


def _feed_dict(rcl: RclParams, src: ResolvedParamDict, distro: str) -> None:
    rcl.find_node(src.key, src.span, "launch parameters")
    for prm in src.params:
        rcl.find_parameter(prm.name, None, "launch parameters")
        if prm.value is None:
            rcl.set("unknown", None, None, _dict_desc(prm), prm.span, unknown=True)
            continue
        slot = _launch_slot(prm.value, distro)
        if slot is None:
            continue  # empty list: nothing written (rclcpp: "No parameter value set")
        kind, value = slot
        rcl.set(kind, value, None, _dict_desc(prm), prm.span, unknown=(kind == "unknown"))


def _dict_desc(prm: ResolvedParam) -> str:
    return f"launch parameter \"{prm.name}\""


def _ops_by_node_key(model: ParamFileModel) -> list[tuple[str, list[tuple]]]:
    """``model.ops`` cut where a node key starts (rcl's state per key is changed only by the ops
    after that key's ``node`` op; ops before any key change nothing); made once per ops list."""
    got = model.op_segments
    if got is not None and got[0] is model.ops:
        return got[1]  # type: ignore[no-any-return]
    segments: list[tuple[str, list[tuple]]] = []
    for op in model.ops:
        if op[0] == "node":
            segments.append((op[1], [op]))
        elif segments:
            segments[-1][1].append(op)
    model.op_segments = (model.ops, segments)
    return segments


def effective_parameters(node_fqn: str | None, sources: list[ParamSourceR],
                         files: Mapping[str, ParamFileModel], composable: bool = False,
                         distro: str = "humble", named: bool = True) -> dict[str, EffectiveParam]:
    """``named``: False for a component loaded with no name (``params.match.unnamed_component``):
    its own parameter files give it their "/**" entries only."""
    if composable:
        return _effective_composable(node_fqn, sources, files, distro, named)
    rcl = RclParams()
    uncertain = False
    for src in sources:
        if isinstance(src, ResolvedParamFile):
            if src.status == "missing":
                continue  # launch drops it with a warning
            model = _file_for(src, files)
            if model is None:
                uncertain = True
                continue
            if node_fqn is None:
                rcl.apply(model.ops, model.path)
            else:
                # Only the blocks keyed to this node can change what is read for it below: replay
                # those (a nav2_params.yaml has ~50 node keys, each server matches one or two).
                for key, ops in _ops_by_node_key(model):
                    if key_matches(key, node_fqn):
                        rcl.apply(ops, model.path)
        elif isinstance(src, ResolvedParamDict):
            _feed_dict(rcl, src, distro)
        elif isinstance(src, UnknownParams):
            uncertain = True
    out: dict[str, EffectiveParam] = {}
    winners: dict[str, Write | None] = {}
    chains: dict[str, list[tuple[Write, str]]] = {}
    uncertain_names: set[str] = set()
    for key, node in rcl.nodes.items():
        if node_fqn is None:
            if not is_universal_key(key):
                uncertain_names.update(e.name for e in node.entries)
                continue
        elif not key_matches(key, node_fqn):
            continue
        for entry in node.entries:
            w = entry.read()
            winners[entry.name] = w
            chains.setdefault(entry.name, []).extend((x, key) for x in entry.writes)
            out[entry.name] = EffectiveParam(entry.name, None, None, None, node_key=key)
    for name, ep in out.items():
        w = winners[name]
        chain = []
        for x, key in chains.get(name, []):
            chain.append(Blame(x.span, x.source, x.value, x is not w,
                               None if x.unknown else x.slot, key))
        ep.chain = chain
        if w is None:
            ep.kind = "not_set"
            ep.value = None
        elif w.unknown:
            ep.kind = None
            ep.value = None
            ep.certain = False
        else:
            ep.kind = w.slot
            ep.value = w.value
            ep.origin = w.span
            ep.item_spans = w.param.item_spans if w.param is not None else None
        if uncertain or name in uncertain_names:
            ep.certain = False
    return out


def _launch_kind(value: Any) -> str | None:
    k = pyyaml_kind(value)
    if k in ("bool", "integer", "double", "string"):
        return k
    if k == "list":
        if not value:
            return "not_set"
        kinds = {pyyaml_kind(v) for v in value}
        if kinds == {"integer", "double"}:
            return "double_array"
        if len(kinds) == 1 and next(iter(kinds)) in ("bool", "integer", "double", "string"):
            return f"{next(iter(kinds))}_array"
    return None


def node_parameters(node: Any, files: Mapping[str, ParamFileModel], distro: str = "humble"
                    ) -> dict[str, EffectiveParam]:
    """``effective_parameters`` of a resolved node (``NodeInstance``)."""
    from physai_lint.params.match import unnamed_component

    return effective_parameters(node.fqn, node.param_sources, files, node.kind == "composable_node", distro,
                                named=not unnamed_component(node))


def _effective_composable(fqn: str | None, sources: list[ParamSourceR],
                          files: Mapping[str, ParamFileModel], distro: str = "humble", named: bool = True
                          ) -> dict[str, EffectiveParam]:
    out: dict[str, EffectiveParam] = {}
    uncertain = False
    # the container's command line, forwarded (forward_global_arguments): rcl reads it, and
    # rclcpp resolves those global arguments before the load request's parameter overrides
    forwarded = [s for s in sources if getattr(s, "origin", None) == "forwarded"]
    if forwarded:
        sources = [s for s in sources if getattr(s, "origin", None) != "forwarded"]
        for name, ep in effective_parameters(fqn, forwarded, files, False, distro).items():
            if ep.kind == "not_set" and ep.origin is None:
                continue
            out[name] = ep
            if ep.kind is None:
                ep.certain = False

    def put(name: str, value: Any, kind: str | None, span: Span | None, desc: str,
            key: str | None) -> None:
        ep = out.get(name)
        if ep is None:
            ep = out[name] = EffectiveParam(name, value, kind, span, node_key=key)
        else:
            ep.chain = [Blame(b.span, b.source_desc, b.value, True, b.kind, b.node_key)
                        for b in ep.chain]
            ep.value, ep.kind, ep.origin, ep.node_key = value, kind, span, key
            ep.item_spans = None
        ep.chain.append(Blame(span, desc, value, False, kind, key))
        if kind is None:
            ep.certain = False

    for src in sources:
        if isinstance(src, ResolvedParamFile):
            if src.status == "missing":
                continue
            model = _file_for(src, files)
            if model is None:
                uncertain = True
                continue
            if model.flat is not None:  # no ros__parameters key: every key is a parameter
                for prm in model.flat.params:
                    put(prm.name, prm.launch_value, _launch_kind(prm.launch_value), prm.value_span,
                        model.path, None)
                continue
            own = fqn if named else ""  # launch_ros matches "" (no name sent) against "/**" only
            blocks = matching_keys(own, model, composable=True) if own is not None else [
                b for b in model.blocks if b.key.lstrip("/") == "**" and not b.nested
                and b.params_key_exact]
            if own is None and any(not b.nested and b.key.lstrip("/") != "**" and "*" not in b.key
                                   for b in model.blocks):
                uncertain = True
            # within one file the exact key beats "**" whatever their order
            ordered = [b for b in blocks if b.key.lstrip("/") == "**"] + \
                      [b for b in blocks if b.key.lstrip("/") != "**"]
            for b in ordered:
                for prm in b.params:
                    put(prm.name, prm.launch_value, _launch_kind(prm.launch_value),
                        prm.value_span, model.path, b.key)
        elif isinstance(src, ResolvedParamDict):
            for prm in src.params:
                v = prm.value
                kind = None if v is None else _launch_kind(v)
                if isinstance(v, float) and math.isnan(v):
                    kind = "double"
                put(prm.name, v, kind, prm.span, _dict_desc(prm), src.key)
        elif isinstance(src, UnknownParams):
            uncertain = True
    if uncertain:
        for ep in out.values():
            ep.certain = False
    return out


def matching_keys(fqn: str, model: ParamFileModel, composable: bool = False) -> list[NodeBlock]:
    """The blocks of ``model`` that apply to the node ``fqn``, in file order."""
    if composable:
        return [b for b in model.blocks
                if b.params_key_exact and composable_key_matches(b.key, fqn, b.nested)]
    return [b for b in model.blocks if key_matches(b.key, fqn)]


def file_binds(fqn: str, model: ParamFileModel, composable: bool = False) -> bool:
    """Does any block of the file apply to the node?"""
    return bool(matching_keys(fqn, model, composable))


fast_pickle_module(globals())  # tuples instead of dataclasses.fields() per object (model/pickling.py)
