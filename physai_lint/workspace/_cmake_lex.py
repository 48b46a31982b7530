"""CMake lexing: commands with their arguments (comments, quoted and bracket arguments, nested
parentheses, line numbers). Never raises: malformed input just ends the command list."""
from __future__ import annotations

import re
from dataclasses import dataclass


@dataclass(frozen=True)
class Arg:
    value: str
    quoted: bool
    line: int


@dataclass(frozen=True)
class Command:
    name: str  # lower-case
    args: tuple[Arg, ...]
    line: int


_IDENT = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")
_BRACKET_OPEN = re.compile(r"\[(=*)\[")


def tokenize(text: str) -> list[Command]:
    """Split CMake source into commands. Malformed input never raises: the rest is dropped."""
    cmds: list[Command] = []
    i, n, line = 0, len(text), 1

    def skip_bracket(pos: int) -> int | None:
        m = _BRACKET_OPEN.match(text, pos)
        if not m:
            return None
        close = "]" + m.group(1) + "]"
        end = text.find(close, m.end())
        return n if end < 0 else end + len(close)

    while i < n:
        c = text[i]
        if c == "\n":
            line += 1
            i += 1
        elif c in " \t\r":
            i += 1
        elif c == "#":
            end = skip_bracket(i + 1)
            if end is not None:
                line += text.count("\n", i, end)
                i = end
            else:
                j = text.find("\n", i)
                i = n if j < 0 else j
        else:
            m = _IDENT.match(text, i)
            if not m:
                i += 1
                continue
            name, cmd_line = m.group(0).lower(), line
            j = m.end()
            while j < n and text[j] in " \t":
                j += 1
            if j >= n or text[j] != "(":
                i = j
                continue
            i = j + 1
            args: list[Arg] = []
            depth = 0
            while i < n:
                c = text[i]
                if c == "\n":
                    line += 1
                    i += 1
                elif c in " \t\r":
                    i += 1
                elif c == "(":
                    depth += 1
                    args.append(Arg("(", False, line))
                    i += 1
                elif c == ")":
                    if depth == 0:
                        i += 1
                        break
                    depth -= 1
                    args.append(Arg(")", False, line))
                    i += 1
                elif c == "#":
                    end = skip_bracket(i + 1)
                    if end is not None:
                        line += text.count("\n", i, end)
                        i = end
                    else:
                        k = text.find("\n", i)
                        i = n if k < 0 else k
                elif c == '"':
                    start_line = line
                    buf: list[str] = []
                    i += 1
                    while i < n and text[i] != '"':
                        ch = text[i]
                        if ch == "\\" and i + 1 < n:
                            nxt = text[i + 1]
                            if nxt == "\n":
                                line += 1
                            else:
                                buf.append({"n": "\n", "t": "\t", "r": "\r", ";": "\\;"}.get(nxt, nxt))
                            i += 2
                            continue
                        if ch == "\n":
                            line += 1
                        buf.append(ch)
                        i += 1
                    i += 1
                    args.append(Arg("".join(buf), True, start_line))
                elif c == "[" and _BRACKET_OPEN.match(text, i):
                    m2 = _BRACKET_OPEN.match(text, i)
                    assert m2 is not None
                    end = skip_bracket(i)
                    assert end is not None
                    close_len = len(m2.group(1)) + 2
                    body = text[m2.end() : max(m2.end(), end - close_len)]
                    body = body.removeprefix("\n")
                    args.append(Arg(body, True, line))
                    line += text.count("\n", i, end)
                    i = end
                else:
                    start = i
                    buf2: list[str] = []
                    while i < n and text[i] not in ' \t\r\n()#"':
                        if text[i] == "\\" and i + 1 < n:
                            buf2.append(text[i : i + 2] if text[i + 1] == ";" else text[i + 1])
                            i += 2
                            continue
                        if text[i] == "$" and i + 1 < n and text[i + 1] == "{":
                            # keep ${...} intact even if it holds spaces/quotes
                            k = text.find("}", i)
                            if k < 0:
                                k = n - 1
                            buf2.append(text[i : k + 1])
                            i = k + 1
                            continue
                        buf2.append(text[i])
                        i += 1
                    if i == start:
                        i += 1
                        continue
                    args.append(Arg("".join(buf2), False, line))
            cmds.append(Command(name, tuple(args), cmd_line))
    return cmds
