"""Rule selection: ``select`` / ``ignore`` / ``extend-select`` / ``per-file-ignores``.

A selector is ``ALL``, a category letter or code prefix (``L``, ``L1``), a full code (``L101``) or
a rule name (``unknown-package``). As in ruff, the most specific selector that matches a code
decides; on a tie ``ignore`` wins.
"""
from __future__ import annotations

import re
from functools import lru_cache
from typing import Any, Iterable, Mapping

from physai_lint.errors import ConfigError

_PREFIX = re.compile(r"^[A-Z][0-9]{0,3}$")


def split_selectors(values: Iterable[str] | None) -> list[str]:
    """Flatten repeatable, comma-separated selector lists: ``["L1,P", "N101"]`` -> ``["L1", "P", "N101"]``."""
    out: list[str] = []
    for value in values or ():
        out.extend(part.strip() for part in value.split(",") if part.strip())
    return out


class Selector:
    """Which rules are enabled, globally and per file."""

    def __init__(
        self,
        select: list[str] | None,
        ignore: list[str],
        extend_select: list[str],
        per_file_ignores: Mapping[str, list[str]],
        catalog: Mapping[str, Any],
    ) -> None:
        self._codes = {code: str(getattr(doc, "name", "")) for code, doc in catalog.items()}
        self._by_name = {name: code for code, name in self._codes.items() if name}
        chosen = list(select) if select is not None else ["ALL"]
        self._enable = [self._parse(s, "select") for s in [*chosen, *extend_select]]
        self._disable = [self._parse(s, "ignore") for s in ignore]
        self._per_file = [
            (pattern, _glob_regex(pattern), [self._parse(s, f"per-file-ignores {pattern!r}") for s in sels])
            for pattern, sels in sorted(per_file_ignores.items())
        ]

    def _parse(self, selector: str, where: str) -> str:
        """Normalise a selector to ``ALL``, a code or a code prefix; raise on unknown ones."""
        token = selector.strip()
        if token.upper() == "ALL":
            return "ALL"
        if token.lower() in self._by_name:
            return self._by_name[token.lower()]
        upper = token.upper()
        if _PREFIX.match(upper) and (not self._codes or any(c.startswith(upper) for c in self._codes)):
            return upper
        from physai_lint.catalog import suggest

        hint = suggest(token, [*self._codes, *self._by_name])
        extra = f' (did you mean "{hint}"?)' if hint else ""
        raise ConfigError(f'{where}: unknown rule code or name "{selector}"{extra}')

    def enabled(self, code: str) -> bool:
        best_on = _best(code, self._enable)
        best_off = _best(code, self._disable)
        return best_on > best_off

    def enabled_for(self, code: str, relpath: str) -> bool:
        if not self.enabled(code):
            return False
        path = relpath.replace("\\", "/")
        base = path.rsplit("/", 1)[-1]
        for _pattern, regex, sels in self._per_file:
            if (regex.fullmatch(path) or regex.fullmatch(base)) and _best(code, sels) >= 0:
                return False
        return True


def _best(code: str, selectors: list[str]) -> int:
    """Specificity of the most specific selector matching ``code`` (-1: none)."""
    best = -1
    for sel in selectors:
        if sel == "ALL":
            best = max(best, 0)
        elif code.startswith(sel):
            best = max(best, len(sel))
    return best


@lru_cache(maxsize=256)
def _glob_regex(pattern: str) -> re.Pattern[str]:
    """Glob with ``**`` (any number of folders), ``*`` and ``?`` (within one folder)."""
    out, i = [], 0
    pat = pattern.replace("\\", "/").removeprefix("./")
    while i < len(pat):
        if pat.startswith("**/", i):
            out.append("(?:.*/)?")
            i += 3
        elif pat.startswith("**", i):
            out.append(".*")
            i += 2
        elif pat[i] == "*":
            out.append("[^/]*")
            i += 1
        elif pat[i] == "?":
            out.append("[^/]")
            i += 1
        else:
            out.append(re.escape(pat[i]))
            i += 1
    return re.compile("".join(out))


def path_matches(patterns: Iterable[str], relpath: str) -> bool:
    """Whether ``relpath`` or one of its parent folders matches a glob (``exclude``)."""
    parts = relpath.replace("\\", "/").split("/")
    prefixes = ["/".join(parts[: i + 1]) for i in range(len(parts))]
    for pattern in patterns:
        regex = _glob_regex(pattern.rstrip("/"))
        if any(regex.fullmatch(p) for p in prefixes) or ("/" not in pattern.rstrip("/") and any(regex.fullmatch(x) for x in parts)):
            return True
    return False
