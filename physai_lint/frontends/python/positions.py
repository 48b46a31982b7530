"""Spans from stdlib ``ast`` positions.

``ast`` gives 1-based lines and 0-based *UTF-8 byte* columns; IR spans use 1-based character
columns with an exclusive end. ASCII lines (the common case) need no conversion.
"""
from __future__ import annotations

import ast

from physai_lint.model.span import Span


class SpanMaker:
    def __init__(self, path: str, text: str) -> None:
        self.path = path
        self._lines = text.splitlines()
        self._ascii = [line.isascii() for line in self._lines]
        # Helpers and loop bodies evaluate the same nodes many times: one Span per node.
        self._spans: dict[int, tuple[ast.AST, Span]] = {}

    def _col(self, line: int, byte_col: int) -> int:
        idx = line - 1
        if 0 <= idx < len(self._lines) and not self._ascii[idx]:
            raw = self._lines[idx].encode("utf-8")[:byte_col]
            return len(raw.decode("utf-8", errors="replace")) + 1
        return byte_col + 1

    def of(self, node: ast.AST) -> Span:
        hit = self._spans.get(id(node))
        if hit is not None and hit[0] is node:
            return hit[1]
        span = self._make(node)
        self._spans[id(node)] = (node, span)
        return span

    def _make(self, node: ast.AST) -> Span:
        line = getattr(node, "lineno", 1)
        col = getattr(node, "col_offset", 0)
        end_line = getattr(node, "end_lineno", None) or line
        end_col = getattr(node, "end_col_offset", None)
        if end_col is None:
            end_col = col + 1
        return Span(self.path, line, self._col(line, col), end_line, self._col(end_line, end_col))

    def keyword(self, kw: ast.keyword) -> Span:
        """The span of a keyword argument's name token (``package`` in ``package='x'``)."""
        line = kw.lineno
        start = self._col(line, kw.col_offset)
        return Span(self.path, line, start, line, start + len(kw.arg or "**"))

    def point(self, line: int, col: int, length: int = 1) -> Span:
        return Span.point(self.path, line, col, length)
