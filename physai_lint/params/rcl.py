"""A Python mirror of ``rcl_params_t``: node keys and parameter entries in first-insertion order,
each entry a variant with one slot per type (``rcl_variant_t``).

Files are merged by replaying their ops (see ``model.py``) into one ``RclParams``: ``find_node`` /
``find_parameter`` keep the first insertion position, a later write overwrites its own slot in
place, and the reader takes the first non-empty slot in ``SLOT_ORDER`` (rclcpp
``parameter_value_from``), so ``x: 5`` then ``x: "text"`` still reads 5.
"""
from __future__ import annotations

from bisect import insort
from dataclasses import dataclass, field
from typing import Any

from physai_lint.model.span import Span

from .model import SLOT_ORDER, FileParam


@dataclass
class Write:
    slot: str
    value: Any
    param: FileParam | None
    source: str  # human description of where it came from
    span: Span | None
    unknown: bool = False  # the value cannot be known statically


@dataclass
class RclEntry:
    name: str
    slots: dict[str, Write] = field(default_factory=dict)
    writes: list[Write] = field(default_factory=list)
    created_by: FileParam | None = None
    created_source: str = ""

    def read(self) -> Write | None:
        """The write rclcpp reads: the first non-NULL slot in bool > int > ... > string[] order."""
        for slot in SLOT_ORDER:
            if slot in self.slots:
                return self.slots[slot]
        if "unknown" in self.slots:
            return self.slots["unknown"]
        return None


@dataclass
class RclNodeKey:
    key: str
    entries: list[RclEntry] = field(default_factory=list)
    spans: list[tuple[Span, str]] = field(default_factory=list)  # where the key was written
    # name -> ascending positions in ``entries`` (a rename can give two entries one name; rcl's
    # linear search finds the first): find_parameter without scanning every entry
    positions: dict[str, list[int]] = field(default_factory=dict, repr=False, compare=False)


class RclParams:
    def __init__(self) -> None:
        self.nodes: dict[str, RclNodeKey] = {}
        self._node: RclNodeKey | None = None
        self._idx: int | None = None

    # -- rcl primitives ---------------------------------------------------------------------------
    def find_node(self, key: str, span: Span | None = None, source: str = "") -> None:
        node = self.nodes.get(key)
        if node is None:
            node = self.nodes[key] = RclNodeKey(key)
        if span is not None:
            node.spans.append((span, source))
        self._node = node
        self._idx = None

    def find_parameter(self, name: str, param: FileParam | None = None, source: str = "") -> None:
        node = self._node
        if node is None:
            return
        found = node.positions.get(name)
        if found:
            self._idx = found[0]
            return
        self._idx = len(node.entries)
        node.entries.append(RclEntry(name, created_by=param, created_source=source))
        node.positions[name] = [self._idx]

    def current(self) -> RclEntry | None:
        if self._node is None or self._idx is None:
            return None
        return self._node.entries[self._idx]

    def rename(self, new_name: str) -> None:
        entry = self.current()
        if entry is None or self._node is None or self._idx is None:
            return
        positions = self._node.positions
        old = positions[entry.name]
        old.remove(self._idx)
        if not old:
            del positions[entry.name]
        insort(positions.setdefault(new_name, []), self._idx)
        entry.name = new_name

    def set(self, slot: str, value: Any, param: FileParam | None, source: str,
            span: Span | None = None, unknown: bool = False) -> None:
        entry = self.current()
        if entry is None:
            return
        w = Write(slot, value, param, source, span if span is not None else
                  (param.value_span if param is not None else None), unknown)
        if unknown:
            # Unknown value: it may land in any slot; model as shadowing everything set so far.
            entry.slots = {"unknown": w}
        else:
            entry.slots.pop("unknown", None)
            entry.slots[slot] = w
        entry.writes.append(w)

    # -- replay -----------------------------------------------------------------------------------
    def apply(self, ops: list[tuple], source: str) -> None:
        for op in ops:
            tag = op[0]
            if tag == "node":
                self.find_node(op[1], op[2] if len(op) > 2 else None, source)
            elif tag == "param":
                self.find_parameter(op[1], op[2] if len(op) > 2 else None, source)
            elif tag == "rename":
                self.rename(op[1])
            elif tag == "set":
                self.set(op[1], op[2], op[3], source, unknown=op[1] == "unknown")
