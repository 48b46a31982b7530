"""Interfaces from C++ sources: a small C++ tokenizer (comments, string/char/raw-string literals,
identifiers, ``::``), then call patterns on the token stream.

Recognised: ``create_publisher<T>("n", ...)``, ``create_subscription<T>("n", ...)``,
``create_service<T>("n", ...)``, ``create_client<T>("n", ...)``, ``rclcpp_action::create_server<T>
(node, "n", ...)`` / ``create_client``, image_transport ``create_publisher``/``create_subscription``
(node first) and ``advertise``/``subscribe``/``advertiseCamera``/``subscribeCamera``,
message_filters subscribers (``message_filters::Subscriber<T> sub_;`` constructed with a node and
a topic: ``sub_(node, "n")``, ``make_shared<...>(node, "n")``, or ``sub_.subscribe(node, "n")``;
image_transport's ``SubscriberFilter`` alike), ``declare_parameter<T>("n", default)`` / ``declare_parameter("n", default)`` and nav2's
``declare_parameter_if_not_declared(node, "n", ParameterValue(default))``; a class derived from
``rclcpp_lifecycle::LifecycleNode`` (or nav2's) marks a lifecycle node. Names are taken only from
string literals or constants the file gives one literal; an endpoint named otherwise is kept as
its kind and type (``NodeInterface.unnamed``). Each item is tagged with the class whose code holds
it (``cpp_scopes.py``): an executable linking a library runs only some of its classes
(``linked.py``).
"""
from __future__ import annotations

import bisect
import dataclasses
import functools
import re
from collections.abc import Callable
from typing import Any, NamedTuple, Protocol

from physai_lint.model.span import Span

from .cpp_scopes import (
    CppFacts,
    blank_code,
    braceless_conditional,
    conditional_blocks,
    owner_at,
    preprocessor_branches,
    scopes,
)
from .cpp_scopes import _inside as _in_skimmed
from .model import CODE_CONDITION, CODE_REMAP, Endpoint, NodeInterface, NodeSite, ParamDecl, decide_node_name

MAX_SOURCE = 2_000_000


class Tok(NamedTuple):
    """One token (a tuple: a source file makes tens of thousands of them)."""

    kind: str  # "id", "str", "num", "char", "op"
    text: str  # for "str": the decoded literal contents
    line: int
    col: int
    end_line: int
    end_col: int


_ID_START_CHARS = frozenset("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz_")
_BLANKS = re.compile(r"[ \t\r\f\v\\]+")
_ID = re.compile(r"[A-Za-z_0-9]*")
_NUM_PATTERN = (r"(?:0[xX][0-9a-fA-F']+|[0-9][0-9']*\.?[0-9']*(?:[eE][+-]?[0-9]+)?"
                r"|\.[0-9]+(?:[eE][+-]?[0-9]+)?)[uUlLfF]*")
_NUM = re.compile(_NUM_PATTERN)
_STR_PREFIX = ("u8R", "uR", "UR", "LR", "R", "u8", "u", "U", "L")
_DEFINE = re.compile(r'#\s*define\s+([A-Za-z_]\w*)\s+"((?:[^"\\]|\\.)*)"\s*$')
_RAW_DELIM = re.compile(r'"([^()\\ \t\n]{0,16})\(')

# One token per match, after any blanks (a backslash counts as one: line continuations); the
# group that matched says what it is. Identifiers that cannot start a string literal, and
# operators, come first: they are most tokens, and each alternative tried before the one that
# matches costs time (a third of the scan). Otherwise the order is the order the old loop decided
# in: a comment before "/", a string prefix before an identifier.
_SCAN = re.compile(
    r"[ \t\r\f\v\\]*(?:"
    r"([A-KM-QSTV-Za-tv-z_][A-Za-z_0-9]*)"               # 1 identifier, not u U L R...
    r"|(::|->|[!$%&()*+,\-:;<=>?@\[\]^`{|}~]"            # 2 operator ("." before a digit: 11,
    r"|\.(?![0-9\x80-\U0010ffff])|/(?![/*]))"            #   before non-ASCII: 12; "//", "/*")
    r"|(\n[\n \t\r\f\v\\]*)"                              # 3 newlines, and the blanks after them
    r"|(//[^\n]*)"                                       # 4 line comment (up to the newline)
    r"|(/\*(?:[^*]*\*+(?:[^/*][^*]*\*+)*/|[\s\S]*))"     # 5 block comment; unterminated: all
    r"|(\#)"                                             # 6 preprocessor line, or a plain "#"
    r'|((?:u8|[uUL])?R")'                                # 7 raw string
    r'|((?:u8|[uUL])?"(?:[^"\\\n]+|\\[\s\S]?)*["\n]?)'  # 8 string, ends at " or newline
    r"|('(?:[^'\\\n]+|\\[\s\S]?)*['\n]?)"                # 9 char, ends at ' or newline
    r"|([A-Za-z_][A-Za-z_0-9]*)"                         # 10 identifier
    r"|(" + _NUM_PATTERN + r")"                          # 11 number
    r"|([^ \t\r\f\v\\])"                                 # 12 anything else: non-ASCII, control
    r")")
# the token kind of the groups that need nothing but their text and position
_SIMPLE_KIND = (None, "id", "op", None, None, None, None, None, None, None, "id", "num", None)


_new = tuple.__new__  # Tok(...) without NamedTuple's Python-level __new__: a third of tokenizing


def tokenize(text: str, start: int = 0, end: int | None = None, line: int = 1,
             line_start: int = 0) -> list[Tok]:
    """Tokens of a C++ source (its first ``MAX_SOURCE`` characters), or of ``text[start:end]``
    where ``start`` is a token boundary on line ``line``, which begins at offset ``line_start``.

    One compiled regex does the common tokens; ``_step`` (the per-character loop this replaced,
    one token at a time) does the rare ones: preprocessor lines, raw strings, non-ASCII, an
    unterminated string or char at the end, and a whole source cut at ``MAX_SOURCE`` (that loop
    looked past the cut). Lines are counted as that loop counted them: a newline inside a char
    literal, or ending one, is not counted."""
    toks: list[Tok] = []
    n = len(text) if end is None else end
    if end is None and n > MAX_SOURCE:
        n, i = MAX_SOURCE, 0
        while i < n:
            i, line, line_start = _step(text, i, n, line, line_start, toks)
        return toks
    append, new, tok, simple = toks.append, _new, Tok, _SIMPLE_KIND
    finditer, count, rfind = _SCAN.finditer, text.count, text.rfind
    i = start
    while i < n:
        ls1 = line_start - 1  # col = offset - ls1
        for m in finditer(text, i, n):
            k: int = m.lastindex  # type: ignore[assignment]  # every alternative is a group
            kind = simple[k]
            if kind:  # identifier, operator, number
                t = m.group(k)
                e = m.end()
                append(new(tok, (kind, t, line, e - len(t) - ls1, line, e - ls1)))
            elif k == 3:  # newlines
                t = m.group(3)
                line += t.count("\n")
                ls1 = m.end() - len(t) + t.rfind("\n")
                line_start = ls1 + 1
            elif k == 8:  # string
                s, e = m.span(8)
                if e == n:  # maybe unterminated: the old loop knows
                    i, line, line_start = _step(text, s, n, line, line_start, toks)
                    break
                q = s if text[s] == '"' else text.index('"', s)
                body = text[q + 1:e - 1]  # without the closing quote or newline
                if "\\" in body:
                    body = _unescape(body)
                sl, sc = line, s - ls1
                nl = count("\n", s, e)
                if nl:
                    line += nl
                    line_start = rfind("\n", s, e) + 1
                    ls1 = line_start - 1
                if toks and toks[-1][0] == "str" and toks[-1][4] > 0:  # adjacent literals concatenate
                    prev = toks.pop()
                    append(new(tok, ("str", prev[1] + body, prev[2], prev[3], line, e - ls1)))
                else:
                    append(new(tok, ("str", body, sl, sc, line, e - ls1)))
            elif k == 9:  # char: a newline in it or ending it is not counted
                s, e = m.span(9)
                if e == n:  # maybe unterminated (after a lone backslash at the end the old loop
                    # stopped one past the end)
                    i, line, line_start = _step(text, s, n, line, line_start, toks)
                    break
                append(new(tok, ("char", text[s + 1:e - 1], line, s - ls1, line, e - ls1)))
            elif k == 5:  # block comment
                s, e = m.span(5)
                nl = count("\n", s, e)
                if nl:
                    line += nl
                    line_start = rfind("\n", s, e) + 1
                    ls1 = line_start - 1
            elif k != 4:  # not a line comment: "#", raw string, anything else; the old loop does them
                i, line, line_start = _step(text, m.start(k), n, line, line_start, toks)
                break
        else:
            break
    return toks


def _step(text: str, i: int, n: int, line: int, line_start: int,
          toks: list[Tok]) -> tuple[int, int, int]:
    """One token (or blanks, newline, comment, preprocessor line) from offset ``i``, exactly as
    ``tokenize``'s old character loop did: one pass of that loop's body. Returns the new
    ``i, line, line_start``."""

    def pos(k: int) -> tuple[int, int]:
        return line, k - line_start + 1

    c = text[i]
    if c == "\n":
        return i + 1, line + 1, i + 1
    if c in " \t\r\f\v\\":
        return _BLANKS.match(text, i).end(), line, line_start  # type: ignore[union-attr]
    if c == "/" and text.startswith("//", i):
        j = text.find("\n", i)
        return (n if j < 0 else j), line, line_start
    if c == "/" and text.startswith("/*", i):
        j = text.find("*/", i + 2)
        j = n if j < 0 else j + 2
        line += text.count("\n", i, j)
        k = text.rfind("\n", i, j)
        if k >= 0:
            line_start = k + 1
        return j, line, line_start
    if c == "#" and text[line_start:i].strip() == "":
        # preprocessor line: keep #define NAME "literal" as tokens, skip the rest
        k = _line_end(text, i, n)
        m = _DEFINE.match(text[i:k])
        if m:
            sl, sc = pos(i)
            toks.append(_new(Tok, ("op", "#define", sl, sc, sl, sc + 1)))
            toks.append(_new(Tok, ("id", m.group(1), sl, sc, sl, sc + 1)))
            toks.append(_new(Tok, ("str", _unescape(m.group(2)), sl, sc, sl, sc + 1)))
            toks.append(_new(Tok, ("op", ";", sl, sc, sl, sc + 1)))
        line += text.count("\n", i, k)
        kk = text.rfind("\n", i, k)
        if kk >= 0:
            line_start = kk + 1
        return k, line, line_start
    # string literals, with prefixes and raw strings
    prefix = ""
    is_id = c in _ID_START_CHARS
    if is_id and c in "uULR":
        for p in _STR_PREFIX:
            if text.startswith(p, i) and i + len(p) < n and text[i + len(p)] == '"':
                prefix = p
                break
    if c == '"' or prefix:
        start = i
        sl, sc = pos(start)
        i += len(prefix)
        if prefix.endswith("R"):
            m = _RAW_DELIM.match(text[i:i + 20])
            if not m:
                return i + 1, line, line_start
            delim = ")" + m.group(1) + '"'
            body_start = i + m.end()
            j = text.find(delim, body_start)
            j = n if j < 0 else j
            body = text[body_start:j]
            end = min(n, j + len(delim))
        else:
            j = i + 1
            buf = []
            while j < n and text[j] != '"' and text[j] != "\n":
                if text[j] == "\\" and j + 1 < n:
                    buf.append(text[j:j + 2])
                    j += 2
                    continue
                buf.append(text[j])
                j += 1
            body = _unescape("".join(buf))
            end = min(n, j + 1)
        line += text.count("\n", start, end)
        k = text.rfind("\n", start, end)
        if k >= 0:
            line_start = k + 1
        el, ec = pos(end)
        # adjacent literals concatenate
        if toks and toks[-1][0] == "str" and toks[-1][4] > 0:
            prev = toks.pop()
            toks.append(_new(Tok, ("str", prev[1] + body, prev[2], prev[3], el, ec)))
        else:
            toks.append(_new(Tok, ("str", body, sl, sc, el, ec)))
        return end, line, line_start
    if c == "'":
        j = i + 1
        while j < n and text[j] != "'" and text[j] != "\n":
            j += 2 if text[j] == "\\" else 1
        sl, sc = pos(i)
        toks.append(_new(Tok, ("char", text[i + 1:j], sl, sc, sl, sc + (j - i + 1))))
        return j + 1, line, line_start
    if is_id:
        m = _ID.match(text, i + 1)
        j = m.end() if m else i + 1
        sl, sc = pos(i)
        toks.append(_new(Tok, ("id", text[i:j], sl, sc, sl, sc + (j - i))))
        return j, line, line_start
    if c.isdigit() or (c == "." and i + 1 < n and text[i + 1].isdigit()):
        m = _NUM.match(text, i)
        j = m.end() if m and m.end() > i else i + 1
        sl, sc = pos(i)
        toks.append(_new(Tok, ("num", text[i:j], sl, sc, sl, sc + (j - i))))
        return j, line, line_start
    two = text[i:i + 2]
    sl, sc = pos(i)
    if two in ("::", "->"):
        toks.append(_new(Tok, ("op", two, sl, sc, sl, sc + 2)))
        return i + 2, line, line_start
    toks.append(_new(Tok, ("op", c, sl, sc, sl, sc + 1)))
    return i + 1, line, line_start


def _line_end(text: str, i: int, n: int) -> int:
    """The offset of the newline that ends the (preprocessor) line from ``i``: the first one no
    backslash continues, or ``n``."""
    j = i
    while True:
        k = text.find("\n", j)
        if k < 0:
            return n
        if text[k - 1:k] != "\\":
            return k
        j = k + 1


def _unescape(s: str) -> str:
    simple = {"n": "\n", "t": "\t", "\\": "\\", '"': '"', "'": "'", "0": "\0", "r": "\r"}
    out = []
    i = 0
    while i < len(s):
        if s[i] == "\\" and i + 1 < len(s):
            out.append(simple.get(s[i + 1], s[i + 1]))
            i += 2
        else:
            out.append(s[i])
            i += 1
    return "".join(out)


# ---- token-stream helpers -----------------------------------------------------------------------

_CLOSE = {"(": ")", "[": "]", "{": "}", "<": ">"}


class _Constants(Protocol):
    """A file's string constants by name (a dict, or ``_LazyConstants``)."""

    def get(self, name: str, /) -> str | None: ...


def _template_args(toks: list[Tok], i: int) -> tuple[str | None, int]:
    """``toks[i]`` is ``<``: return (joined text of the args, index after ``>``)."""
    depth = 0
    parts: list[str] = []
    j = i
    while j < len(toks) and j < i + 400:
        t = toks[j]
        if t.kind == "op" and t.text == "<":
            depth += 1
            if depth > 1:
                parts.append("<")
        elif t.kind == "op" and t.text == ">":
            depth -= 1
            if depth == 0:
                return "".join(parts), j + 1
            parts.append(">")
        elif t.kind == "op" and t.text in ("(", ")", ";", "{", "}"):
            if t.text in (";", "{", "}"):
                return None, i
            parts.append(t.text)
        else:
            if parts and t.kind == "id" and parts[-1][-1:].isalnum():
                parts.append(" ")
            parts.append(t.text)
        j += 1
    return None, i


def _call_args(toks: list[Tok], i: int, braces: bool = False
               ) -> tuple[list[list[Tok]], int] | None:
    """``toks[i]`` is ``(`` (or, with ``braces``, ``{``): the top-level comma-separated
    arguments."""
    if i >= len(toks) or not (toks[i].text == "(" or braces and toks[i].text == "{"):
        return None
    args: list[list[Tok]] = [[]]
    stack = [toks[i].text]
    j = i + 1
    while j < len(toks) and j < i + 4000:
        t = toks[j]
        if t.kind == "op" and t.text in "([{":
            stack.append(t.text)
        elif t.kind == "op" and t.text in ")]}":
            stack.pop()
            if not stack:
                if not args[-1]:
                    args.pop()
                return args, j + 1
        elif t.kind == "op" and t.text == "," and len(stack) == 1:
            args.append([])
            j += 1
            continue
        elif t.kind == "op" and t.text == ";" and "{" not in stack:
            return None  # (a ";" in braces is in a lambda's body: the call goes on)
        args[-1].append(t)
        j += 1
    return None


def _constants(toks: list[Tok]) -> dict[str, str]:
    """``NAME = "literal";`` / ``NAME[] = "literal";`` / ``NAME{"literal"}`` / ``#define``: the
    names given one literal, and nothing else, in the file (a variable set to ``"map"`` in one
    branch and to a parameter's value in another is not a constant). The last ``#define`` of a
    name wins over anything."""
    values: dict[str, set[str]] = {}
    defines: dict[str, str] = {}
    for j in [j for j, t in enumerate(toks) if t[0] == "str"]:
        if j < 2:
            continue
        k = _constant_name_at(toks, j)
        if k is None:
            continue
        if toks[j - 1].kind == "id" and toks[j - 2].text == "#define":
            defines[toks[j - 1].text] = toks[j].text
        elif _is_constant_name(toks, k):
            values.setdefault(toks[k].text, set()).add(toks[j].text)
    assigned = {t[1] for k, t in enumerate(toks) if t[0] == "id" and _assigned_otherwise(toks, k)}
    out = {name: next(iter(v)) for name, v in values.items() if len(v) == 1 and name not in assigned}
    out.update(defines)
    return out


# Calls that write a parameter's value into their last argument (rclcpp::Node::get_parameter,
# get_parameter_or; ros1-style param): a variable passed there is the parameter's value.
_OUT_PARAM_CALLS = frozenset({"get_parameter", "get_parameter_or", "param"})
# (the same, read backwards from a name in the text: ``get_parameter("topic", this->NAME``)
_OUT_PARAM_BEFORE = re.compile(rf"\b(?:{'|'.join(sorted(_OUT_PARAM_CALLS))})\s*(?:<[^<>;()]*>)?\s*\("
                               r"[^;()]*,\s*(?:this\s*->\s*)?$")


def _passed_out(toks: list[Tok], k: int) -> bool:
    """``get_parameter("topic", NAME)``: ``toks[k]`` is a later argument of a call that writes it."""
    depth = 0
    for j in range(k - 1, max(-1, k - 40), -1):
        t = toks[j].text
        if t in (")", "]", "}"):
            depth += 1
        elif t in ("(", "[", "{"):
            if depth == 0:
                return t == "(" and j > 0 and toks[j - 1].text in _OUT_PARAM_CALLS and \
                    any(x.text == "," for x in toks[j + 1:k])
            depth -= 1
        elif t == ";":
            return False
    return False


def _assigned_otherwise(toks: list[Tok], k: int) -> bool:
    """Whether ``toks[k]`` is given something other than a string literal: ``NAME = value`` (not
    ``==``), ``NAME += ...``, or a parameter's value (``get_parameter("topic", NAME)``)."""
    if _passed_out(toks, k):
        return True
    nxt = toks[k + 1][1] if k + 1 < len(toks) else ""
    after = toks[k + 2] if k + 2 < len(toks) else None
    if nxt == "=":
        return after is not None and after[1] != "=" and after[0] != "str"
    return nxt == "+" and after is not None and after[1] == "="


def _name_of(arg: list[Tok], consts: _Constants) -> tuple[str | None, Tok | None]:
    arg = [t for t in arg]
    # std::string("x") / std::string{"x"} / rclcpp::ParameterValue? no
    strs = [t for t in arg if t.kind == "str"]
    if len(arg) == 1 and arg[0].kind == "str":
        return arg[0].text, arg[0]
    if strs and len(strs) == 1 and all(t.kind in ("id", "op", "str") for t in arg) and \
            any(t.text == "string" for t in arg) and not any(t.text == "+" for t in arg):
        return strs[0].text, strs[0]
    ids = [t for t in arg if t.kind == "id"]
    if ids and all(t.kind == "id" or t.text in ("::", "this", "->", ".") for t in arg):
        last = ids[-1]
        value = consts.get(last.text)
        if value is not None:
            return value, last
    return None, None


def ros_type(cpp: str | None) -> str | None:
    """``sensor_msgs::msg::Image`` -> ``sensor_msgs/msg/Image``."""
    if not cpp:
        return None
    t = cpp.replace("typename", "").replace("const ", "").strip()
    t = re.sub(r"\s+", "", t).lstrip(":")
    m = re.fullmatch(r"(\w+)::(msg|srv|action)::(\w+)", t)
    if m:
        return f"{m.group(1)}/{m.group(2)}/{m.group(3)}"
    return None


_CPP_PARAM_TYPES = {
    "double": "double", "float": "double", "bool": "bool", "int": "integer", "long": "integer",
    "int64_t": "integer", "int32_t": "integer", "int16_t": "integer", "int8_t": "integer",
    "uint32_t": "integer", "uint16_t": "integer", "uint8_t": "integer", "size_t": "integer",
    "unsignedint": "integer", "longlong": "integer", "std::int64_t": "integer",
    "std::string": "string", "string": "string",
}


def param_type(cpp: str | None) -> str | None:
    if not cpp:
        return None
    t = re.sub(r"\s+", "", cpp.replace("const", ""))
    m = re.fullmatch(r"(?:std::)?vector<(.+?)(?:,.*)?>", t)
    if m:
        inner = m.group(1)
        if inner in ("uint8_t", "std::uint8_t", "unsignedchar"):
            return "byte_array"
        base = _CPP_PARAM_TYPES.get(inner) or _CPP_PARAM_TYPES.get(inner.replace("std::", ""))
        return f"{base}_array" if base else None
    return _CPP_PARAM_TYPES.get(t) or _CPP_PARAM_TYPES.get(t.replace("std::", ""))


def _literal_default(arg: list[Tok]) -> tuple[str | None, object]:
    toks = [t for t in arg]
    # unwrap rclcpp::ParameterValue(x) / std::string("x") / std::vector<T>{...}
    texts = [t.text for t in toks]
    if "ParameterValue" in texts:
        k = texts.index("ParameterValue")
        inner = _call_args(toks, k + 1) if k + 1 < len(toks) else None
        if inner and inner[0]:
            return _literal_default(inner[0][0])
        return None, None
    neg = False
    if toks and toks[0].text in ("-", "+"):
        neg = toks[0].text == "-"
        toks = toks[1:]
    if len(toks) == 1:
        t = toks[0]
        if t.kind == "num":
            txt = t.text.replace("'", "").rstrip("uUlLfF") if not t.text.lower().startswith("0x") \
                else t.text.replace("'", "").rstrip("uUlL")
            try:
                if re.fullmatch(r"0[xX][0-9a-fA-F]+|[0-9]+", txt):
                    v = int(txt, 0) if not re.fullmatch(r"0[0-7]+", txt) else int(txt, 8)
                    return "integer", -v if neg else v
                v = float(txt)
                return "double", -v if neg else v
            except ValueError:
                return None, None
        if t.kind == "id" and t.text in ("true", "false"):
            return "bool", t.text == "true"
        if t.kind == "str":
            return "string", t.text
    strs = [t for t in toks if t.kind == "str"]
    if len(strs) == 1 and "string" in texts and "+" not in texts:
        return "string", strs[0].text
    if len(toks) >= 1 and toks[0].text in ("std",) and "vector" in texts:
        k = texts.index("vector")
        if k + 1 < len(toks) and toks[k + 1].text == "<":
            inner, _ = _template_args(toks, k + 1)
            pt = param_type(f"std::vector<{inner}>") if inner else None
            return pt, None
    return None, None


_ENDPOINT_CALLS = {
    "create_publisher": "publishers", "create_subscription": "subscribers",
    "create_service": "services", "create_client": "clients",
}


def _interface(source: str = "") -> NodeInterface:
    return NodeInterface(publishers=[], subscribers=[], services=[], clients=[],
                         action_servers=[], action_clients=[], parameters={},
                         parameters_complete=False, source=source)


def extract_cpp(files: list[tuple[str, str]], cache: Any = None) -> NodeInterface:
    """What the sources declare together; ``cache`` (a ``cache.ParseCache``) keeps what each
    file declares on disk across runs."""
    return merge_facts([(_file_interface(path, text, cache), _everything) for path, text in files])


def _everything(owner: str | None) -> bool:
    return True


def merge_facts(parts: list[tuple[CppFacts, Callable[[str | None], bool | str]]]) -> NodeInterface:
    """The interface of the items of each part whose class its ``keep(class)`` accepts (``None``
    for code outside any class); ``keep`` may also answer "unnamed": an endpoint is then kept as
    its kind and type only (code that may or may not run), and a parameter or lifecycle base is
    kept. The first declaration of a parameter wins; any declaration of it makes it read-only."""
    iface = _interface("extracted from C++ sources")
    sites: list[NodeSite] = []
    makes: list[tuple[str, str | None, Span | None]] = []
    for part, keep in parts:
        for kind, endpoint, owner in part.endpoints:
            verdict = keep(owner)
            if verdict == "unnamed":
                iface.unnamed.append((kind, endpoint.type))
            elif verdict:
                getattr(iface, kind).append(endpoint)
        iface.unnamed.extend((kind, type_) for kind, type_, owner in part.unnamed if keep(owner))
        iface.lifecycle = iface.lifecycle or any(keep(owner) for owner in part.lifecycle)
        sites.extend((name, (owner or "") if passed else None, span, ns)
                     for name, passed, span, owner, ns in part.node_sites if keep(owner))
        makes.extend(part.makes)
        for decl, owner in part.parameters:
            if keep(owner):
                mine = iface.parameters.setdefault(decl.name, dataclasses.replace(decl))  # type: ignore[union-attr]
                if decl.read_only:
                    mine.read_only = True
    decide_node_name(iface, sites, makes)
    return iface


CACHE_KIND = "cpp-facts-6"  # the disk cache's kind for what one file declares (6: node namespaces)


@functools.lru_cache(maxsize=1024)
def _file_interface(path: str, text: str, cache: Any = None) -> CppFacts:
    """What one file contributes, once per file (callers copy from it, never change it): a
    package's executables share sources (2,195 extractions of 601 files on the real-world corpus).

    A pure function of the path (spans name it) and the text: with a ``cache``, read from disk when
    this text was seen before. Files without a call word are not stored (the check is cheaper than
    a lookup), nor is what a failed extraction left."""
    part = CppFacts()
    if not _CALL_WORDS.search(text):
        return part
    key = cache.key(CACHE_KIND, path, text) if cache is not None else None
    if key is not None:
        hit = cache.get(key)
        if type(hit) is CppFacts:
            return hit
    try:
        _extract_one(path, text, part)
    except (RecursionError, IndexError, ValueError):
        return part  # what was found before the failure stays
    if key is not None:
        cache.put(key, part)
    return part


def _span(path: str, t: Tok | None) -> Span | None:
    if t is None:
        return None
    return Span(path, t.line, t.col, t.end_line, t.end_col)


def _read_only_descriptors(toks: list[Tok]) -> set[str]:
    """Variables given ``NAME.read_only = true`` (or ``->``) in the file."""
    names = (_read_only_at(toks, j) for j, t in enumerate(toks) if t[1] == "read_only")
    return {name for name in names if name is not None}


def _read_only_at(toks: list[Tok], j: int) -> str | None:
    """The variable ``toks[j]`` (a ``read_only``) is in ``NAME.read_only = true``, if it is."""
    if 2 <= j < len(toks) - 2 and toks[j - 1].text in (".", "->") and toks[j + 1].text == "=" \
            and toks[j + 2].text == "true" and toks[j - 2].kind == "id":
        return toks[j - 2].text
    return None


def _descriptor_read_only(arg: list[Tok], names: set[str]) -> bool:
    """A descriptor argument that makes the parameter read-only: a variable set read-only above,
    ``...set__read_only(true)`` or a brace initialiser with ``.read_only = true``."""
    if len(arg) == 1 and arg[0].kind == "id":
        return arg[0].text in names
    for j in range(len(arg) - 2):
        if arg[j].text == "set__read_only" and arg[j + 1].text == "(" and arg[j + 2].text == "true":
            return True
        if arg[j].text == "read_only" and arg[j + 1].text == "=" and arg[j + 2].text == "true":
            return True
    return False


# Every call _extract_one looks for names one of these (a message_filters subscriber's class is
# ``message_filters::Subscriber``); a file without any has nothing to give (two thirds of the C++
# files of a workspace), and tokenizing it is most of the cost.
_WORDS = (r"create_(?:publisher|subscription|service|client|server)|advertise|subscribe"
          r"|declare_(?:parameter|or_get_parameter)|Transform(?:Listener|Broadcaster)|LifecycleNode")
_CALL_WORDS = re.compile(_WORDS + r"|message_filters|Node\s*(?:::\s*make_shared\s*)?\("
                         r'|make_(?:shared|unique)\s*<[\w:\s]*>\s*\(\s*"|__(?:node|name|ns):=')
_TF_ENDPOINTS = {
    "TransformListener": (("subscribers", "/tf"), ("subscribers", "/tf_static")),
    "TransformBroadcaster": (("publishers", "/tf"),),
    "StaticTransformBroadcaster": (("publishers", "/tf_static"),),
}


# every name a branch of _extract_one's loop acts on
_LOOP_NAMES = frozenset(_TF_ENDPOINTS) | frozenset(_ENDPOINT_CALLS) | {
    "create_server", "advertise", "subscribe", "advertiseCamera", "subscribeCamera",
    "declare_parameter", "declare_parameter_if_not_declared", "declare_or_get_parameter",
    "LifecycleNode", "Subscriber", "SubscriberFilter"}
# The namespaces of the lifecycle node classes a node's class derives from (nav2's own wrapper:
# nav2_util up to jazzy, nav2 after), and the tokens a base class or a constructor's initialiser
# names one after, or ``make_shared<...>`` makes one with.
_LIFECYCLE_NAMESPACES = frozenset({"rclcpp_lifecycle", "nav2_util", "nav2"})
_BASE_BEFORE = frozenset({"public", "protected", "private", ":", ","})
_BASE_AFTER = frozenset({"{", ",", "("})


# ---- where the tokens come from ------------------------------------------------------------------
# Extraction reads only a few tokens around each call word (the two before it, and up to the ";"
# that ends its statement), the file's string constants and its ``X.read_only = true`` lines. A
# "skim" (one regex for comments, strings, chars and preprocessor lines, a tenth of tokenizing)
# finds the parts of the file that are not code; only the statements around the words extraction
# acts on are then tokenized. A file whose skim meets something the tokenizer reads in its own
# way (an unterminated char literal, whose newline it does not count; a raw string without a
# delimiter; a file past MAX_SOURCE) is tokenized whole, as before.

_IDCHARS = _ID_START_CHARS | frozenset("0123456789")
_SKIM = re.compile(r"//[^\n]*"
                   r"|/\*(?:[^*]*\*+(?:[^/*][^*]*\*+)*/|[\s\S]*)"
                   r'|"(?:[^"\\\n]+|\\[\s\S]?)*["\n]?'
                   r"|'(?:[^'\\\n]+|\\[\s\S]?)*['\n]?"
                   r"|\#")
_RAW_PREFIXES = frozenset(p for p in _STR_PREFIX if p.endswith("R"))
# a part of every word an anchor can be (_LOOP_NAMES and read_only); the identifier around it
# decides. (No look-around, nor optional prefixes: either costs the regex its fast scan for the
# first character, three times the time.)
_ANCHOR = re.compile(_WORDS + "|read_only|Subscriber")
_ANCHOR_WORDS = _LOOP_NAMES | {"read_only"}
_FOUR_BEFORE = frozenset({"LifecycleNode", "Subscriber", "SubscriberFilter"})


_DIGITS = frozenset("0123456789")


def _run_start(text: str, p: int) -> int | None:
    """The start of the run of identifier characters that ends at offset ``p``; None when a number
    before it may reach into it (``1'0x``, ``1.e5x``, ``1.fx``): how the tokenizer splits such a
    run depends on what precedes it. (A run that starts with a digit is a number, which callers
    judge; only digits can follow an exponent's sign.)"""
    j = p
    while j and text[j - 1] in _IDCHARS:
        j -= 1
    if j < p and j >= 2:
        before, before2 = text[j - 1], text[j - 2]
        if before == "'" and before2 in _IDCHARS:
            return None
        if before == "." and before2 in _DIGITS and text[j] in "eEuUlLfF":
            return None
    return j


class _Whole:
    """Every token of the file (the fallback, and the reference the windows are tested against)."""

    def __init__(self, text: str) -> None:
        self.text = text
        self.toks = tokenize(text)

    def anchors(self) -> list[tuple[list[Tok], int, int]]:
        toks = self.toks
        # only the identifiers extraction acts on (a comprehension over the list, not a loop)
        return [(toks, i, -1) for i, t in enumerate(toks) if t[1] in _LOOP_NAMES and t[0] == "id"]

    def uses(self, name: str) -> list[tuple[list[Tok], int, int]]:
        """Where the identifier ``name`` is (a message_filters member's name)."""
        toks = self.toks
        return [(toks, i, -1) for i, t in enumerate(toks) if t[1] == name and t[0] == "id"]

    def classes(self) -> list[tuple[str | None, int, int]]:
        return []  # (offsets are not known: nothing is attributed to a class)

    def constants(self) -> dict[str, str]:
        return _constants(self.toks)

    def read_only(self) -> set[str]:
        return _read_only_descriptors(self.toks)


class _Windows:
    """The tokens of the statements around the file's anchors, from a skim of the whole text."""

    def __init__(self, text: str, starts: list[int], ends: list[int], defines: list[tuple[str, str]],
                 words: list[tuple[int, str]]) -> None:
        self.text, self.starts, self.ends, self.defines = text, starts, ends, defines
        self.words = words  # (offset, word) of each anchor outside comments, strings...
        self._at, self._line = 0, 1  # _line_of's cursor

    @classmethod
    def of(cls, text: str) -> _Windows | None:
        """The skim of ``text``; None when the file must be tokenized whole."""
        if len(text) > MAX_SOURCE:
            return None
        starts: list[int] = []
        ends: list[int] = []
        defines: list[tuple[str, str]] = []
        search, n, pos = _SKIM.search, len(text), 0
        while True:
            m = search(text, pos)
            if m is None:
                break
            s, e = m.span()
            c = text[s]
            if c == "'":
                if s and text[s - 1] in _IDCHARS:
                    j = _run_start(text, s)
                    if j is None or (j and text[j - 1] in ".+-"):
                        return None  # (".5'", "1e+5'": the number may start before the run)
                    if text[j] in _DIGITS:  # a digit separator, inside a number
                        num = _NUM.match(text, j)
                        if num and num.end() > s:
                            pos = num.end()
                            continue
                if e == n or text[e - 1] != "'" or e - s < 2 or text.find("\n", s, e) >= 0:
                    return None  # a newline in it, or unterminated: the tokenizer does not count
                    # that newline (nor a char at the very end, read by its slow path)
            elif c == '"':
                j = _run_start(text, s)
                if j is None or (j < s and text[j] in _DIGITS):
                    return None  # a number may run into the prefix
                if text[j:s] in _RAW_PREFIXES:
                    delim = _RAW_DELIM.match(text, s, s + 20)
                    if not delim:
                        return None
                    close = ")" + delim.group(1) + '"'
                    k = text.find(close, delim.end())
                    s, e = j, (n if k < 0 else k + len(close))
            elif c == "#":
                line_start = text.rfind("\n", 0, s) + 1
                if text[line_start:s].strip():
                    pos = s + 1  # an operator, not a preprocessor line
                    continue
                e = _line_end(text, s, n)
                d = _DEFINE.match(text[s:e])
                if d:
                    defines.append((d.group(1), _unescape(d.group(2))))
            starts.append(s)
            ends.append(e)
            pos = e
        view = cls(text, starts, ends, defines, [])
        last = -1
        for m in _ANCHOR.finditer(text):
            p = _run_start(text, m.start())
            if p is None or (p < m.start() and text[p] in _DIGITS):
                return None  # a number may run into it
            word = text[p:_ID.match(text, m.end()).end()]  # type: ignore[union-attr]
            if p > last and word in _ANCHOR_WORDS and not view._inside(p):
                view.words.append((p, word))
                last = p
        return view

    def _inside(self, p: int) -> bool:
        """Whether offset ``p`` is in a comment, string, char or preprocessor line."""
        return _in_skimmed(p, self.starts, self.ends)

    def _first_token(self, p: int) -> bool:
        """Whether no token comes before offset ``p``: only blanks, comments and preprocessor
        lines other than a ``#define`` of a literal."""
        text, starts, pos = self.text, self.starts, 0
        while True:
            while pos < p and text[pos] in " \t\r\f\v\\\n":
                pos += 1
            if pos >= p:
                return True
            k = bisect.bisect_left(starts, pos)
            if k == len(starts) or starts[k] != pos or text[pos] not in "/#" \
                    or _DEFINE.match(text, pos, self.ends[k]):
                return False
            pos = self.ends[k]

    def _line_of(self, p: int) -> int:
        """The line of offset ``p``, counted from the last one asked (they mostly increase)."""
        text, at = self.text, self._at
        self._line += text.count("\n", at, p) if p >= at else -text.count("\n", p, at)
        self._at = p
        return self._line

    def _line_start(self, p: int) -> int:
        """The start of the line holding offset ``p``, moved up past any comment, string or
        preprocessor line that spans it (a line start outside them is a token boundary)."""
        text = self.text
        ls = text.rfind("\n", 0, p) + 1
        while ls:
            k = bisect.bisect_right(self.starts, ls) - 1
            if k < 0 or not self.starts[k] < ls < self.ends[k]:
                return ls
            ls = text.rfind("\n", 0, self.starts[k]) + 1
        return ls

    def _statement_end(self, p: int) -> int:
        """Just after the first ";" token from ``p``, or the end of the text."""
        text = self.text
        k = text.find(";", p)
        while k >= 0 and self._inside(k):
            k = text.find(";", self.ends[bisect.bisect_right(self.starts, k) - 1])
        return len(self.text) if k < 0 else k + 1

    def _window(self, p: int, name: str, calls: bool = True) -> tuple[list[Tok], int] | None:
        """The tokens from a line start with at least two tokens (four before a
        ``LifecycleNode`` or a message_filters ``Subscriber``: ``make_shared<ns::Subscriber``)
        before offset ``p`` to the end of its statement (past a lambda's body in a call, unless
        not ``calls``), and the index of the token at ``p``."""
        before = 4 if name in _FOUR_BEFORE else 2
        end = self._statement_end(p)
        ls = self._line_start(p)
        for _ in range(8):  # a line back at a time, while fewer than ``before`` tokens come first
            line = self._line_of(ls)
            toks = tokenize(self.text, ls, end, line, ls)
            at_line, at_col = self._line_of(p), p - self.text.rfind("\n", 0, p)
            i = next((i for i, t in enumerate(toks) if t[2] == at_line and t[3] == at_col), -1)
            if i < 0 or toks[i][1] != name:
                return None  # the tokenizer reads the line otherwise: leave it
            if i >= before or ls == 0:
                break
            ls = self._line_start(ls - 1)
        # Extraction reads up to the ";" that ends the call: past a ";" inside braces opened
        # after the word (a lambda's body), as ``_call_args`` does, up to its limit.
        stack: list[str] = []  # (the brackets open after the word in the tokens scanned so far)
        scanned = i + 1
        while calls and end < len(self.text) and len(toks) < i + 4400:
            brace_open, scanned = _brace_open(toks, scanned, stack)
            if not brace_open:
                break
            start, end = end, self._statement_end(end)
            ls = self.text.rfind("\n", 0, start) + 1
            toks += tokenize(self.text, start, end, self._line_of(ls), ls)
        return toks, i

    def anchors(self) -> list[tuple[list[Tok], int, int]]:
        """(tokens, index of the word, its offset) per anchor."""
        out = []
        for p, name in self.words:
            if name != "read_only":
                win = self._window(p, name, name not in _FILTER_CLASSES)
                if win is not None:
                    out.append((*win, p))
        return out

    def uses(self, name: str) -> list[tuple[list[Tok], int, int]]:
        """Where the identifier ``name`` is, outside comments and strings (a message_filters
        member's name: its initialiser ``name_(node, "topic")``)."""
        out = []
        text = self.text
        # (only a name a call's or a brace's arguments follow)
        for m in re.finditer(re.escape(name) + r"\s*[({]", text):
            p = m.start()
            if p and text[p - 1] in _IDCHARS or self._inside(p):
                continue
            win = self._window(p, name, False)  # (an initialiser's arguments end before its body)
            if win is not None:
                out.append((*win, p))
        return out

    def classes(self) -> list[tuple[str | None, int, int]]:
        """The scopes at namespace level (``cpp_scopes.scopes``)."""
        return scopes(self.text, self.starts, self.ends)

    def constants(self) -> _LazyConstants:
        return _LazyConstants(self)

    def read_only(self) -> set[str]:
        out: set[str] = set()
        for p, name in self.words:
            if name == "read_only":
                win = self._window(p, name)
                variable = _read_only_at(*win) if win is not None else None
                if variable is not None:
                    out.add(variable)
        return out


class _LazyConstants:
    """``_constants`` of a skimmed file, one name at a time (extraction asks about a few)."""

    def __init__(self, view: _Windows) -> None:
        self.view = view
        self.memo: dict[str, str | None] = {}
        self.whole: dict[str, str] | None = None  # _constants of every token, when in doubt

    def _every_token(self) -> dict[str, str]:
        if self.whole is None:
            self.whole = _constants(tokenize(self.view.text))
        return self.whole

    def get(self, name: str) -> str | None:
        if name not in self.memo:
            self.memo[name] = self._find(name)
        return self.memo[name]

    def _find(self, name: str) -> str | None:
        view = self.view
        defined = [lit for n, lit in view.defines if n == name]
        if defined:  # a #define wins over any definition, the last one over the others
            return defined[-1]
        if name in ("return", "std", "string"):
            return None
        text = view.text
        values: set[str] = set()
        for m in re.finditer(re.escape(name), text):
            p = m.start()
            if m.end() < len(text) and text[m.end()] in _IDCHARS or view._inside(p):
                continue
            j = _run_start(text, p)
            if j is None or (j < p and text[j] in _DIGITS):
                return self._every_token().get(name)  # a number may run into it
            if j < p:
                continue  # a part of a longer name
            ls = text.rfind("\n", 0, p) + 1
            line, end = view._line_of(ls), view._statement_end(p)
            toks = tokenize(text, p, end, line, ls)
            while len(toks) < 8 and end < len(text):  # the name, up to 5 tokens, the literal, one
                end = view._statement_end(end)
                toks = tokenize(text, p, end, line, ls)
            if not toks or toks[0][1] != name or toks[0][0] != "id":
                continue
            if _assigned_otherwise(toks, 0) or _OUT_PARAM_BEFORE.search(text, max(0, p - 200), p):
                return None  # a variable (or a parameter's value: get_parameter("topic", NAME))
            first = 2 if view._first_token(p) else 1  # (_constants skips a literal at 0 or 1)
            for j in range(first, min(len(toks), 7)):
                if toks[j][0] == "str" and _constant_name_at(toks, j) == 0:
                    values.add(toks[j][1])  # (toks[0] is the name: _is_constant_name holds)
                    break
        return next(iter(values)) if len(values) == 1 else None


def _brace_open(toks: list[Tok], start: int, stack: list[str]) -> tuple[bool, int]:
    """Whether a "{" opened after the word is still open at the end of ``toks`` (no bracket
    opened before the word closed first), going on from ``toks[start]`` with ``stack`` the
    brackets open before it (updated); and where the next call goes on. (A window grows a
    statement at a time; scanning it whole again each time took half of extraction's time.)"""
    for k in range(start, len(toks)):
        t = toks[k]
        if t[0] == "op":
            if t[1] in "([{":
                stack.append(t[1])
            elif t[1] in ")]}":
                if not stack:
                    return False, len(toks)
                stack.pop()
    return "{" in stack, len(toks)


def _constant_name_at(toks: list[Tok], j: int) -> int | None:
    """Where the name is that the string literal ``toks[j]`` may define (``NAME = "x";``,
    ``NAME[] = "x";``, ``NAME{"x"}``, ``NAME("x")``), before asking whether it is a name: None
    when ``toks[j]`` cannot be such a definition."""
    nxt = toks[j + 1].text if j + 1 < len(toks) else ";"
    if nxt not in (";", "}", ")"):
        return None
    k = j - 1
    if toks[k].text in ("=", "{", "("):
        k -= 1
    if toks[k].text == "#define":
        return None
    if toks[k].kind == "op" and toks[k].text == "]":
        k -= 2 if toks[k - 1].text == "[" else 3
    return k


def _is_constant_name(toks: list[Tok], k: int) -> bool:
    return k >= 0 and toks[k].kind == "id" and toks[k].text not in ("return", "std", "string")


def _extract_one(path: str, text: str, facts: CppFacts) -> None:
    """Extract a file ``_file_interface`` found a call word in."""
    _extract_from(path, skim(text) or _Whole(text), facts)


@functools.lru_cache(maxsize=64)
def skim(text: str) -> _Windows | None:
    """``_Windows.of(text)``, for a while: telling which classes run in an executable reads again
    the sources just extracted (``linked.py``)."""
    return _Windows.of(text)


class _Collector:
    """Adds what extraction finds to a ``CppFacts``, each item with the class whose code holds
    the word it was found at."""

    def __init__(self, path: str, view: _Whole | _Windows, facts: CppFacts) -> None:
        self.path, self.facts = path, facts
        self.view = view if isinstance(view, _Windows) else None
        found = view.classes()
        facts.classes = tuple((c, a, b) for c, a, b in found if c is not None)
        self.scopes, self.firsts = found, [a for _, a, _ in found]
        self.owner: str | None = None
        self.p = -1
        self._blocks: dict[int, tuple[str, list[tuple[int, int]]]] = {}  # per scope: its code, blocks
        self._branches: list[tuple[int, int]] | None = None  # #if ... #endif

    def at(self, p: int) -> None:
        """Items from here on are at offset ``p`` (-1: unknown)."""
        self.p = p
        self.owner = owner_at(self.scopes, self.firsts, p) if p >= 0 else None

    def conditional(self) -> bool:
        """Whether the code at the current offset runs only under a condition it tests (an
        ``if``/``else``/``switch`` body, a braceless ``if``, a ``?:``) or is compiled only under one
        (``#ifdef``). The scope's blocks are found once per scope."""
        view, p = self.view, self.p
        if view is None or p < 0:
            return False
        if self._branches is None:
            self._branches = preprocessor_branches(view.text, view.starts, view.ends)
        if any(a < p < b for a, b in self._branches):
            return True
        k = bisect.bisect_right(self.firsts, p) - 1
        if k < 0 or p >= self.scopes[k][2]:
            return False
        if k not in self._blocks:
            _, a, b = self.scopes[k]
            code = blank_code(view.text, a, b, view.starts, view.ends, keep_offsets=True)
            self._blocks[k] = (code, conditional_blocks(code))
        code, blocks = self._blocks[k]
        at = p - self.scopes[k][1]
        return any(o < at < c for o, c in blocks) or braceless_conditional(code, at)

    def endpoint(self, kind: str, name: str | None, type_: str | None, tok: Tok | None) -> None:
        if name is None:
            self.facts.unnamed.append((kind, type_, self.owner))
        else:
            when = CODE_CONDITION if self.conditional() else ()
            self.facts.endpoints.append((kind, Endpoint(name, type_, _span(self.path, tok), when),
                                         self.owner))

    def parameter(self, decl: ParamDecl) -> None:
        self.facts.parameters.append((decl, self.owner))

    def lifecycle(self) -> None:
        self.facts.lifecycle.append(self.owner)

    def node_site(self, name: str | None, passed: bool, span: Span | None, namespace: str | None) -> None:
        self.facts.node_sites.append((name, passed, span, self.owner, namespace))


def _extract_from(path: str, view: _Whole | _Windows, facts: CppFacts) -> None:
    consts = view.constants()
    read_only = view.read_only()
    out = _Collector(path, view, facts)
    anchors = view.anchors()
    declared: set[tuple[int, int]] = set()  # where the declarations name them
    filters = _filter_members(anchors, consts, out, declared)  # message_filters members -> type
    facts.filters = filters
    for toks, i, p in anchors:
        t = toks[i]
        name = t.text
        out.at(p)
        prev = toks[i - 1].text if i > 0 else ""
        prev2 = toks[i - 2].text if i > 1 else ""
        if name == "LifecycleNode":
            if prev == "::" and prev2 in _LIFECYCLE_NAMESPACES and i + 1 < len(toks) and (
                    (i > 2 and toks[i - 3].text in _BASE_BEFORE and toks[i + 1].text in _BASE_AFTER)
                    or (i > 3 and toks[i - 3].text == "<" and toks[i - 4].text == "make_shared"
                        and toks[i + 1].text == ">")
                    or (i + 2 < len(toks) and toks[i + 1].text == "::" and toks[i + 2].text == "make_shared")):
                out.lifecycle()  # a lifecycle node's class, or one made (LifecycleNode::make_shared)
            continue
        if name in _FILTER_CLASSES:
            continue  # (``_filter_members`` read them)
        if name in _TF_ENDPOINTS and prev == "::" and prev2 == "tf2_ros":
            # tf2_ros' listener subscribes to (and its broadcasters publish on) the absolute /tf and
            # /tf_static: nodes using them honour a ("/tf", "tf") remap like any other topic.
            for kind, topic in _TF_ENDPOINTS[name]:
                out.endpoint(kind, topic, "tf2_msgs/msg/TFMessage", t)
            continue
        if name in _ENDPOINT_CALLS or name in ("create_server",):
            j = i + 1
            targ = None
            if j < len(toks) and toks[j].text == "<":
                targ, j = _template_args(toks, j)
            parsed = _call_args(toks, j)
            if parsed is None:
                continue
            args, _ = parsed
            ns = prev2 if prev == "::" else ""
            if ns == "rclcpp_action":
                if len(args) >= 2:
                    n, tok = _name_of(args[1], consts)
                    kind = "action_servers" if name == "create_server" else "action_clients"
                    out.endpoint(kind, n, ros_type(targ), tok)
                continue
            if ns == "image_transport":
                if len(args) >= 2 and name in ("create_publisher", "create_subscription"):
                    n, tok = _name_of(args[1], consts)
                    out.endpoint(_ENDPOINT_CALLS[name], n, "sensor_msgs/msg/Image", tok)
                continue
            if name == "create_server" or not args or targ is None:
                continue
            n, tok = _name_of(args[0], consts)
            out.endpoint(_ENDPOINT_CALLS[name], n, ros_type(targ), tok)
        elif name in ("advertise", "subscribe", "advertiseCamera", "subscribeCamera") and \
                prev in (".", "->"):
            parsed = _call_args(toks, i + 1)
            if parsed is None or not parsed[0]:
                continue
            args = parsed[0]
            n, tok = _name_of(args[0], consts)
            receiver = toks[i - 2].text if i > 1 and toks[i - 2].kind == "id" else ""
            if name == "subscribe" and (receiver in filters or n is None and _filter_subscribe(
                    args, consts)):
                # message_filters' ``sub_.subscribe(node, "topic", qos)``, not image_transport's
                # ``it.subscribe("topic", queue_size, callback)``
                n, tok = _name_of(args[1], consts) if len(args) > 1 else (None, None)
                out.endpoint("subscribers", n, filters.get(receiver), tok)
                continue
            kind = "publishers" if name.startswith("advertise") else "subscribers"
            out.endpoint(kind, n, "sensor_msgs/msg/Image", tok)
        elif name in ("declare_parameter", "declare_parameter_if_not_declared",
                      "declare_or_get_parameter"):
            j = i + 1
            targ = None
            if j < len(toks) and toks[j].text == "<":
                targ, j = _template_args(toks, j)
            parsed = _call_args(toks, j)
            if parsed is None or not parsed[0]:
                continue
            args = parsed[0]
            k = 1 if name == "declare_parameter_if_not_declared" else 0
            if len(args) <= k:
                continue
            n, tok = _name_of(args[k], consts)
            if n is None:
                continue
            ptype = param_type(targ)
            default = None
            has_default = False
            if len(args) > k + 1:
                dtype, default = _literal_default(args[k + 1])
                has_default = dtype is not None and default is not None
                if ptype is None:
                    ptype = dtype
            decl = ParamDecl(n, ptype, default, span=_span(path, tok), source=path,
                             has_default=has_default)
            decl.read_only = len(args) > k + 2 and _descriptor_read_only(args[k + 2], read_only)
            out.parameter(decl)
    for member in sorted(filters):
        for toks, i, p in view.uses(member):
            if (toks[i].line, toks[i].col) not in declared:
                out.at(p)
                _filter_initialiser(toks, i, filters[member], consts, out)
    _node_sites(path, view, consts, out)


# ---- the node the code makes ----------------------------------------------------------------------
# ``: Node("talker")``, ``: rclcpp::Node("talker", options)``, ``: nav2_util::LifecycleNode("amcl",
# "", options)``, ``rclcpp::Node::make_shared("talker")``, ``std::make_shared<rclcpp::Node>("talker")``,
# ``new rclcpp::Node("talker")``: the first argument is the name rclcpp gives the node when the
# command line does not rename it (``-r __node:=``, which launch adds for ``name=``). Read from the
# text with a few regular expressions (each starts with a literal, which the regex engine scans
# for fast: a leading ``\b`` or alternation made them twenty times slower), not tokenized.

_NODE_CALL = re.compile(r"Node\s*(?:::\s*make_shared\s*)?\(")
_NODE_MAKE = re.compile(r"make_shared\s*<\s*(?:\w+\s*::\s*)*(?:Lifecycle)?Node\s*>\s*\(")
_MAKE = re.compile(r'make_(?:shared|unique)\s*<\s*(?:\w+\s*::\s*)*(\w+)\s*>\s*\(')
# the first argument, after the "(": a literal, a name, a declaration, ``std::string("x")``
_LITERAL_ARG = re.compile(r'\s*"((?:[^"\\\n]|\\.)*)"\s*[,)]')
_NAME_ARG = re.compile(r"\s*((?:\w+\s*::\s*)*\w+)\s*[,)]")
_STRING_ARG = re.compile(r'\s*(?:std\s*::\s*)?string\s*[({]\s*"((?:[^"\\\n]|\\.)*)"\s*[)}]\s*[,)]')
_DECLARATION_ARG = re.compile(r"\s*(?:\)|(?:const|volatile)\b|[\w:<>]+\s*[&*]+\s*\w|[\w:<>]+\s+\w+\s*[,)=])")




_NAMESPACE_WORD = re.compile(r"(?i)(?:^|[_.>:\s])(?:ns|name_?space)(?:$|_|\b)")


def _namespace_argument(text: str, end: int) -> str | None:
    """The namespace a node constructor's second argument gives (``text[end]`` ends the first
    argument): "" when there is none (``Node("x")``, ``Node("x", options)``), the literal
    (``Node("x", "robot1")``), None when not known statically."""
    if text[end] != ",":
        return ""
    lit = _LITERAL_ARG.match(text, end + 1)
    if lit:
        return _unescape(lit.group(1))
    depth, j = 0, end + 1
    while j < len(text) and j < end + 400:
        c = text[j]
        if c in "([{":
            depth += 1
        elif c in ")]}":
            if depth == 0:
                break
            depth -= 1
        elif c in ",;" and depth == 0:
            break
        j += 1
    argument = text[end + 1:j].strip()
    # (``Node("x", options)``, ``Node("x", o)``, ``Node("x", rclcpp::NodeOptions())``: options;
    # ``Node("x", ns)``, ``Node("x", robot_namespace_)``: a namespace not known statically)
    return None if _NAMESPACE_WORD.search(argument) else ""


def _after_word(text: str, p: int) -> bool:
    return not (p and text[p - 1] in _IDCHARS)


def _node_sites(path: str, view: _Whole | _Windows, consts: _Constants, out: _Collector) -> None:
    """Record each place the file makes a node (not a declaration ``Node(const std::string &
    name)``), and each class construction's first literal (``_makes``)."""
    text = view.text
    inside = view._inside if isinstance(view, _Windows) else (lambda p: False)
    starts = []  # (offset of the word, offset after its "(")
    for m in _NODE_CALL.finditer(text):
        p = m.start()
        if not _after_word(text, p):  # ``LifecycleNode(`` only, not ``MyNode(``
            if text[p - 9:p] != "Lifecycle" or not _after_word(text, p - 9):
                continue
            p -= 9
        starts.append((p, m.end()))
    starts.extend((m.start(), m.end()) for m in _NODE_MAKE.finditer(text) if _after_word(text, m.start()))
    for p, arg in sorted(starts):
        if inside(p) or text[max(0, p - 8):p].rstrip().endswith(("~", "class", "struct")):
            continue
        out.at(p)
        if _DECLARATION_ARG.match(text, arg):
            continue  # ``Node()`` (rclcpp::Node has none), or a parameter list
        lit = _LITERAL_ARG.match(text, arg) or _STRING_ARG.match(text, arg)
        if lit:
            out.node_site(_unescape(lit.group(1)), False, _text_span(path, text, lit.start(1) - 1, lit.end(1) + 1),
                          _namespace_argument(text, lit.end() - 1))
            continue
        ident = _NAME_ARG.match(text, arg)
        word = ident.group(1).rsplit(":", 1)[-1].strip() if ident else None
        value = consts.get(word) if word else None
        span = _text_span(path, text, ident.start(1), ident.end(1)) if ident else None
        ns = _namespace_argument(text, ident.end() - 1) if ident else None
        if value is not None:
            out.node_site(value, False, span, ns)
            continue
        passed = word is not None and re.search(
            r"\b(?:string|char|auto)\s*(?:const\s*)?[&*]?\s*" + re.escape(word) + r"\s*[,)=]",
            text[max(0, p - 4000):p]) is not None
        out.node_site(None, passed, span, ns)
    for m in CODE_REMAP.finditer(text):  # ``NodeOptions().arguments({"--ros-args", "-r", "__node:=x"})``
        out.at(m.start())
        out.node_site(None, False, _text_span(path, text, m.start(), m.end()), "")
    _makes(path, text, inside, out.facts)


def _makes(path: str, text: str, inside: Callable[[int], bool], facts: CppFacts) -> None:
    """``make_shared<LifecycleTalker>("lc_talker")``: the literal a class is constructed with
    first (the name its constructor may pass on to ``Node``), None for another argument."""
    for m in _MAKE.finditer(text):
        if not _after_word(text, m.start()) or inside(m.start()):
            continue
        lit = _LITERAL_ARG.match(text, m.end())
        if lit:
            facts.makes.append((m.group(1), _unescape(lit.group(1)),
                                _text_span(path, text, lit.start(1) - 1, lit.end(1) + 1)))
        else:
            facts.makes.append((m.group(1), None, _text_span(path, text, m.start(1), m.end(1))))


def _text_span(path: str, text: str, a: int, b: int) -> Span:
    line = text.count("\n", 0, a) + 1
    col = a - text.rfind("\n", 0, a)
    return Span(path, line, col, line, col + (b - a))


# ---- message_filters ----------------------------------------------------------------------------
# ``message_filters::Subscriber<T> sub_;`` subscribes when constructed with a node and a topic
# (``sub_(node, "topic", qos)`` in a constructor's initialisers, ``make_shared<...>(node, "topic")``)
# or told to (``sub_.subscribe(node, "topic", qos)``); image_transport's ``SubscriberFilter`` is
# the same for images.

_FILTER_CLASSES = {"Subscriber": "message_filters", "SubscriberFilter": "image_transport"}
_MAKERS = frozenset({"make_shared", "make_unique"})
_HOLDERS = frozenset({"shared_ptr", "unique_ptr"})


@functools.lru_cache(maxsize=256)
def member_initialisers(path: str, text: str, members: tuple[tuple[str, str | None], ...]
                        ) -> CppFacts:
    """The subscriptions a source's constructors make by initialising message_filters
    ``members`` (name, message type) that another file (its header) declares:
    ``odom_sub_(node, "odom/filtered", qos)``."""
    facts = CppFacts()
    try:
        view = skim(text) or _Whole(text)
        out = _Collector(path, view, facts)
        consts = view.constants()
        for member, type_ in members:
            for toks, i, p in view.uses(member):
                out.at(p)
                _filter_initialiser(toks, i, type_, consts, out)
    except (RecursionError, IndexError, ValueError):
        pass  # what was found before the failure stays
    facts.classes = ()  # (the source's own facts hold them)
    return facts


def _filter_members(anchors: list[tuple[list[Tok], int, int]], consts: _Constants,
                    out: _Collector, declared: set[tuple[int, int]]) -> dict[str, str | None]:
    """The members (and variables) declared as message_filters subscribers, with their message
    types (and in ``declared`` where their declarations name them); records the subscriptions
    constructed with a topic on the way."""
    members: dict[str, str | None] = {}
    for toks, i, p in anchors:
        name = toks[i].text
        if name not in _FILTER_CLASSES or i < 2 or toks[i - 1].text != "::" \
                or toks[i - 2].text != _FILTER_CLASSES[name]:
            continue
        out.at(p)
        j = i + 1
        type_: str | None = "sensor_msgs/msg/Image" if name == "SubscriberFilter" else None
        if name == "Subscriber":
            if j >= len(toks) or toks[j].text != "<":
                continue
            targ, j = _template_args(toks, j)
            type_ = ros_type(_first_template_arg(targ))
        before = toks[i - 3].text if i > 2 else ""
        if before == "<" and j < len(toks) and toks[j].text == ">":  # inside make_shared<...>
            j += 1
            maker = toks[i - 4].text if i > 3 else ""
            if maker in _MAKERS:
                _filter_construction(toks, j, type_, consts, out)
                continue
            if maker not in _HOLDERS:
                continue
        elif before == "new":
            _filter_construction(toks, j, type_, consts, out)
            continue
        while j + 1 < len(toks) and toks[j].kind == "id":  # ``Subscriber<T> a_, b_{node, "t"};``
            members[toks[j].text] = type_
            declared.add((toks[j].line, toks[j].col))
            _filter_construction(toks, j + 1, type_, consts, out)
            j = _skip_initialiser(toks, j + 1)
            if j >= len(toks) or toks[j].text != ",":
                break
            j += 1
    return members


def _filter_construction(toks: list[Tok], j: int, type_: str | None, consts: _Constants,
                         out: _Collector) -> None:
    """``(node, "topic", ...)`` or ``{node, "topic", ...}`` at ``toks[j]``: a subscription (with
    fewer arguments, or a string first, it is something else: ``subscribe`` comes later). Not
    past a ";" (a window of tokens ends there: a lambda's body is no topic anyway)."""
    parsed = _call_args(toks, j, braces=True)
    if parsed is not None and any(t.text == ";" for t in toks[j:parsed[1]]):
        return
    if parsed is not None and len(parsed[0]) >= 2 and not _is_string(parsed[0][0]):
        n, tok = _name_of(parsed[0][1], consts)
        out.endpoint("subscribers", n, type_, tok)


def _filter_initialiser(toks: list[Tok], i: int, type_: str | None, consts: _Constants,
                        out: _Collector) -> None:
    """``member_(node, "topic", ...)`` in a constructor's initialisers."""
    if i and toks[i - 1].text in (":", ","):
        _filter_construction(toks, i + 1, type_, consts, out)


def _skip_initialiser(toks: list[Tok], j: int) -> int:
    """The index of the "," after a declarator's initialiser (``(...)``, ``{...}``, ``= ...``)
    at ``j``, or of the ";" that ends the statement (a window of tokens ends there)."""
    depth = 0
    while j < len(toks):
        t = toks[j].text
        if t in "({[":
            depth += 1
        elif t in ")}]":
            depth -= 1
        elif t == ";" or depth == 0 and t == ",":
            return j
        j += 1
    return j


def _filter_subscribe(args: list[list[Tok]], consts: _Constants) -> bool:
    """Whether ``x.subscribe(args)`` is message_filters' (a node first, the topic second) rather
    than image_transport's (the topic first, then a queue size)."""
    first = args[0]
    if any(t.kind == "id" and (t.text == "this" or "node" in t.text.lower()
                               or t.text == "shared_from_this") for t in first):
        return True
    return len(args) > 1 and _name_of(args[1], consts)[0] is not None


def _is_string(arg: list[Tok]) -> bool:
    return len(arg) == 1 and arg[0].kind == "str"


def _first_template_arg(targ: str | None) -> str | None:
    """``A, B<C, D>`` -> ``A``."""
    if targ is None:
        return None
    depth = 0
    for k, c in enumerate(targ):
        if c == "<":
            depth += 1
        elif c == ">":
            depth -= 1
        elif c == "," and depth == 0:
            return targ[:k]
    return targ

