"""The located model of one parameter YAML file (what rcl_yaml_param_parser would build).

``ParamFileModel.blocks`` lists one ``NodeBlock`` per ``ros__parameters`` mapping in file order.
``ops`` is the sequence of rcl operations (find node, find parameter, rename, set a value slot) the
file performs on an ``rcl_params_t``; ``effective.py`` replays the ops of every file a node loads
into one shared ``RclParams`` to mirror rcl's merge across files exactly.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Literal, Union

from physai_lint.model.findings import Diagnostic
from physai_lint.model.pickling import fast_init, fast_pickle_module
from physai_lint.model.span import Span

# Kinds of a parameter value in a params file (rcl never makes byte arrays from YAML).
# "not_set" is an empty sequence ``[]``: rcl leaves the variant empty.
ValueKind = Literal[
    "bool", "integer", "double", "string",
    "bool_array", "integer_array", "double_array", "string_array", "byte_array", "not_set",
]

# The rcl_variant_t slots in the order rclcpp/rclpy read them (first non-NULL wins).
SLOT_ORDER: tuple[str, ...] = (
    "bool", "integer", "double", "string",
    "byte_array", "bool_array", "integer_array", "double_array", "string_array",
)


@fast_init
@dataclass(frozen=True, slots=True)
class FileParam:
    """One parameter value as written: ``name`` is the dotted name rcl gives it (quirks included),
    ``value`` the rcl-typed value (a list for arrays), ``launch_value`` what PyYAML makes of it
    (launch_ros reads composable nodes' files with PyYAML)."""

    name: str
    value: Any
    kind: ValueKind
    raw: str
    value_span: Span
    key_span: Span
    quoted: bool = False
    launch_value: Any = None
    item_spans: tuple[Span, ...] | None = None  # an array: where each item is written


@fast_init
@dataclass(frozen=True, slots=True)
class NodeBlock:
    """A ``<node key>: {ros__parameters: {...}}`` block. ``key`` is the node key as rcl stores it
    (nested maps joined with ``/``), ``nested`` when it came from nested maps (launch_ros joins
    those for composable nodes too, each part stripped of its leading ``/``: ``params.match``)."""

    key: str
    key_span: Span
    params: tuple[FileParam, ...]
    nested: bool = False
    params_key_span: Span | None = None
    params_key_exact: bool = True  # the key is exactly "ros__parameters" (not just a prefix match)


# rcl ops, replayed by effective.py:
#   ("node", key, key_span)        find_node: select (or append) the node key
#   ("param", name)                find_parameter: select (or append) a parameter of that node
#   ("rename", new_name)           rename the selected parameter (nested maps)
#   ("set", slot, value, FileParam)  write one variant slot of the selected parameter
Op = Union[tuple]


@dataclass
class ParamFileModel:
    path: str
    blocks: list[NodeBlock] = field(default_factory=list)
    diagnostics: list[Diagnostic] = field(default_factory=list)
    ops: list[tuple] = field(default_factory=list)
    ok: bool = True  # rcl would parse it (no X001/P104/P106 error)
    has_ros_parameters: bool = False
    distro: str = "humble"
    # X006 for a key repeated with a mapping as value: rcl merges the two mappings, PyYAML keeps
    # the second; reported only for files a PyYAML reader loads (engine._load_params)
    merged_keys: list[Diagnostic] = field(default_factory=list)
    # (ops, ops cut per node key): params.effective's memo, made again when ``ops`` is replaced
    op_segments: Any = field(default=None, repr=False, compare=False)
    # A file with no ros__parameters key read the way launch_ros reads it for a composable node
    # (to_parameters_list: with nothing to normalise, the whole mapping is the node's parameters,
    # nested keys joined with "."); None for any other file.
    flat: NodeBlock | None = None

    def params_named(self, name: str) -> list[tuple[NodeBlock, FileParam]]:
        return [(b, p) for b in self.blocks for p in b.params if p.name == name]


def is_param_file(model: ParamFileModel) -> bool:
    """A params file has a key starting with ``ros__parameters`` somewhere."""
    return model.has_ros_parameters


fast_pickle_module(globals())  # tuples instead of dataclasses.fields() per object (model/pickling.py)
