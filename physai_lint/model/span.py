"""Source positions. Every IR value carries one; frontends normalise them, rules never compute them."""
from __future__ import annotations

from dataclasses import dataclass

from physai_lint.model.pickling import fast_init, fast_pickle_module


@fast_init
@dataclass(frozen=True, slots=True, order=True)
class Span:
    """A region of a file: 1-based lines and columns; ``end_col`` is the column after the last character.

    ``file`` is an absolute, ``/``-separated path; reporters make it relative to the working directory.
    """

    file: str
    line: int
    col: int
    end_line: int
    end_col: int

    @staticmethod
    def point(file: str, line: int, col: int = 1, length: int = 1) -> "Span":
        return Span(file, line, col, line, col + max(length, 1))

    @staticmethod
    def whole_file(file: str) -> "Span":
        return Span(file, 1, 1, 1, 1)

    def with_file(self, file: str) -> "Span":
        return Span(file, self.line, self.col, self.end_line, self.end_col)


fast_pickle_module(globals())  # tuples instead of dataclasses.fields() per object (model/pickling.py)
