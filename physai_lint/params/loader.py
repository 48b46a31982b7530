"""``load_param_file``: parse a params YAML into a located ``ParamFileModel``.

The parse mirrors ``parse_file_events`` of ``rcl_yaml_param_parser/src/parse.c`` event by event
(libyaml events via PyYAML's ``CParser``: no Python objects are built for the document, so alias
bombs and deep nesting stay bounded). rcl stops at its first error, and so do we (that is the one
``P104``/``P106`` a file gets); duplicate mapping keys (``X006``) are reported for the whole file.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import yaml

from physai_lint.model.findings import Diagnostic
from physai_lint.model.span import Span

from .model import FileParam, NodeBlock, ParamFileModel
from .names import validate_node_key
from .rcl import RclParams
from .typing import pyyaml_scalar, rcl_type_scalar

_Loader = getattr(yaml, "CSafeLoader", yaml.SafeLoader)

PARAMS_KEY = "ros__parameters"
MAP_NODE_NAME_LVL = 1
MAP_PARAMS_LVL = 2
MAX_DEPTH = 256
MAX_EVENTS = 2_000_000
MAX_STRING_SZ = 256 * 1024  # rcl MAX_STRING_SZ in older releases; a generous bound here

HELP_STRUCTURE = (
    "a params file is `<node key>:` -> `ros__parameters:` -> parameters, e.g.\n"
    "my_node:\n  ros__parameters:\n    rate: 10.0"
)


class _RclError(Exception):
    def __init__(self, code: str, span: Span, message: str, help: str | None = None) -> None:
        super().__init__(message)
        self.code = code
        self.span = span
        self.message = message
        self.help = help


@dataclass
class _BlockBuilder:
    key: str
    key_span: Span
    nested: bool
    params_key_span: Span
    params_key_exact: bool
    params: list[FileParam] = field(default_factory=list)

    def freeze(self) -> NodeBlock:
        return NodeBlock(self.key, self.key_span, tuple(self.params), self.nested,
                         self.params_key_span, self.params_key_exact)


def _span(path: str, ev: Any, end: bool = True) -> Span:
    sm = ev.start_mark
    em = ev.end_mark if end else sm
    line = sm.line + 1
    col = sm.column + 1
    eline = em.line + 1
    ecol = em.column + 1
    if eline < line or (eline == line and ecol <= col):
        eline, ecol = line, col + 1
    return Span(path, line, col, eline, ecol)


def _quoted(ev: Any) -> bool:
    return ev.style in ("'", '"')


class _Parser:
    def __init__(self, path: str, text: str, distro: str) -> None:
        self.path = path
        self.text = text
        self.distro = distro
        self.model = ParamFileModel(path=path, distro=distro)
        # rcl's selected parameter (None: none selected), followed through the ops instead of
        # replaying every op into an RclParams while loading
        self.current: str | None = None
        # the selected parameter has had no value yet; ``first_of_name``: no other parameter of the
        # node has its name (then find_parameter of that name selects it again)
        self.pending = False
        self.first_of_name = True
        self.names: set[str] = set()  # every name a parameter of the selected node ever had
        self.node_names: dict[str, set[str]] = {}
        # a parameter may have lost the selection without a value (rcl leaves it unset): only
        # then does load_param_file replay the ops to find which
        self.maybe_unset = False
        # rcl state
        self.is_key = True
        self.is_seq = False
        self.seq_type: str | None = None
        self.map_level = MAP_NODE_NAME_LVL
        self.map_depth = 0
        self.is_new_map = False
        self.node_ns: list[tuple[str, Span]] = []  # node namespace tracker (joined with "/")
        self.param_ns: str | None = None
        self.param_ns_count = 0
        self.have_node = False
        self.block: _BlockBuilder | None = None
        self.blocks: list[_BlockBuilder] = []
        self.last_key_span: Span | None = None
        self.last_node_key_span: Span | None = None
        # current sequence
        self.seq_items: list[Any] = []
        self.seq_spans: list[Span] = []
        self.seq_launch: list[Any] = []
        self.seq_start: Any = None
        self.seq_key_span: Span | None = None
        # a mapping inside a sequence (``- interfaces: [a, b]``): map_depth outside it, while open
        self.seq_map_depth: int | None = None
        # rcl's error at the first item of another type, raised at the sequence's end so that the
        # array is still recorded for launch_ros, which reads composable nodes' files itself
        self.seq_mixed: _RclError | None = None
        self.failed = False

    # -- helpers ----------------------------------------------------------------------------------
    def op(self, *op: Any) -> None:
        self.model.ops.append(op)
        tag = op[0]
        if tag == "set":
            self.pending = False
            return
        if tag == "rename":
            self.current = op[1]
            self.first_of_name = op[1] not in self.names
            self.names.add(op[1])
            return
        # find_parameter of the name the selection already has keeps the same entry when it is the
        # first of that name; anything else moves the selection
        if self.pending and not (tag == "param" and op[1] == self.current and self.first_of_name):
            self.maybe_unset = True
        if tag == "param":
            self.current = op[1]
            self.names.add(op[1])
            self.pending = True
        else:
            self.current = None
            self.names = self.node_names.setdefault(op[1], set())
            self.pending = False
        self.first_of_name = True

    def err(self, code: str, span: Span, message: str, help: str | None = None) -> None:
        if self.seq_mixed is not None:  # rcl stopped at the mixed item, before this
            raise self.seq_mixed
        raise _RclError(code, span, message, help)

    def cur_name(self) -> str:
        return self.current if self.current is not None else ""

    def raw(self, ev: Any, end_ev: Any = None) -> str:
        start = ev.start_mark.index
        stop = (end_ev or ev).end_mark.index
        if 0 <= start <= stop <= len(self.text):
            return self.text[start:stop]
        return getattr(ev, "value", "") or ""

    # -- events ------------------------------------------------------------------------------------
    def scalar(self, ev: Any, span: Span) -> None:
        if self.is_key:
            self.parse_key(ev, span)
            self.is_key = False
            return
        if self.map_level < MAP_PARAMS_LVL:
            self.err("P104", self.last_key_span or span,
                     f"parameters must sit under 'ros__parameters': value at line {span.line} "
                     "comes before any 'ros__parameters' key "
                     f"(rcl: \"Cannot have a value before ros__parameters at line {span.line}\")",
                     HELP_STRUCTURE)
        if not self.have_node or self.current is None:
            self.err("P104", span,
                     f"'ros__parameters' must be a mapping of parameters, not a value "
                     f"(rcl: \"Cannot have a value before ros__parameters at line {span.line}\")",
                     HELP_STRUCTURE)
        value = ev.value
        quoted = _quoted(ev)
        if not quoted and len(value) == 0:
            self.err("P104", self.last_key_span or span,
                     f"parameter \"{self.cur_name()}\" has no value (rcl: \"No value at line "
                     f"{span.line}\")", "give it a value; write \"\" for an empty string")
        kind, typed = rcl_type_scalar(value, quoted, ev.tag, self.distro)
        launch_value = pyyaml_scalar(value, quoted, ev.tag)
        if not self.is_seq:
            fp = FileParam(self.cur_name(), typed, kind, self.raw(ev), span,
                           self.last_key_span or span, quoted, launch_value)
            self.op("set", kind, typed, fp)
            if self.block is not None:
                self.block.params.append(fp)
            self.is_key = True
        else:
            if self.seq_type is None:
                self.seq_type = kind
            elif self.seq_type != kind and self.seq_mixed is None:
                self.seq_mixed = _RclError(
                    "P106", span,
                    f"array \"{self.cur_name()}\" mixes types: {self.seq_type} then {kind} "
                    f"\"{value}\" (rcl: \"Sequence should be of same type. Value type "
                    f"'{kind}' do not belong at line_num {span.line}\")",
                    "make every element the same type (e.g. write 1.0 instead of 1 in a "
                    "double array, or quote every element of a string array)")
            if self.seq_map_depth is not None and self.seq_start is None:
                self.err("P104", span,
                         f"\"{value}\" is a value in a mapping inside a sequence (parameter "
                         f"\"{self.cur_name()}\"): rcl does not read it as a parameter but appends "
                         "it to an array, and the next key becomes an item too",
                         "give each key of a mapping inside a sequence a list value, or flatten "
                         "the structure into separate parameters")
            self.seq_items.append(typed)
            self.seq_launch.append(launch_value)
            self.seq_spans.append(span)

    def parse_key(self, ev: Any, span: Span) -> None:
        value = ev.value
        if len(value) == 0:
            self.err("P104", span, f"empty key (rcl: \"No key at line {span.line}\")")
        if len(value) > MAX_STRING_SZ:
            self.err("P104", span, f"key at line {span.line} is too long")
        self.last_key_span = span
        if self.map_level == MAP_NODE_NAME_LVL:
            if not value.startswith(PARAMS_KEY):
                self.node_ns.append((value, span))
                self.last_node_key_span = span
                return
            if not self.node_ns:
                self.err("P104", span,
                         "'ros__parameters' has no node key above it (rcl: \"There are no node "
                         f"names before ros__parameters at line {span.line}\")",
                         "put it under a node key such as `/**:` or `my_node:`")
            key = "/".join(part for part, _ in self.node_ns)
            key_span = self.node_ns[-1][1]
            problem = validate_node_key(key)
            if problem is not None:
                self.err("P104", key_span, f"invalid node key \"{key}\": {problem}",
                         "node keys are `/ns/node`, `node`, `/**`, `/**/node`, `/ns/*` ...; "
                         "nested keys are joined with `/`, so do not start a nested key with `/`")
            self.op("node", key, key_span)
            self.have_node = True
            self.node_ns.pop()
            self.map_level += 1
            self.block = _BlockBuilder(key, key_span, len(self.node_ns) > 0, span,
                                       value == PARAMS_KEY)
            self.blocks.append(self.block)
            return
        # MAP_PARAMS_LVL
        if self.is_new_map:
            if self.current is None:
                self.err("P104", span, f"internal error creating param namespace at line "
                         f"{span.line}")
            self.param_ns = self.current
            self.param_ns_count += 1
            self.is_new_map = False
        if self.param_ns is None:
            self.op("param", value)
        else:
            self.op("param", self.param_ns)
            self.op("rename", f"{self.param_ns}.{value}")

    def sequence_start(self, ev: Any) -> None:
        span = _span(self.path, ev, end=False)
        if self.is_seq and not (self.seq_map_depth is not None and self.seq_start is None
                                and not self.is_key):
            self.err("P104", span, f"nested sequences are not supported in parameter "
                     f"\"{self.cur_name()}\" (parameters have no nested array type)")
        if self.is_key:
            self.err("P104", span, f"a sequence cannot be a key (rcl: \"Sequences cannot be key "
                     f"at line {span.line}\")", HELP_STRUCTURE)
        if self.map_level < MAP_PARAMS_LVL:
            self.err("P104", self.last_key_span or span,
                     "parameters must sit under 'ros__parameters': a sequence comes before any "
                     f"'ros__parameters' key (rcl: \"Sequences can only be values and not keys "
                     f"in params. Error at line {span.line}\")", HELP_STRUCTURE)
        self.is_seq = True
        self.seq_type = None
        self.seq_items = []
        self.seq_launch = []
        self.seq_spans = []
        self.seq_start = ev
        self.seq_key_span = self.last_key_span

    def sequence_end(self, ev: Any) -> None:
        if self.is_seq and self.seq_start is not None:
            start = self.seq_start
            span = Span(self.path, start.start_mark.line + 1, start.start_mark.column + 1,
                        ev.end_mark.line + 1, ev.end_mark.column + 1)
            name = self.cur_name()
            if self.seq_items:
                kind = f"{self.seq_type}_array"
                fp = FileParam(name, list(self.seq_items), kind, self.raw(start, ev), span,
                               self.seq_key_span or span, False, list(self.seq_launch),
                               tuple(self.seq_spans) if len(self.seq_spans) == len(self.seq_items) else None)
                if self.seq_mixed is not None:
                    if self.block is not None:
                        self.block.params.append(fp)
                    mixed, self.seq_mixed = self.seq_mixed, None
                    raise mixed
                self.op("set", kind, list(self.seq_items), fp)
            else:
                fp = FileParam(name, [], "not_set", self.raw(start, ev), span,
                               self.seq_key_span or span, False, [])
            if self.block is not None:
                self.block.params.append(fp)
        elif self.seq_map_depth is not None and self.map_depth == self.seq_map_depth:
            self.seq_map_depth = None  # the end of the sequence that held a mapping
        self.is_seq = False
        self.is_key = True
        self.seq_start = None

    def mapping_start(self, ev: Any) -> None:
        # rcl accepts one mapping in a sequence whose keys hold lists (ros2_control's
        # ``gpio: - interfaces: [a]``): the keys become parameters below the sequence's name.
        span = _span(self.path, ev, end=False)
        if self.is_seq and (self.seq_items or self.seq_map_depth is not None):
            self.err("P104", span, f"sequence \"{self.cur_name()}\" mixes items with mappings: rcl "
                     "puts them all into one parameter", "flatten the structure into separate "
                     "parameters or arrays of scalars")
        if self.seq_map_depth is not None and not self.is_seq and self.map_depth == self.seq_map_depth:
            self.err("P104", span, f"a second mapping in the sequence above \"{self.cur_name()}\": "
                     "rcl nests it under the first one's last parameter instead of making a list "
                     "of maps (parameters have no dict type)", "flatten the structure into "
                     "separate parameters or arrays of scalars")
        if self.is_seq:
            self.seq_map_depth = self.map_depth
            self.is_seq = True
            self.seq_start = None
        self.map_depth += 1
        self.is_new_map = True
        self.is_key = True
        if self.map_level == MAP_PARAMS_LVL and self.map_depth - (len(self.node_ns) + 1) == 2:
            self.is_new_map = False

    def mapping_end(self, ev: Any) -> None:
        if self.map_level == MAP_PARAMS_LVL:
            if self.param_ns_count > 0:
                if self.param_ns_count == 1 or self.param_ns is None:
                    self.param_ns = None
                    self.param_ns_count = 0
                else:
                    cut = self.param_ns.rfind(".")
                    self.param_ns = self.param_ns[:cut] if cut >= 0 else self.param_ns
                    self.param_ns_count -= 1
            else:
                self.map_level -= 1
                self.block = None
        elif self.map_level == MAP_NODE_NAME_LVL and self.map_depth == len(self.node_ns) + 1:
            if self.node_ns:
                self.node_ns.pop()
        self.map_depth -= 1

    def alias(self, ev: Any) -> None:
        span = _span(self.path, ev)
        self.err("P104", span, f"YAML alias \"*{ev.anchor}\" (rcl: \"Will not support aliasing at "
                 f"line {span.line}\"): the node fails to start",
                 "repeat the values instead of using anchors, aliases or `<<:` merge keys")


class _DupTracker:
    """Duplicate mapping keys (X006) and the ``ros__parameters`` presence test, over all events."""

    def __init__(self, path: str, model: ParamFileModel) -> None:
        self.path = path
        self.model = model
        self.stack: list[list[Any]] = []  # [kind, expect_key, keys dict]
        self.pending: tuple[str, Span, Span] | None = None  # duplicate key waiting for its value

    def node(self, ev: Any, is_scalar: bool, span: Span | None = None) -> None:
        if self.pending is not None:
            key, dup_span, first = self.pending
            self.pending = None
            merged = isinstance(ev, yaml.MappingStartEvent)
            if merged:
                what = ("rcl merges both mappings, but launch_ros loads this file for a composable "
                        "node with PyYAML, which keeps only the second")
            else:
                what = "rcl keeps the first position and overwrites its value"
            (self.model.merged_keys if merged else self.model.diagnostics).append(Diagnostic(
                "X006", dup_span, f"duplicate key \"{key}\" (first at line {first.line}); {what}",
                "remove one of them, or merge their contents under one key", key=key))
        if self.stack and self.stack[-1][0] == "map":
            frame = self.stack[-1]
            if frame[1]:
                frame[1] = False
                if is_scalar:
                    key = ev.value
                    if span is None:
                        span = _span(self.path, ev)
                    if key.startswith(PARAMS_KEY):
                        self.model.has_ros_parameters = True
                    first = frame[2].get(key)
                    if first is not None:
                        self.pending = (key, span, first)
                    else:
                        frame[2][key] = span
            else:
                frame[1] = True

    def start(self, kind: str) -> None:
        self.stack.append([kind, True, {}])

    def end(self) -> None:
        if self.stack:
            self.stack.pop()


def load_param_file(path: str, text: str, distro: str = "humble") -> ParamFileModel:
    """Parse a params file; never raises. Diagnostics: X001 (YAML syntax), X006 (duplicate key),
    P104 (structure rcl rejects), P106 (mixed-type array)."""
    p = _Parser(path, text, distro)
    dup = _DupTracker(path, p.model)
    depth = 0
    count = 0
    # The parser's events one by one (``yaml.parse`` wraps the same loop in a generator), each
    # handed to the rcl mirror until its first error (``_fail``), and to the duplicate-key tracker.
    loader = _Loader(text)
    next_event = loader.get_event
    try:
        while (ev := next_event()) is not None:
            try:
                count += 1
                if count > MAX_EVENTS:
                    p.model.diagnostics.append(Diagnostic(
                        "X001", _span(path, ev), "file too large to analyse (too many YAML nodes)"))
                    p.model.ok = False
                    break
                if isinstance(ev, yaml.ScalarEvent):
                    span = _span(path, ev)  # one Span per scalar, shared by both trackers
                    dup.node(ev, True, span)
                    if not p.failed:
                        p.scalar(ev, span)
                elif isinstance(ev, (yaml.MappingStartEvent, yaml.SequenceStartEvent)):
                    mapping = isinstance(ev, yaml.MappingStartEvent)
                    dup.node(ev, False)
                    dup.start("map" if mapping else "seq")
                    depth += 1
                    if depth > MAX_DEPTH:
                        p.model.diagnostics.append(Diagnostic(
                            "P104", _span(path, ev, end=False),
                            f"nesting deeper than {MAX_DEPTH} levels"))
                        p.model.ok = False
                        break
                    if not p.failed:
                        if mapping:
                            p.mapping_start(ev)
                        else:
                            p.sequence_start(ev)
                elif isinstance(ev, yaml.MappingEndEvent):
                    dup.end()
                    depth -= 1
                    if not p.failed:
                        p.mapping_end(ev)
                elif isinstance(ev, yaml.SequenceEndEvent):
                    dup.end()
                    depth -= 1
                    if not p.failed:
                        p.sequence_end(ev)
                elif isinstance(ev, yaml.AliasEvent):
                    dup.node(ev, False)
                    if not p.failed:
                        p.alias(ev)
            except _RclError as e:  # rcl's first error: the handler ran last in its branch
                _fail(p, e)
    except yaml.MarkedYAMLError as exc:
        mark = error_mark(exc)
        line = mark.line + 1 if mark is not None else 1
        col = mark.column + 1 if mark is not None else 1
        msg = " ".join(str(x) for x in (exc.context, exc.problem) if x)
        p.model.diagnostics.append(Diagnostic(
            "X001", Span(path, line, col, line, col + 1),
            f"YAML syntax error at line {line}, column {col}: {msg}", key="yaml"))
        p.model.ok = False
        _drop_values_reaching(p, line)
    except (yaml.YAMLError, ValueError, RecursionError, MemoryError) as exc:
        p.model.diagnostics.append(Diagnostic(
            "X001", Span.whole_file(path), f"YAML error: {exc}", key="yaml"))
        p.model.ok = False
    finally:
        loader.dispose()
    if p.seq_mixed is not None and not p.failed:  # rcl stopped at the mixed item, before the rest
        _fail(p, p.seq_mixed)
    p.model.blocks = [b.freeze() for b in p.blocks]
    # rclcpp throws "No parameter value set" for a parameter that never got a value ([]).
    if p.model.ok and not p.failed and (p.maybe_unset or p.pending):
        rcl = RclParams()
        rcl.apply(p.model.ops, path)
        for node in rcl.nodes.values():
            for entry in node.entries:
                if entry.read() is None:
                    fp = entry.created_by
                    where = None
                    for b in p.model.blocks:
                        for prm in b.params:
                            if prm.name == entry.name and prm.kind == "not_set" and b.key == node.key:
                                where = prm.value_span
                    if where is None:
                        where = fp.value_span if fp is not None else Span.whole_file(path)
                    p.model.diagnostics.append(Diagnostic(
                        "P104", where,
                        f"parameter \"{entry.name}\" is an empty array: rcl leaves it unset and "
                        "rclcpp throws \"No parameter value set\" (rclpy gives NOT_SET)",
                        "remove the parameter or give the array at least one element",
                        key=entry.name))
    p.model.diagnostics.sort(key=lambda d: (d.span.line, d.span.col, d.code))
    if not p.model.ok and not p.model.has_ros_parameters:
        from physai_lint.sniff import has_params_key

        if not has_params_key(text):
            p.model.flat = _flat_block(path, text)
    return p.model


def _drop_values_reaching(p: _Parser, line: int) -> None:
    """Forget the values that reach the line of a syntax error: the scanner folded the next line
    into them (``zeta: 0.0`` then an over-indented ``use_mag: false`` is the scalar "0.0 use_mag"
    until the ``:``), a value no reader ever gives the node."""
    def reaches(fp: Any) -> bool:
        return isinstance(fp, FileParam) and fp.value_span.end_line >= line

    for b in p.blocks:
        b.params = [fp for fp in b.params if not reaches(fp)]
    p.model.ops = [op for op in p.model.ops if not (op and op[0] == "set" and reaches(op[-1]))]


def _flat_block(path: str, text: str) -> NodeBlock | None:
    """The parameters launch_ros gives a composable node from a file with no ``ros__parameters``
    key (``ParamFileModel.flat``): every scalar or list of scalars of the top mapping, under its
    dotted name (``normalize_parameters.py :: normalize_parameter_dict``). None when the file is
    not a mapping or cannot be read."""
    try:
        root = yaml.compose(text, Loader=_Loader)
    except (yaml.YAMLError, ValueError, RecursionError, MemoryError):
        return None
    if not isinstance(root, yaml.MappingNode):
        return None
    params: list[FileParam] = []
    budget = [MAX_EVENTS]

    def walk(node: yaml.MappingNode, prefix: str) -> None:
        for key, value in node.value:
            budget[0] -= 1
            if budget[0] < 0 or not isinstance(key, yaml.ScalarNode):
                return
            name = f"{prefix}{key.value}"
            key_span = _span(path, key)
            if isinstance(value, yaml.MappingNode):
                walk(value, name + ".")
            elif isinstance(value, yaml.ScalarNode):
                quoted = value.style in ("'", '"')
                kind, typed = rcl_type_scalar(value.value, quoted, value.tag)
                params.append(FileParam(name, typed, kind, value.value, _span(path, value), key_span,
                                        quoted, pyyaml_scalar(value.value, quoted, value.tag)))
            elif isinstance(value, yaml.SequenceNode) and all(isinstance(x, yaml.ScalarNode) for x in value.value):
                items = [(x.value, x.style in ("'", '"'), x.tag) for x in value.value]
                typed = [rcl_type_scalar(v, q, t) for v, q, t in items]
                kinds = {k for k, _ in typed}
                kind = "not_set" if not kinds else f"{kinds.pop()}_array" if len(kinds) == 1 else "string_array"
                params.append(FileParam(name, [v for _, v in typed], kind,  # type: ignore[arg-type]
                                        text[value.start_mark.index:value.end_mark.index],
                                        _span(path, value), key_span, False,
                                        [pyyaml_scalar(v, q, t) for v, q, t in items]))

    walk(root, "")
    span = Span.point(path, 1)
    return NodeBlock("", span, tuple(params), False, None, False)


def _fail(p: _Parser, e: _RclError) -> None:
    """rcl's first error: the file is not loaded; no later event goes to the rcl mirror."""
    p.failed = True
    p.model.ok = False
    p.model.diagnostics.append(Diagnostic(e.code, e.span, e.message, e.help))


def error_mark(exc: Any) -> Any:
    """Where to report a YAML syntax error: where the parser noticed it, except when it ran into
    the end of the file inside something never closed (an unterminated quote or bracket): there,
    where that thing starts (libyaml's context mark)."""
    if exc.context_mark is not None and "end of stream" in str(exc.problem or ""):
        return exc.context_mark
    return exc.problem_mark or exc.context_mark
