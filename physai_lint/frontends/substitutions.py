"""The XML/YAML substitution grammar (``$(name args...)``) turned into ``Value``s with exact spans.

Mirrors ``launch/share/launch/frontend/grammar.lark`` and ``launch/frontend/parse_substitution.py``:
arguments are separated by single spaces, an argument is either a run of unquoted parts (text and
nested substitutions) or one quoted template, and ``\\c`` stands for ``c`` in every text token. A
``$`` not followed by ``(`` is text (``\\$(`` writes a literal ``$(``). Problems become ``L007``
diagnostics and the offending substitution an ``Unknown``.
"""
from __future__ import annotations

import bisect
import difflib
import re
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any

from physai_lint.model.findings import Diagnostic
from physai_lint.model.span import Span
from physai_lint.model.values import (
    Anon,
    BoolOp,
    Command,
    Compare,
    EnvVar,
    ExecInPackage,
    FileContent,
    FindExecutable,
    FindPackage,
    IfElse,
    LaunchConfig,
    ParamRef,
    PythonExpr,
    Subst,
    Text,
    ThisFile,
    ThisFileDir,
    Unknown,
    Value,
)

# name -> (min args, max args or None for unbounded), as each upstream ``parse`` classmethod checks
# them. Where distros differ the union is accepted (this parser does not know the distro): "param"
# takes an optional default since jazzy (launch_ros ``Parameter.parse``), humble takes one argument.
ARITY: dict[str, tuple[int, int | None]] = {
    "var": (1, 2), "env": (1, 2), "find-pkg-share": (1, 1),
    "find-pkg-prefix": (1, 1), "find-exec": (1, 1), "exec-in-pkg": (2, 2), "dirname": (0, 0),
    "filename": (0, 0), "anon": (1, 1), "eval": (1, 2), "command": (1, 2), "not": (1, 1),
    "and": (2, 2), "or": (2, 2), "any": (1, None), "all": (1, None), "equals": (2, 2),
    "not-equals": (2, 2), "if": (2, 3), "param": (1, 2), "file-content": (1, 1),
    "log_dir": (0, 0), "launch_log_dir": (0, 0),
}
SUBSTITUTION_NAMES: tuple[str, ...] = tuple(sorted(ARITY))
# roslaunch (ROS 1) substitutions that ROS 2 launch does not expose (it fails with "Unknown
# substitution"), with what replaces them.
ROS1_SUBSTITUTIONS: dict[str, str] = {
    "optenv": "$(env NAME DEFAULT)", "arg": "$(var NAME)", "find": "$(find-pkg-share PKG)",
}
# Substitutions missing from humble's expose registry: name -> first distro that has them.
# launch_log_dir came with iron (launch #652, ``LaunchLogDir``); humble has only ``log_dir``.
DISTRO_ONLY_SUBSTITUTIONS: dict[str, str] = {
    "any": "iron", "all": "iron", "equals": "iron", "not-equals": "iron", "if": "iron",
    "file-content": "iron", "launch_log_dir": "iron",
}
# What ``$(launch_log_dir)`` becomes (the directory is only known at run time).
LAUNCH_LOG_DIR_REASON = "launch log directory ($(launch_log_dir))"

_ESCAPE = re.compile(r"\\(.)")
_IDENT = re.compile(r"[A-Za-z][A-Za-z0-9_-]*")
Positions = Sequence[tuple[int, int]]


class _SyntaxError(Exception):
    def __init__(self, message: str, pos: int) -> None:
        super().__init__(message)
        self.message = message
        self.pos = pos


@dataclass
class _Ctx:
    text: str
    pos: Sequence[tuple[int, int]]
    file: str
    diags: list[Diagnostic]

    def span(self, start: int, end: int) -> Span:
        last = len(self.pos) - 1  # an error at the very end ("$(" closing a value) points past it
        start, end = min(start, last), min(end, last)
        (l1, c1), (l2, c2) = self.pos[start], self.pos[max(end, start)]
        if end <= start:
            return Span(self.file, l1, c1, l1, c1 + 1)
        return Span(self.file, l1, c1, l2, c2)


class positions_from(Sequence[tuple[int, int]]):  # used like the function it was
    """(line, col) of every character of ``text`` (and one past the end), starting at line:col.

    Computed on access from the line starts: a whole parameter file parsed for ``$(...)`` asks for
    a handful of positions out of tens of thousands of characters."""

    def __init__(self, text: str, line: int, col: int) -> None:
        self.n = len(text) + 1
        self.line, self.col = line, col
        self.starts = [m.end() for m in re.finditer("\n", text)] if "\n" in text else []

    def __len__(self) -> int:
        return self.n

    def __getitem__(self, index: Any) -> Any:
        if isinstance(index, slice):
            return [self[i] for i in range(*index.indices(self.n))]
        if index < 0:
            index += self.n
        if not 0 <= index < self.n:
            raise IndexError(index)
        k = bisect.bisect_right(self.starts, index)
        if k == 0:
            return self.line, self.col + index
        return self.line + k, index - self.starts[k - 1] + 1


def parse_substitutions(
    text: str, span: Span, positions: Positions | None = None,
) -> tuple[Value, list[Diagnostic]]:
    """Parse an attribute value; ``span`` gives where its first character is.

    ``positions`` (optional, ``len(text) + 1`` entries) maps each character to its source line/col
    when the value is not a verbatim copy of the source (XML entity references, folded YAML).
    """
    if positions is None and text and "$" not in text and "\\" not in text and "\n" not in text:
        # plain text on one line (most values): what the general path below makes of it
        return (Text(text, Span(span.file, span.line, span.col, span.line, span.col + len(text))),), []
    pos = positions if positions is not None and len(positions) == len(text) + 1 \
        else positions_from(text, span.line, span.col)
    ctx = _Ctx(text, pos, span.file, [])
    if not text:
        return (Text("", ctx.span(0, 0)),), []
    parts: list[Subst] = []
    i = 0
    seg = 0
    n = len(text)
    while i < n:
        i = text.find("$", i)
        if i < 0:
            break
        # launch's grammar (frontend/grammar.lark): a "$" not followed by "(" is text
        if not (i > 0 and text[i - 1] == "\\") and text.startswith("$(", i):
            if i > seg:
                parts.append(_text(ctx, seg, i))
            i = _top_subst(ctx, i, parts)
            seg = i
            continue
        i += 1
    if seg < n:
        parts.append(_text(ctx, seg, n))
    return tuple(parts), ctx.diags


def _text(ctx: _Ctx, start: int, end: int) -> Text:
    return Text(_ESCAPE.sub(r"\1", ctx.text[start:end]), ctx.span(start, end))


def _diag(ctx: _Ctx, start: int, end: int, message: str, help: str | None, key: str) -> Diagnostic:
    return Diagnostic("L007", ctx.span(start, end), message, help, key=key)


def _top_subst(ctx: _Ctx, start: int, parts: list[Subst]) -> int:
    try:
        subst, end = _subst(ctx, start, "u")
    except _SyntaxError as err:
        end = _recover(ctx.text, start)
        raw = ctx.text[start:end]
        ctx.diags.append(_diag(ctx, err.pos, err.pos + 1,
                               f'malformed substitution "{raw}": {err.message}',
                               "substitutions are written $(name arg1 arg2); separate arguments "
                               "with single spaces and quote arguments containing spaces", raw))
        parts.append(Unknown(f"malformed substitution {raw!r}", ctx.span(start, end)))
        return end
    parts.append(subst)
    return end


def _recover(text: str, start: int) -> int:
    depth = 0
    for j in range(start, len(text)):
        if text[j] == "(" and (j == 0 or text[j - 1] != "\\"):
            depth += 1
        elif text[j] == ")" and text[j - 1] != "\\":
            depth -= 1
            if depth == 0:
                return j + 1
    return len(text)


# Characters that end an unquoted argument part in each context: "u" unquoted, "s" inside a
# single-quoted template, "d" inside a double-quoted one.
_STOP = {"u": " '\"()", "s": " '()", "d": ' "()'}


def _subst(ctx: _Ctx, start: int, qctx: str) -> tuple[Subst, int]:
    text = ctx.text
    m = _IDENT.match(text, start + 2)
    if m is None:
        raise _SyntaxError('expected a substitution name after "$("', start + 2)
    name = m.group(0)
    i = m.end()
    args: list[tuple[Value, int, int]] = []
    if i < len(text) and text[i] == " ":
        while True:
            i += 1
            astart = i
            value, i = _arg(ctx, i, qctx)
            args.append((value, astart, i))
            if i < len(text) and text[i] == " ":
                continue
            break
    if i >= len(text):
        raise _SyntaxError('unbalanced "$(": missing ")"', start)
    if text[i] != ")":
        raise _SyntaxError(f'unexpected "{text[i]}"', i)
    end = i + 1
    return _build(ctx, name, [a[0] for a in args], start, end), end


def _arg(ctx: _Ctx, i: int, qctx: str) -> tuple[Value, int]:
    text = ctx.text
    if i < len(text) and qctx == "u" and text[i] in "'\"":
        return _quoted(ctx, i)
    parts: list[Subst] = []
    stop = _STOP[qctx]
    seg = i
    while i < len(text):
        ch = text[i]
        if ch == "\\" and i + 1 < len(text) and text[i + 1] in "()$\"'\\":
            i += 2
            continue
        if ch == "$" and text.startswith("$(", i):
            if i > seg:
                parts.append(_text(ctx, seg, i))
            sub, i = _subst(ctx, i, qctx)
            parts.append(sub)
            seg = i
            continue
        if ch in stop:
            break
        i += 1
    if i > seg:
        parts.append(_text(ctx, seg, i))
    if not parts:
        found = f'"{text[i]}"' if i < len(text) else "end of value"
        raise _SyntaxError(f"expected an argument, found {found}", i)
    return tuple(parts), i


def _quoted(ctx: _Ctx, i: int) -> tuple[Value, int]:
    text = ctx.text
    quote = text[i]
    inner = "s" if quote == "'" else "d"
    i += 1
    seg = i
    parts: list[Subst] = []
    while i < len(text):
        ch = text[i]
        if ch == "\\" and i + 1 < len(text):
            i += 2
            continue
        if ch == "$" and text.startswith("$(", i):
            if i > seg:
                parts.append(_text(ctx, seg, i))
            sub, i = _subst(ctx, i, inner)
            parts.append(sub)
            seg = i
            continue
        if ch == quote:
            if i > seg:
                parts.append(_text(ctx, seg, i))
            if not parts:
                parts.append(Text("", ctx.span(i, i)))
            return tuple(parts), i + 1
        i += 1
    raise _SyntaxError(f"unterminated quote {quote}", seg - 1)


def _literal(value: Value) -> str | None:
    if all(isinstance(p, Text) for p in value):
        return "".join(p.text for p in value if isinstance(p, Text))
    return None


def _build(ctx: _Ctx, name: str, args: list[Value], start: int, end: int) -> Subst:
    span = ctx.span(start, end)
    raw = ctx.text[start:end]
    arity = ARITY.get(name)
    if arity is None:
        close = difflib.get_close_matches(name, SUBSTITUTION_NAMES, n=1)
        hint = f'did you mean "{close[0]}"? ' if close else ""
        if name in ROS1_SUBSTITUTIONS:
            hint = f"$({name} ...) is ROS 1 roslaunch; in ROS 2 write {ROS1_SUBSTITUTIONS[name]}. "
        ctx.diags.append(_diag(ctx, start, end, f'unknown substitution "{raw}"',
                               hint + "valid substitutions: " + ", ".join(SUBSTITUTION_NAMES),
                               name))
        return Unknown(f"unknown substitution {name!r}", span)
    low, high = arity
    if len(args) < low or (high is not None and len(args) > high):
        expect = (f"{low}" if low == high else f"{low} or {high}" if high is not None
                  else f"at least {low}")
        plural = "argument" if expect == "1" else "arguments"
        ctx.diags.append(_diag(
            ctx, start, end,
            f'substitution "{name}" expects {expect} {plural}, got {len(args)} in "{raw}"',
            "arguments are separated by spaces; quote an argument that contains spaces, "
            "e.g. $(eval '1 + 2')", name))
        return Unknown(f"wrong number of arguments to {name!r}", span)
    return _BUILDERS[name](args, span)


def _opt(args: list[Value], i: int) -> Value | None:
    return args[i] if len(args) > i else None


def _eval(args: list[Value], span: Span) -> Subst:
    modules: tuple[str, ...] = ("math",)
    if len(args) > 1:
        lit = _literal(args[1])
        if lit is None:
            return PythonExpr(args[0], None, span, args[1])  # the modules are not known
        modules = tuple(m.strip() for m in lit.split(",") if m.strip())
    return PythonExpr(args[0], modules, span)


_BUILDERS: dict[str, Callable[[list[Value], Span], Subst]] = {
    "var": lambda a, s: LaunchConfig(a[0], _opt(a, 1), s),
    "env": lambda a, s: EnvVar(a[0], _opt(a, 1), s),
    "find-pkg-share": lambda a, s: FindPackage(a[0], "share", s),
    "find-pkg-prefix": lambda a, s: FindPackage(a[0], "prefix", s),
    "find-exec": lambda a, s: FindExecutable(a[0], s),
    "exec-in-pkg": lambda a, s: ExecInPackage(a[0], a[1], s),
    "dirname": lambda a, s: ThisFileDir(s),
    "filename": lambda a, s: ThisFile(s),
    "anon": lambda a, s: Anon(a[0], s),
    "eval": _eval,
    "command": lambda a, s: Command(a[0], s),
    "not": lambda a, s: BoolOp("not", tuple(a), s),
    "and": lambda a, s: BoolOp("and", tuple(a), s),
    "or": lambda a, s: BoolOp("or", tuple(a), s),
    "any": lambda a, s: BoolOp("any", tuple(a), s),
    "all": lambda a, s: BoolOp("all", tuple(a), s),
    "equals": lambda a, s: Compare("equals", a[0], a[1], s),
    "not-equals": lambda a, s: Compare("not-equals", a[0], a[1], s),
    "if": lambda a, s: IfElse(a[0], a[1], _opt(a, 2) or (), s),  # else value defaults to ""
    "param": lambda a, s: ParamRef(a[0], s, _opt(a, 1)),
    "file-content": lambda a, s: FileContent(a[0], s),
    "log_dir": lambda a, s: Unknown("log directory ($(log_dir))", s),
    "launch_log_dir": lambda a, s: Unknown(LAUNCH_LOG_DIR_REASON, s),
}
