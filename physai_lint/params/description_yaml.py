"""Whether a robot description that a ``Command`` prints survives launch's YAML typing.

A parameter given ``Command(['xacro ', file])`` without ``ParameterValue(..., value_type=str)`` is
typed by ``yaml.safe_load`` of the command's output (launch_ros ``evaluate_parameter_dict``). A
URDF is one long plain YAML scalar for PyYAML, so it loads as the text (newlines folded into
spaces) unless some line holds what a plain scalar cannot: ``": "`` or a ``:`` ending the line
(a mapping), ``" #"`` (a comment: the description is cut there, and what follows fails to parse),
or a tab starting a line. Nothing is run here: the output is predicted from the file's text.

``cat FILE`` prints the file as it is. ``xacro FILE`` prints the document again with minidom's
``toprettyxml``: elements are re-indented with spaces, and what it copies verbatim is the text of
comments, of text nodes and of attribute values (xacro ``__init__.py``: ``eval_all``,
``remove_previous_comments``, ``process_file``). Only what certainly reaches the output is looked
at: nothing inside a ``xacro:`` element (a macro's body is printed only where it is called, an
``if`` only when it holds, an include's file is another file), no comment that xacro drops (the
comments right before a ``xacro:`` element), no text with a ``$`` (xacro substitutes it), and no
file that asks for ``xacro:eval-comments``.
"""
from __future__ import annotations

import posixpath
import re
import shlex
from dataclasses import dataclass
from typing import Any
from xml.parsers import expat

MAX_DESCRIPTION = 2_000_000  # bytes of a description file looked at

_MAPPING = re.compile(r":(?:[ \t]|$)")
_COMMENT = re.compile(r"(?:^|[ \t])#")


@dataclass(frozen=True)
class Breakage:
    """Why the printed description is no YAML scalar: ``line`` of ``path`` (1-based), the
    ``snippet`` of that line, and ``what`` YAML makes of it."""

    path: str
    line: int
    snippet: str
    what: str


def printed_file(command: str) -> tuple[str, str] | None:
    """(program, file) of a command line that prints a description file: ``xacro FILE ...``
    (arguments ``name:=value`` and options aside) or ``cat FILE``; None otherwise."""
    try:
        argv = shlex.split(command)
    except ValueError:
        return None
    if not argv:
        return None
    program = posixpath.basename(argv[0])
    if program in ("xacro", "xacro.py"):
        files = [a for a in argv[1:] if not a.startswith("-") and ":=" not in a]
        return ("xacro", files[0]) if files else None
    if program == "cat" and len(argv) == 2 and not argv[1].startswith("-"):
        return "cat", argv[1]
    return None


def _line_problem(line: str, first: bool) -> str | None:
    if _MAPPING.search(line):
        return '": " (or a ":" ending the line) makes YAML read a mapping'
    if _COMMENT.search(line):
        return '" #" starts a YAML comment, which cuts the description there'
    if not first and line.startswith("\t"):
        return "a line starting with a tab cannot continue a YAML plain scalar"
    return None


def _verbatim_problem(path: str, start_line: int, text: str) -> Breakage | None:
    """The first line of ``text`` (printed verbatim from ``start_line`` on) that breaks."""
    for i, line in enumerate(text.split("\n")):
        what = _line_problem(line, i == 0)
        if what is not None:
            return Breakage(path, start_line + i, line.strip()[:120], what)
    return None


class _Node:
    __slots__ = ("tag", "line", "attrs", "children")

    def __init__(self, tag: str, line: int, attrs: list[str]) -> None:
        self.tag, self.line, self.attrs = tag, line, attrs
        self.children: list[Any] = []  # _Node, ("text", str, line) or ("comment", str, line)


def _refuse(*_: Any) -> Any:
    raise ValueError("a DTD is not read")


def _tree(text: str) -> _Node | None:
    """The document as nested nodes (expat; no DTD, so no entity is expanded), or None."""
    root = _Node("", 1, [])
    stack = [root]
    parser = expat.ParserCreate()
    parser.ordered_attributes = True
    parser.SetParamEntityParsing(expat.XML_PARAM_ENTITY_PARSING_NEVER)
    parser.StartDoctypeDeclHandler = _refuse
    parser.EntityDeclHandler = _refuse
    parser.ExternalEntityRefHandler = _refuse

    def start(tag: str, attrs: list[str]) -> None:
        node = _Node(tag, parser.CurrentLineNumber, attrs)
        stack[-1].children.append(node)
        stack.append(node)

    def end(_tag: str) -> None:
        stack.pop()

    def chars(data: str) -> None:
        kids = stack[-1].children
        if kids and isinstance(kids[-1], tuple) and kids[-1][0] == "text":
            kids[-1] = ("text", kids[-1][1] + data, kids[-1][2])
        else:
            kids.append(("text", data, parser.CurrentLineNumber))

    def comment(data: str) -> None:
        stack[-1].children.append(("comment", data, parser.CurrentLineNumber))

    parser.StartElementHandler = start
    parser.EndElementHandler = end
    parser.CharacterDataHandler = chars
    parser.CommentHandler = comment
    try:
        parser.Parse(text, True)
    except (expat.ExpatError, ValueError, RecursionError):
        return None
    return root


def _dropped(children: list[Any]) -> set[int]:
    """Indexes of the comments xacro's ``remove_previous_comments`` drops: those right before a
    ``xacro:`` element, apart from a whitespace text of at most one newline between them."""
    out: set[int] = set()
    for j, child in enumerate(children):
        if not (isinstance(child, _Node) and child.tag.startswith("xacro:")):
            continue
        k = j - 1
        while k >= 0:
            prev = children[k]
            if isinstance(prev, tuple) and prev[0] == "text" and prev[1].isspace() and prev[1].count("\n") <= 1:
                k -= 1
                if k < 0:
                    break
                prev = children[k]
            if isinstance(prev, tuple) and prev[0] == "comment":
                out.add(k)
                k -= 1
            else:
                break
    return out


def _xacro_problem(path: str, node: _Node) -> Breakage | None:
    dropped = _dropped(node.children)
    for i, child in enumerate(node.children):
        if isinstance(child, _Node):
            if child.tag.startswith("xacro:"):
                continue
            for value in child.attrs[1::2]:
                if "$" not in value and "\n" not in value:
                    what = _line_problem('"' + value + '"', False)  # printed between quotes
                    if what is not None:
                        return Breakage(path, child.line, value.strip()[:120], what)
            found = _xacro_problem(path, child)
            if found is not None:
                return found
        elif child[0] == "comment" and i not in dropped:
            # minidom writes "<!--" + data + "-->" after the indentation; the data's lines verbatim
            found = _verbatim_problem(path, child[2], "<!--" + child[1] + "-->")  # from its first line
            if found is not None:
                return found
        elif child[0] == "text" and child[1].strip() and "$" not in child[1]:
            body = child[1].strip("\n")
            # after ">" (alone in its element) or the indentation, before the closing tag or the
            # next node's indentation: its first line is taken as following ">" (no comment
            # there), its last as never ending a line
            found = _verbatim_problem(path, child[2] + len(child[1]) - len(child[1].lstrip("\n")),
                                      ">" + body.lstrip(" ") + "<")
            if found is not None:
                return found
    return None


def description_breakage(program: str, path: str, text: str) -> Breakage | None:
    """Where the description ``program`` (``xacro`` or ``cat``) prints from ``path``, whose text is
    ``text``, stops being a YAML scalar for launch; None when it does not, or is not known."""
    if len(text) > MAX_DESCRIPTION or "\0" in text:
        return None
    if program == "cat":
        return _verbatim_problem(path, 1, text.rstrip("\n"))
    if "xacro:eval-comments" in text:
        return None
    root = _tree(text)
    try:
        return None if root is None else _xacro_problem(path, root)
    except RecursionError:  # nested deeper than the interpreter's stack: not worked out
        return None
