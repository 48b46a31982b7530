"""Syntax-level facts: calls of known launch APIs (``CallFact``) and undefined names (``NameFact``).

Both come from one walk of the stdlib ``ast`` tree, independent of what the evaluator reached, so
code in branches the evaluator skipped is still checked.
"""
from __future__ import annotations

import ast
import symtable
from collections.abc import Iterable

from physai_lint.model.launch import CallFact, NameFact

from . import api
from .evaluator import BUILTIN_NAMES
from .positions import SpanMaker

_SCOPES = (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef, ast.Lambda, ast.ListComp, ast.SetComp,
           ast.DictComp, ast.GeneratorExp)


def _import_map(nodes: list[ast.AST]) -> dict[str, str]:
    out: dict[str, str] = {}
    for node in nodes:
        if isinstance(node, ast.Import):
            for a in node.names:
                if a.asname:
                    out[a.asname] = a.name
                else:
                    top = a.name.split(".")[0]
                    out[top] = top
        elif isinstance(node, ast.ImportFrom) and node.level == 0 and node.module:
            for a in node.names:
                if a.name != "*":
                    out[a.asname or a.name] = f"{node.module}.{a.name}"
    return out


def _qual(expr: ast.expr, imports: dict[str, str]) -> str | None:
    if isinstance(expr, ast.Name):
        return imports.get(expr.id)
    if isinstance(expr, ast.Attribute):
        base = _qual(expr.value, imports)
        return f"{base}.{expr.attr}" if base else None
    return None


def _kind(v: ast.expr) -> str:
    if isinstance(v, (ast.List, ast.ListComp)):
        return "list"
    if isinstance(v, (ast.Dict, ast.DictComp)):
        return "dict"
    if isinstance(v, ast.Tuple):
        return "tuple"
    if isinstance(v, ast.Constant):
        c = v.value
        if isinstance(c, bool):
            return "bool"
        if c is None:
            return "none"
        if isinstance(c, (int, float, complex)):
            return "number"
        if isinstance(c, str):
            return "str"
        return "other"
    if isinstance(v, ast.JoinedStr):
        return "str"
    if isinstance(v, ast.Call):
        return "call"
    if isinstance(v, (ast.Name, ast.Attribute)):
        return "name"
    return "other"


def call_facts(nodes: list[ast.AST], spans: SpanMaker, evaluated: dict[tuple[int, str], str]) -> list[CallFact]:
    imports = _import_map(nodes)
    out: list[CallFact] = []
    for node in nodes:
        if not isinstance(node, ast.Call):
            continue
        q = _qual(node.func, imports)
        canon = api.canonical(q) if q else None
        if canon is None:
            continue
        kwargs = tuple((kw.arg, spans.keyword(kw)) for kw in node.keywords if kw.arg is not None)
        kinds = []
        for kw in node.keywords:
            if kw.arg is None:
                continue
            k = _kind(kw.value)
            if k in ("name", "call", "other"):
                k = evaluated.get((id(node), kw.arg), k)
            kinds.append((kw.arg, k))
        splat = any(kw.arg is None for kw in node.keywords) or any(isinstance(a, ast.Starred) for a in node.args)
        out.append(CallFact(canon, spans.of(node), kwargs, len(node.args), tuple(kinds), splat))
    out.sort(key=lambda f: (f.span.line, f.span.col))
    return out


# ---- undefined names --------------------------------------------------------------------------


def _bound_in(nodes: Iterable[ast.AST]) -> set[str]:
    """Names bound directly in a scope (not descending into nested scopes)."""
    out: set[str] = set()
    stack = list(nodes)
    while stack:
        n = stack.pop()
        if isinstance(n, ast.Name) and not isinstance(n.ctx, ast.Load):
            out.add(n.id)
        elif isinstance(n, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
            out.add(n.name)
            stack.extend(n.decorator_list)
            continue
        elif isinstance(n, (ast.Import, ast.ImportFrom)):
            for a in n.names:
                out.add(a.asname or a.name.split(".")[0])
        elif isinstance(n, ast.ExceptHandler) and n.name or isinstance(n, (ast.MatchAs, ast.MatchStar)) and n.name:
            out.add(n.name)
        elif isinstance(n, ast.MatchMapping) and n.rest:
            out.add(n.rest)
        elif isinstance(n, (ast.Global, ast.Nonlocal)):
            out.update(n.names)
        if isinstance(n, _SCOPES[3:]):
            continue
        stack.extend(ast.iter_child_nodes(n))
    return out


def _params(a: ast.arguments) -> set[str]:
    names = [x.arg for x in a.posonlyargs + a.args + a.kwonlyargs]
    if a.vararg:
        names.append(a.vararg.arg)
    if a.kwarg:
        names.append(a.kwarg.arg)
    return set(names)


class _NameChecker:
    def __init__(self, spans: SpanMaker, module_bound: set[str]) -> None:
        self.spans = spans
        self.module = module_bound
        self.found: list[NameFact] = []

    def check(self, node: ast.AST, chain: list[tuple[set[str], bool]]) -> None:
        # (node, the scopes around it, the function whose body holds it: "" at module level)
        stack: list[tuple[ast.AST, list[tuple[set[str], bool]], str]] = [(node, chain, "")]
        while stack:
            n, ch, fn = stack.pop()
            if isinstance(n, (ast.FunctionDef, ast.AsyncFunctionDef, ast.Lambda)):
                a = n.args
                outer = list(a.defaults) + [d for d in a.kw_defaults if d is not None]
                if not isinstance(n, ast.Lambda):
                    outer += n.decorator_list
                    if n.returns is not None:
                        outer.append(n.returns)
                outer += [x.annotation for x in a.posonlyargs + a.args + a.kwonlyargs if x.annotation is not None]
                stack.extend((x, ch, fn) for x in outer)
                body = n.body if isinstance(n.body, list) else [n.body]
                inner = ch + [(_params(a) | _bound_in(body), False)]
                name = fn if isinstance(n, ast.Lambda) else n.name
                stack.extend((x, inner, name) for x in body)
                continue
            if isinstance(n, ast.ClassDef):
                stack.extend((x, ch, fn) for x in n.bases + n.decorator_list + [k.value for k in n.keywords])
                inner = ch + [(_bound_in(n.body), True)]
                stack.extend((x, inner, fn) for x in n.body)
                continue
            if isinstance(n, (ast.ListComp, ast.SetComp, ast.DictComp, ast.GeneratorExp)):
                gens = n.generators
                stack.append((gens[0].iter, ch, fn))
                inner = ch + [(_bound_in([g.target for g in gens]), False)]
                rest: list[ast.AST] = [gens[0].target, *gens[0].ifs]
                for g in gens[1:]:
                    rest += [g.target, g.iter, *g.ifs]
                rest += [n.key, n.value] if isinstance(n, ast.DictComp) else [n.elt]
                stack.extend((x, inner, fn) for x in rest)
                continue
            if isinstance(n, ast.Name) and isinstance(n.ctx, ast.Load):
                if not self._defined(n.id, ch):
                    self.found.append(NameFact(n.id, self.spans.of(n), fn, self._visible(ch)))
                continue
            stack.extend((c, ch, fn) for c in ast.iter_child_nodes(n))

    def _visible(self, chain: list[tuple[set[str], bool]]) -> tuple[str, ...]:
        """The names a load at the end of ``chain`` can see (for a did-you-mean)."""
        out = set(self.module)
        for k, (bound, is_class) in enumerate(reversed(chain)):
            if not (is_class and k > 0):
                out |= bound
        return tuple(sorted(out))

    def _defined(self, name: str, chain: list[tuple[set[str], bool]]) -> bool:
        for k, (bound, is_class) in enumerate(reversed(chain)):
            if is_class and k > 0:
                continue
            if name in bound:
                return True
        return name in self.module or name in BUILTIN_NAMES


def _candidates(text: str, path: str) -> set[str]:
    """Names some scope reads without binding them (stdlib ``symtable``, fast); a superset of
    the undefined names, refined by the scope walk below only when it is not empty."""
    out: set[str] = set()
    stack = [symtable.symtable(text, path, "exec")]
    while stack:
        t = stack.pop()
        stack.extend(t.get_children())
        for sym in t.get_symbols():
            if sym.is_referenced() and not (sym.is_assigned() or sym.is_imported() or sym.is_parameter()
                                            or sym.is_free()):
                out.add(sym.get_name())
    return out


def star_names(n: ast.ImportFrom) -> frozenset[str] | None:
    """What ``from <module> import *`` may bind: for a public launch / launch_ros module, at most
    the names it binds in some distro (``launch-exports.json``); None for any other module."""
    if n.level or not n.module or n.module.split(".")[0] not in _LAUNCH_PACKAGES:
        return None
    from physai_lint.workspace.distro import launch_exports

    tables = [t[n.module] for t in launch_exports().values() if n.module in t]
    return frozenset().union(*tables) if tables else None


def undefined_names(tree: ast.Module, nodes: list[ast.AST], spans: SpanMaker, text: str) -> list[NameFact]:
    star_bound: set[str] = set()
    for n in nodes:
        if isinstance(n, ast.ImportFrom) and any(a.name == "*" for a in n.names):
            names = star_names(n)
            if names is None:
                return []  # any name may come from it
            star_bound |= names
    module_bound = _bound_in(tree.body) | star_bound
    for n in nodes:
        if isinstance(n, ast.Global):
            module_bound.update(n.names)
    try:
        cands = _candidates(text, spans.path) - module_bound - BUILTIN_NAMES
    except (SyntaxError, ValueError, RecursionError, MemoryError):
        cands = {"*"}
    if not cands:
        return []
    checker = _NameChecker(spans, module_bound)
    for stmt in tree.body:
        checker.check(stmt, [])
    checker.found.sort(key=lambda f: (f.span.line, f.span.col))
    return checker.found


_LAUNCH_PACKAGES = ("launch", "launch_ros", "launch_xml", "launch_yaml")


def launch_imports(tree: ast.Module, spans: SpanMaker) -> list[tuple[str, str, Span]]:
    """``from <launch package module> import <name>`` anywhere in the file: (module, name, span of
    the name), but not inside the body of a ``try`` with handlers (``try: from launch_ros.actions
    import PushROSNamespace except ImportError: ...`` is how files support several distros).
    Imports are statements: only statement lists are walked, not expressions."""
    out: list[tuple[str, str, Span]] = []
    stack: list[tuple[list[ast.stmt], bool]] = [(tree.body, False)]
    while stack:
        body, guarded = stack.pop()
        for node in body:
            if isinstance(node, ast.ImportFrom):
                if not guarded and not node.level and node.module \
                        and node.module.split(".")[0] in _LAUNCH_PACKAGES:
                    out.extend((node.module, alias.name, spans.of(alias)) for alias in node.names
                               if alias.name != "*")
            elif isinstance(node, ast.Try) or type(node).__name__ == "TryStar":
                stack.append((node.body, guarded or bool(node.handlers)))  # type: ignore[attr-defined]
                stack.extend((h.body, guarded) for h in node.handlers)  # type: ignore[attr-defined]
                stack.extend(((node.orelse, guarded), (node.finalbody, guarded)))  # type: ignore[attr-defined]
            elif type(node).__name__ == "Match":
                stack.extend((case.body, guarded) for case in node.cases)  # type: ignore[attr-defined]
            else:
                for field in ("body", "orelse", "finalbody"):
                    block = getattr(node, field, None)
                    if isinstance(block, list) and block and isinstance(block[0], ast.stmt):
                        stack.append((block, guarded))
    out.sort(key=lambda i: (i[2].line, i[2].col))
    return out
