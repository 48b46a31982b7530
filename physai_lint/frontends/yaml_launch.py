"""YAML launch files -> IR, read with ``yaml.compose`` (libyaml when available) for positions.

Only the node graph is built, never Python objects for the whole document. Anchors, aliases and
merge keys (``<<: *base``) are followed as launch's ``yaml.safe_load`` does, within a budget of
node visits: an alias bomb exceeds it and gives X001 instead of expanding. Duplicate mapping keys
give X006 (the last wins, as with ``yaml.safe_load``).
"""
from __future__ import annotations

import bisect
import re
from typing import Any

import yaml

from physai_lint.frontends import FrontendResult
from physai_lint.frontends.markup import Attr, Element, build_launch_file
from physai_lint.frontends.tags import ACCEPTED
from physai_lint.model.findings import Diagnostic
from physai_lint.model.span import Span

_Loader: Any = getattr(yaml, "CSafeLoader", yaml.SafeLoader)
_STR = "tag:yaml.org,2002:str"


_MERGE = "tag:yaml.org,2002:merge"
# Node visits one launch file may take with its aliases expanded: thousands for a large real file,
# billions for an alias bomb.
MAX_VISITS = 200_000


class _Alias(Exception):
    """Aliases expand the document past ``MAX_VISITS``."""

    def __init__(self, node: yaml.Node) -> None:
        super().__init__("alias")
        self.node = node


class _Reader:
    def __init__(self, path: str, text: str) -> None:
        self.path = path
        self.text = text
        self.starts = [0] + [m.end() for m in re.finditer("\n", text)]
        self.visits = 0
        self.duplicates: set[tuple[int, str]] = set()
        self.diags: list[Diagnostic] = []

    def offset(self, mark: Any) -> int:
        return self.starts[min(mark.line, len(self.starts) - 1)] + mark.column

    def lc(self, offset: int) -> tuple[int, int]:
        line = bisect.bisect_right(self.starts, offset) - 1
        return line + 1, offset - self.starts[line] + 1

    def span(self, node: yaml.Node) -> Span:
        return Span(self.path, node.start_mark.line + 1, node.start_mark.column + 1,
                    node.end_mark.line + 1, node.end_mark.column + 1)

    def visit(self, node: yaml.Node) -> None:
        self.visits += 1
        if self.visits > MAX_VISITS:
            raise _Alias(node)

    def merged(self, value: yaml.Node) -> list[tuple[yaml.ScalarNode, yaml.Node]]:
        """The pairs a merge key (``<<: *base`` / ``<<: [*a, *b]``) brings, as SafeConstructor's
        ``flatten_mapping`` does: earlier mappings of a list win over later ones."""
        sources = value.value if isinstance(value, yaml.SequenceNode) else [value]
        out: list[tuple[yaml.ScalarNode, yaml.Node]] = []
        taken: set[str] = set()
        for src in sources:
            if not isinstance(src, yaml.MappingNode):
                continue
            for k, v in self.pairs(src, report=False):
                name = str(k.value)
                if name not in taken:
                    taken.add(name)
                    out.append((k, v))
        return out

    def pairs(self, node: yaml.MappingNode, report: bool = True) -> list[tuple[yaml.ScalarNode, yaml.Node]]:
        """Key/value pairs with duplicates reported (X006) and dropped, the last one kept; merged
        pairs come first, so the mapping's own keys override them."""
        self.visit(node)
        last: dict[str, int] = {}
        items: list[tuple[yaml.ScalarNode, yaml.Node]] = []
        own = []
        for key, value in node.value:
            if isinstance(key, yaml.ScalarNode) and key.tag == _MERGE:
                for k, v in self.merged(value):
                    last[str(k.value)] = len(items)
                    items.append((k, v))
            else:
                own.append((key, value))
        merged = set(last)
        for key, value in own:
            self.visit(key)
            name = str(key.value) if isinstance(key, yaml.ScalarNode) else ""
            if name in merged:
                merged.discard(name)
                items[last[name]] = (key, value)
            elif name in last:
                if report and (key.start_mark.index, name) not in self.duplicates:  # once, however often aliased
                    self.duplicates.add((key.start_mark.index, name))
                    self.diags.append(Diagnostic("X006", self.span(key), f'duplicate key "{name}"',
                                                 "give each key once; the last one wins", key=name))
                items[last[name]] = (key, value)
            else:
                last[name] = len(items)
                items.append((key, value))
        return items

    # ---- elements -----------------------------------------------------------------------------
    def element(self, tag: str, key: yaml.Node, body: yaml.Node, parent: str | None) -> Element:
        kspan = self.span(key)
        el = Element(tag, Span(self.path, kspan.line, kspan.col, kspan.line,
                               kspan.col + len(tag)), parent=parent)
        if isinstance(body, yaml.MappingNode):
            for k, v in self.pairs(body):
                self.member(el, k, v)
        elif isinstance(body, yaml.SequenceNode):
            # launch_yaml Entity.children: a list body *is* the children ("- group: [- node: ...]")
            el.children.extend(self.entities(body, tag))
        else:
            self.visit(body)
        return el

    def entities(self, seq: yaml.SequenceNode, parent: str) -> list[Element]:
        """A list of one-key mappings ``- tag: {...}`` (``launch:`` and ``children:``)."""
        self.visit(seq)
        out: list[Element] = []
        for item in seq.value:
            if isinstance(item, yaml.MappingNode):
                for k, v in self.pairs(item):
                    out.append(self.element(str(k.value), k, v, parent))
            else:
                self.visit(item)
        return out

    def member(self, el: Element, key: yaml.ScalarNode, value: yaml.Node) -> None:
        name = str(key.value)
        if isinstance(value, yaml.SequenceNode) and name == "children":
            el.children.extend(self.entities(value, el.tag))
        elif isinstance(value, yaml.SequenceNode) and value.value and all(
                isinstance(v, yaml.MappingNode) for v in value.value):
            self.visit(value)
            spec = ACCEPTED.get(el.tag)
            if spec is not None and spec.children is not None and name not in spec.children:
                # a key the element does not take ("parameters:" for "param:"): launch rejects the
                # key, reported once there, whatever its items hold
                el.children.append(self.element(name, key, value.value[0], el.tag))
            else:
                el.children.extend(self.element(name, item, item, el.tag) for item in value.value)
        elif isinstance(value, yaml.MappingNode):
            child = self.element(name, value, value, el.tag)
            child.single = True
            el.children.append(child)
        else:
            el.attrs[name] = self.attr(name, key, value)

    def attr(self, name: str, key: yaml.Node, value: yaml.Node) -> Attr:
        self.visit(value)
        if isinstance(value, yaml.SequenceNode):
            items = tuple(self.attr(name, key, v) for v in value.value)
            return Attr(name, "", self.span(key), self.span(value), typed=tuple(
                i.typed if not i.is_str else i.text for i in items), is_str=False, items=items)
        if not isinstance(value, yaml.ScalarNode):
            return Attr(name, "", self.span(key), self.span(value), is_str=False)
        text = str(value.value)
        is_str = value.tag == _STR
        typed: Any = None
        if not is_str:
            typed = _construct(value)
        quoted = value.style in ("'", '"')
        start = self.offset(value.start_mark) + (1 if quoted else 0)
        end = self.offset(value.end_mark) - (1 if quoted else 0)
        # A verbatim value (plain, or quoted without escapes or folding) needs no table: its
        # characters follow its start, as parse_substitutions assumes when given none.
        positions = None if self.text[start:end] == text else self.positions(text, start, end)
        vspan = self.span(value)
        if quoted:
            (l1, c1), (l2, c2) = self.lc(start), self.lc(max(end, start))
            vspan = Span(self.path, l1, c1, l2, c2)
        return Attr(name, text, self.span(key), vspan, positions, is_str, typed)

    def positions(self, value: str, start: int, end: int) -> list[tuple[int, int]]:
        """Align the scalar's characters with the source (folding and escapes move them)."""
        offs: list[int] = []
        j = start
        src = self.text
        end = min(end, len(src))  # libyaml's marks can run past the text it was given (fuzzer)
        for ch in value:
            if j < len(src) and src[j] == ch:
                offs.append(j)
                j += 1
                continue
            k = src.find(ch, j, min(end, j + 256)) if ch not in " \n" else -1
            if k >= 0:
                offs.append(k)
                j = k + 1
            else:
                offs.append(min(j, max(end - 1, start)))
                while j < end and src[j] in " \t\r\n" and ch in " \n":
                    j += 1
        return [self.lc(o) for o in offs] + [self.lc(j)]


def _construct(node: yaml.ScalarNode) -> Any:
    """The Python value of one non-string scalar (bool, int, float, null)."""
    from physai_lint.params.typing import safe_constructor

    try:
        return safe_constructor().construct_object(node, deep=False)
    except (yaml.YAMLError, ValueError, OverflowError):
        return None


def parse_yaml_launch(path: str, text: str) -> FrontendResult:
    """Parse a YAML launch file; a syntax error, an alias or a non-``launch:`` root gives X001."""
    try:
        root = yaml.compose(text, Loader=_Loader)
    except yaml.MarkedYAMLError as err:
        from physai_lint.params.loader import error_mark

        mark = error_mark(err)
        line, col = (mark.line + 1, mark.column + 1) if mark is not None else (1, 1)
        return FrontendResult(None, [Diagnostic(
            "X001", Span(path, line, col, line, col + 1),
            f"malformed YAML: {err.problem or err.context}", None, key=str(err.problem))])
    except yaml.YAMLError as err:
        return FrontendResult(None, [Diagnostic("X001", Span.whole_file(path),
                                                f"malformed YAML: {err}", None, key="yaml")])
    reader = _Reader(path, text)
    pairs = reader.pairs(root) if isinstance(root, yaml.MappingNode) else []
    if len(pairs) != 1 or str(pairs[0][0].value) != "launch":
        span = reader.span(root) if root is not None else Span.whole_file(path)
        return FrontendResult(None, [*reader.diags, Diagnostic(
            "X001", span, 'a YAML launch file must be one mapping with the key "launch"',
            "start the file with \"launch:\" followed by a list of actions", key="root")])
    body = pairs[0][1]
    # launch_yaml Entity.children: a list, or a mapping with a "children" list (entity.py)
    if isinstance(body, yaml.ScalarNode) or isinstance(body, yaml.MappingNode) and not any(
            isinstance(k, yaml.ScalarNode) and k.value == "children" for k, _ in body.value):
        kspan = reader.span(pairs[0][0])
        what, error = ("a mapping", "ValueError \"Expected entity `launch` to have children entities\"") \
            if isinstance(body, yaml.MappingNode) else \
            (f'the {"empty value" if not body.value else "scalar " + repr(body.value)}',
             "an error (launch_yaml has no entities to read)")
        return FrontendResult(None, [*reader.diags, Diagnostic(
            "L010", Span(path, kspan.line, kspan.col, kspan.line, kspan.col + len("launch")),
            f'"launch" holds {what}, not a list of actions; launch_yaml fails loading the file with {error}',
            'make each action a list item: "- node:", "- arg:" under "launch:"', key="launch")])
    try:
        tree = reader.element("launch", pairs[0][0], body, None)
    except _Alias as alias:
        return FrontendResult(None, [Diagnostic(
            "X001", reader.span(alias.node), f"YAML aliases expand this launch file past "
            f"{MAX_VISITS} nodes (an alias bomb?); it was not read", "write the repeated parts "
            "out, or reuse fewer nested anchors", key="alias")])
    launch, diags = build_launch_file(path, "yaml", tree)
    return FrontendResult(launch, reader.diags + diags)
