"""The C++ tokenizer against its previous implementation: the regex scanner must produce exactly
the same token list (kinds, texts, positions, the quirks included) as the character loop it
replaced, on hand-written tricky snippets and on generated text."""
from __future__ import annotations

import re

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from physai_lint.interfaces import extract_cpp
from physai_lint.interfaces.extract_cpp import MAX_SOURCE, Tok, tokenize

# ---- oracle -------------------------------------------------------------------------------------
# The previous implementation of ``tokenize`` (a hand-written character loop), kept verbatim with
# the helpers it used as the reference the faster scanner is checked against. Do not "fix" it: its
# quirks (e.g. a newline swallowed by a char literal is not counted) are part of the contract.

_ID_START_CHARS = frozenset("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz_")
_BLANKS = re.compile(r"[ \t\r\f\v\\]+")
_ID = re.compile(r"[A-Za-z_0-9]*")
_NUM = re.compile(r"(?:0[xX][0-9a-fA-F']+|[0-9][0-9']*\.?[0-9']*(?:[eE][+-]?[0-9]+)?|\.[0-9]+(?:[eE][+-]?[0-9]+)?)[uUlLfF]*")
_STR_PREFIX = ("u8R", "uR", "UR", "LR", "R", "u8", "u", "U", "L")


_new = tuple.__new__  # Tok(...) without NamedTuple's Python-level __new__: a third of tokenizing


def _reference_tokenize(text: str) -> list[Tok]:
    toks: list[Tok] = []
    i, n = 0, min(len(text), MAX_SOURCE)
    line, line_start = 1, 0

    def pos(k: int) -> tuple[int, int]:
        return line, k - line_start + 1

    while i < n:
        c = text[i]
        if c == "\n":
            line += 1
            line_start = i + 1
            i += 1
            continue
        if c in " \t\r\f\v\\":
            i = _BLANKS.match(text, i).end()  # type: ignore[union-attr]
            continue
        if c == "/" and text.startswith("//", i):
            j = text.find("\n", i)
            i = n if j < 0 else j
            continue
        if c == "/" and text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            line += text.count("\n", i, j)
            k = text.rfind("\n", i, j)
            if k >= 0:
                line_start = k + 1
            i = j
            continue
        if c == "#" and text[line_start:i].strip() == "":
            # preprocessor line: keep #define NAME "literal" as tokens, skip the rest
            j = i
            while True:
                k = text.find("\n", j)
                if k < 0:
                    k = n
                    break
                if text[k - 1:k] == "\\":
                    j = k + 1
                    continue
                break
            directive = text[i:k]
            m = re.match(r'#\s*define\s+([A-Za-z_]\w*)\s+"((?:[^"\\]|\\.)*)"\s*$', directive)
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
            i = k
            continue
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
                m = re.match(r'"([^()\\ \t\n]{0,16})\(', text[i:i + 20])
                if not m:
                    i += 1
                    continue
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
            if toks and toks[-1].kind == "str" and toks[-1].end_line > 0:
                prev = toks.pop()
                toks.append(_new(Tok, ("str", prev.text + body, prev.line, prev.col, el, ec)))
            else:
                toks.append(_new(Tok, ("str", body, sl, sc, el, ec)))
            i = end
            continue
        if c == "'":
            j = i + 1
            while j < n and text[j] != "'" and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            sl, sc = pos(i)
            toks.append(_new(Tok, ("char", text[i + 1:j], sl, sc, sl, sc + (j - i + 1))))
            i = j + 1
            continue
        if is_id:
            m = _ID.match(text, i + 1)
            j = m.end() if m else i + 1
            sl, sc = pos(i)
            toks.append(_new(Tok, ("id", text[i:j], sl, sc, sl, sc + (j - i))))
            i = j
            continue
        if c.isdigit() or (c == "." and i + 1 < n and text[i + 1].isdigit()):
            m = _NUM.match(text, i)
            j = m.end() if m and m.end() > i else i + 1
            sl, sc = pos(i)
            toks.append(_new(Tok, ("num", text[i:j], sl, sc, sl, sc + (j - i))))
            i = j
            continue
        two = text[i:i + 2]
        sl, sc = pos(i)
        if two in ("::", "->"):
            toks.append(_new(Tok, ("op", two, sl, sc, sl, sc + 2)))
            i += 2
            continue
        toks.append(_new(Tok, ("op", c, sl, sc, sl, sc + 1)))
        i += 1
    return toks


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



# ---- the new scanner against it ------------------------------------------------------------------


def _same(text: str) -> None:
    new, ref = tokenize(text), _reference_tokenize(text)
    assert new == ref
    assert all(type(t) is Tok for t in new)


SNIPPETS = [
    "",
    "\n",
    "   \t  ",
    "a",
    'auto s = R"d(a"b)d"; f("p" "q");',
    'R"(no delimiter)" R"xyz(with )\" inside)xyz" R"(unterminated',
    'u8R"(u8 raw)" LR"--(wide raw)--" uR"(x)" UR"(y)" R"bad delim with space(x)"',
    'R"0123456789abcdefg(seventeen)0123456789abcdefg"',
    'u8"utf8" u"16" U"32" L"wide" U8"not a prefix" x"y" Lx "z"',
    r'"escaped \" quote" "back\\slash" "\n\t\0\r\q"',
    '"unterminated at the end',
    '"unterminated at a newline\nnext',
    '"continued \\\nstring"',
    '"ends in a backslash\\',
    '"escaped quote at the end\\"',
    'u8"',
    '/* unterminated block comment\n\n',
    '/* one */ a /* two\nlines */ b /*/ tricky */ c /***/ d /**/',
    '// a comment ending in a backslash \\\nnext_line();',
    '// comment at the end',
    '#define NAME "literal"\n#define OTHER "a\\"b" \n#define MULTI \\\n  "continued"\n#define N 3\n',
    '#define TOPIC "/scan"\nauto p = create_publisher<T>(TOPIC, 10);',
    '  # include <vector>\n\t#  define X "y"\n a # b\n/* c */ #define Y "z"\n',
    '#if 0\n"str" \n#endif\n"after"',
    "#define CONT \\\r\n still\n",
    "int x = 1'000'000 + 0x1F'FF + 0XabcUL + 1e-3f + 1.5e+10 + .5 + 3. + 1E5L + 0x + 1e + 1.e2;",
    "a::b::c(); p->q; x.y; r.0; s .. t ... u; a:::b; -->",
    r"char c = '\''; char d = '\\'; char e = 'ab'; char f = '\n'; '",
    "'unterminated char\nnext line col",
    "'escaped newline \\\nstill char' after",
    "'\\",
    "'a\\",
    "line1\r\nline2\r\n\tcol\r\n",
    "\tint\ta;\t// tab\n\t\tb;",
    'std::string s = "héllo wörld"; int naïve = 1; auto π = 3.14; x.\u0663 \u0663 \u00b2 \u00a0 y',
    "a\x00b\x1fc\x7fd\x0be\x0cf",
    "x \\\n y \\ z",
    "`$@ ? ~ ^ | & % ! { } [ ] < > = , ; + - * /",
]


@pytest.mark.parametrize("text", SNIPPETS)
def test_snippet_same_as_reference(text: str) -> None:
    _same(text)


def test_all_snippets_joined_same_as_reference() -> None:
    _same("\n".join(SNIPPETS))
    _same("".join(SNIPPETS))


@pytest.mark.parametrize("cut", range(60))
def test_truncated_source_same_as_reference(cut: int, monkeypatch: pytest.MonkeyPatch) -> None:
    # a source longer than MAX_SOURCE: both stop at the cut, and both look past it the same way
    text = 'ab::c->d 12e+5 "str" \'c\' /* x */ // y\n#define A "b"\nR"(raw)" u8"z" 0x1f.5\n' * 2
    monkeypatch.setattr(extract_cpp, "MAX_SOURCE", cut)
    monkeypatch.setitem(globals(), "MAX_SOURCE", cut)
    _same(text)


_CPP_CHARS = "\"'/\\*#\n\r\tRLu8 ()::abc_0123.eE+-x"


@settings(max_examples=3000, deadline=None)
@given(st.text(alphabet=_CPP_CHARS, max_size=80))
def test_generated_text_same_as_reference(text: str) -> None:
    _same(text)


@settings(max_examples=500, deadline=None)
@given(st.lists(st.sampled_from(SNIPPETS + list(_CPP_CHARS) + ["é", "\u0663"]), max_size=12))
def test_snippet_mixtures_same_as_reference(parts: list[str]) -> None:
    _same("".join(parts))
