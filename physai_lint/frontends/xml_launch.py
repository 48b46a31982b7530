"""XML launch files -> IR. Read with expat, refusing any DTD (so no entity can ever be expanded).

Expat reports where each start tag begins; the positions of attribute names and values are found
by scanning the raw start tag, and XML attribute-value normalisation (entity references,
newlines -> spaces) is mirrored so every substitution keeps its exact source line and column.
"""
from __future__ import annotations

import bisect
import re
from typing import Any
from xml.parsers import expat

from physai_lint.frontends import FrontendResult
from physai_lint.frontends.markup import Attr, Element, build_launch_file
from physai_lint.model.findings import Diagnostic
from physai_lint.model.span import Span

_TAG = re.compile(r"<([^\s/>]+)")
_ATTR = re.compile(r"""\s*([^\s=/>]+)\s*=\s*(?:"([^"]*)"|'([^']*)')""", re.DOTALL)
_REF = re.compile(r"&(#x[0-9a-fA-F]+|#[0-9]+|[A-Za-z_][\w.-]*);")
_NAMED = {"lt": "<", "gt": ">", "amp": "&", "quot": '"', "apos": "'"}


class _Refused(Exception):
    def __init__(self, message: str) -> None:
        super().__init__(message)
        self.message = message


class _Lines:
    def __init__(self, path: str, text: str) -> None:
        self.path = path
        self.text = text
        self.starts = [0] + [m.end() for m in re.finditer("\n", text)]

    def lc(self, offset: int) -> tuple[int, int]:
        line = bisect.bisect_right(self.starts, offset) - 1
        return line + 1, offset - self.starts[line] + 1

    def span(self, start: int, end: int) -> Span:
        (l1, c1), (l2, c2) = self.lc(start), self.lc(max(end, start + 1))
        return Span(self.path, l1, c1, l2, c2)


def _normalise(raw: str, base: int) -> tuple[str, list[int]]:
    """Attribute-value normalisation with the source offset of every resulting character."""
    out: list[str] = []
    offs: list[int] = []
    i = 0
    while i < len(raw):
        ch = raw[i]
        if ch == "&":
            m = _REF.match(raw, i)
            if m is not None:
                ref = m.group(1)
                rep = chr(int(ref[2:], 16)) if ref.startswith("#x") else \
                    chr(int(ref[1:])) if ref.startswith("#") else _NAMED.get(ref, "")
                for r in rep:
                    out.append(r)
                    offs.append(base + i)
                i = m.end()
                continue
        if ch == "\r" and raw.startswith("\r\n", i):
            i += 1
            continue
        out.append(" " if ch in "\t\n\r" else ch)
        offs.append(base + i)
        i += 1
    return "".join(out), offs


class _Reader:
    def __init__(self, path: str, text: str) -> None:
        self.lines = _Lines(path, text)
        self.text = text
        self.data = text.encode("utf-8")
        self.ascii = len(self.data) == len(text)  # then a byte index is a character offset
        self.byte_pos = 0
        self.char_pos = 0
        self.stack: list[Element] = []
        self.root: Element | None = None

    def char_offset(self, byte_index: int) -> int:
        if self.ascii and 0 <= byte_index <= len(self.data):
            return byte_index
        if byte_index < self.byte_pos:
            self.byte_pos = self.char_pos = 0
        self.char_pos += len(self.data[self.byte_pos:byte_index].decode("utf-8", "replace"))
        self.byte_pos = byte_index
        return self.char_pos

    def start(self, parser: Any, tag: str, attrs: list[str]) -> None:
        off = self.char_offset(parser.CurrentByteIndex)
        el = Element(tag, self.lines.span(off, off + 1 + len(tag)),
                     parent=self.stack[-1].tag if self.stack else None)
        scanned = self.scan(off)
        for k in range(0, len(attrs), 2):
            name, value = attrs[k], attrs[k + 1]
            found = scanned.get(name)
            if found is None:
                el.attrs[name] = Attr(name, value, el.span, el.span)
                continue
            name_off, value_off, raw = found
            end = value_off + len(raw)
            # A verbatim value (the usual case) needs no table: its characters follow its start.
            positions = None
            if raw != value:
                norm, offs = _normalise(raw, value_off)
                if norm == value:
                    positions = [self.lines.lc(o) for o in offs] + [self.lines.lc(end)]
            el.attrs[name] = Attr(name, value, self.lines.span(name_off, name_off + len(name)),
                                  self.lines.span(value_off, end), positions)
        if self.stack:
            self.stack[-1].children.append(el)
        else:
            self.root = el
        self.stack.append(el)

    def end(self, tag: str) -> None:
        self.stack.pop()

    def scan(self, off: int) -> dict[str, tuple[int, int, str]]:
        """name -> (name offset, value offset, raw value) in the start tag at ``off``."""
        m = _TAG.match(self.text, off)
        found: dict[str, tuple[int, int, str]] = {}
        if m is None:
            return found
        i = m.end()
        while True:
            a = _ATTR.match(self.text, i)
            if a is None:
                return found
            group = 2 if a.group(2) is not None else 3
            found.setdefault(a.group(1), (a.start(1), a.start(group), a.group(group)))
            i = a.end()

    def duplicate(self, off: int) -> tuple[str, Span] | None:
        """The second occurrence of a repeated attribute in the start tag before ``off``."""
        start = self.text.rfind("<", 0, off + 1)
        m = _TAG.match(self.text, start) if start >= 0 else None
        if m is None:
            return None
        seen: set[str] = set()
        i = m.end()
        while (a := _ATTR.match(self.text, i)) is not None:
            if a.group(1) in seen:
                return a.group(1), self.lines.span(a.start(1), a.end(1))
            seen.add(a.group(1))
            i = a.end()
        return None


def _refuse(what: str) -> Any:
    def handler(*_: Any) -> Any:
        raise _Refused(f"{what} is not allowed in a launch file")
    return handler


_HANDLERS = ("StartDoctypeDeclHandler", "EntityDeclHandler", "UnparsedEntityDeclHandler",
             "ExternalEntityRefHandler", "StartElementHandler", "EndElementHandler")


def parse_xml_launch(path: str, text: str) -> FrontendResult:
    """Parse an XML launch file; malformed XML or any DTD gives X001 and no IR."""
    reader = _Reader(path, text)
    parser = expat.ParserCreate(encoding="utf-8")
    parser.ordered_attributes = True
    parser.SetParamEntityParsing(expat.XML_PARAM_ENTITY_PARSING_NEVER)
    parser.StartDoctypeDeclHandler = _refuse("a DOCTYPE declaration")
    parser.EntityDeclHandler = _refuse("an entity declaration")
    parser.UnparsedEntityDeclHandler = _refuse("an entity declaration")
    parser.ExternalEntityRefHandler = _refuse("an external entity")
    parser.StartElementHandler = lambda tag, attrs: reader.start(parser, tag, attrs)
    parser.EndElementHandler = reader.end
    try:
        parser.Parse(reader.data, True)
    except _Refused as err:
        off = reader.char_offset(parser.CurrentByteIndex)
        return FrontendResult(None, [Diagnostic("X001", reader.lines.span(off, off + 1),
                                                err.message, "remove the DOCTYPE/entity "
                                                "declarations; launch files do not need them",
                                                key="dtd")])
    except expat.ExpatError as err:
        return FrontendResult(None, [_expat_error(reader, err)])
    finally:
        # The start handler refers to the parser: without this, the parser, the reader and the
        # whole element tree are a reference cycle that only the cyclic collector frees.
        for handler in _HANDLERS:
            setattr(parser, handler, None)
    root = reader.root
    if root is None or root.tag != "launch":
        tag = root.tag if root is not None else ""
        span = root.span if root is not None else Span.whole_file(path)
        return FrontendResult(None, [Diagnostic(
            "X001", span, f'root element is "<{tag}>", expected "<launch>"',
            "wrap the actions in <launch> ... </launch>", key="root")])
    launch, diags = build_launch_file(path, "xml", root)
    return FrontendResult(launch, diags)


def _expat_error(reader: _Reader, err: expat.ExpatError) -> Diagnostic:
    line = err.lineno
    line_start = reader.lines.starts[min(line, len(reader.lines.starts)) - 1]
    line_text = reader.text[line_start:].split("\n", 1)[0]
    col = len(line_text.encode("utf-8")[:err.offset].decode("utf-8", "ignore")) + 1
    if err.code == expat.errors.codes[expat.errors.XML_ERROR_DUPLICATE_ATTRIBUTE]:
        dup = reader.duplicate(line_start + col - 1)
        if dup is not None:
            return Diagnostic("X006", dup[1], f'duplicate attribute "{dup[0]}"',
                              "give each attribute once", key=dup[0])
    message = expat.errors.messages[err.code] if err.code else str(err)
    span = Span(reader.lines.path, line, col, line, col + 1)
    return Diagnostic("X001", span, f"malformed XML: {message}", None, key=message)
