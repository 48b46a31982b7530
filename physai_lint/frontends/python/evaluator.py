"""Statement evaluation over stdlib ``ast`` nodes (expressions: ``expressions.py``; calls:
``calls.py``).

Bounded: a global step budget, a per-loop iteration limit and a call-depth limit; exceeding one
turns the affected call's result into ``Opaque``. ``RecursionError`` is caught the same way.
"""
from __future__ import annotations

import ast
from collections import Counter
from collections.abc import Callable
from difflib import SequenceMatcher
from typing import Any

from physai_lint.model.launch import Condition
from physai_lint.model.span import Span
from physai_lint.model.values import Unknown as UnknownValue

from . import bounds, calls, classes, matching, symbolic
from .core import (
    BUILTIN_NAMES,
    MAX_DEPTH,
    MAX_LOOP,
    MAX_STEPS,
    NO,
    Abort,
    Break,
    Continue,
    ModuleCtx,
    Raise,
    Return,
    Scope,
    is_concrete,
    truth,
)
from .expressions import ExpressionsMixin
from .positions import SpanMaker
from .runtime import (
    Alternatives,
    Branched,
    CondTag,
    LaunchConfigsSym,
    LObj,
    ModuleValue,
    Opaque,
    Ref,
    SymBool,
    UserFunc,
)

__all__ = ["BUILTIN_NAMES", "MAX_DEPTH", "Abort", "Evaluator", "ModuleCtx", "Scope", "is_concrete", "truth"]



# What an API of another distro raises (a keyword argument, a module or a name that is not
# there): the handlers of a ``try`` that catches only these are that distro's fallback.
_COMPAT_ERRORS = frozenset({"TypeError", "ImportError", "ModuleNotFoundError", "AttributeError", "NameError"})


def _catches_only(handler: ast.ExceptHandler, names: frozenset[str]) -> bool:
    """The handler names its exception classes, all of them among ``names``."""
    t = handler.type
    types = t.elts if isinstance(t, ast.Tuple) else [t] if t is not None else []
    return bool(types) and all(
        (x.id if isinstance(x, ast.Name) else x.attr if isinstance(x, ast.Attribute) else None) in names
        for x in types)


class Evaluator(ExpressionsMixin, symbolic.Recorder):
    def __init__(self, path: str, text: str, read_file: Callable[[str], str | None] | None,
                 distro: str | None = None) -> None:
        super().__init__()
        self.path = path
        # The only environment the file may see: the distro it is checked against.
        self.env: dict[str, str] = {"ROS_DISTRO": distro} if distro else {}
        self.read_file = read_file
        self.main = ModuleCtx(path, SpanMaker(path, text), "")
        self.steps = 0
        self.depth = 0
        self.bounds = bounds.SizeGuard()
        self.cond_stack: list[CondTag] = []
        # per function being run: its early returns from undecided ``if``s, each with the tags of
        # (the branch that returned, the rest of the function)
        self.pending: list[list[tuple[Any, tuple[CondTag, CondTag]]]] = []
        # per ``if`` statement run: the outcomes of its test ({True, False} when undecided)
        self.branches: dict[ast.If, set[bool]] = {}
        self.try_outcomes: dict[ast.AST, set[bool]] = {}  # True: the body completed; False: it raised
        self.frame_tags: list[int] = []
        self.modules: dict[str, Any] = {}
        self.frames: list[tuple[UserFunc, Scope]] = []  # user functions being called, innermost last

    # ---- bookkeeping ----------------------------------------------------------------------
    def tick(self) -> None:
        self.steps += 1
        if self.steps > MAX_STEPS:
            raise Abort("evaluation step budget exhausted")

    def span(self, node: ast.AST, scope: Scope) -> Span:
        mod = scope.module or self.main
        return mod.spans.of(node)

    # ---- statements -----------------------------------------------------------------------
    def exec_block(self, stmts: list[ast.stmt], scope: Scope) -> None:
        for s in stmts:
            self.tick()
            handler = getattr(self, "st_" + type(s).__name__, None)
            if handler is not None:
                handler(s, scope)

    def st_Expr(self, s: ast.Expr, scope: Scope) -> None:
        self.ev(s.value, scope)

    def st_Assign(self, s: ast.Assign, scope: Scope) -> None:
        value = self.ev(s.value, scope)
        for t in s.targets:
            self.assign(t, value, scope)

    def st_AnnAssign(self, s: ast.AnnAssign, scope: Scope) -> None:
        if s.value is not None:
            self.assign(s.target, self.ev(s.value, scope), scope)

    def st_AugAssign(self, s: ast.AugAssign, scope: Scope) -> None:
        cur = self.ev(s.target, scope)
        rhs = self.ev(s.value, scope)
        if isinstance(s.op, ast.Add) and isinstance(cur, list) and isinstance(rhs, (list, tuple)) \
                and len(cur) + self.bounds.weight(rhs) <= bounds.MAX_WEIGHT:
            cur.extend(rhs)  # in place, like list.__iadd__
            return
        value = self.binop(s.op, cur, rhs, s, scope)
        if self.bounds.too_big(value):
            value = Opaque("value too large to analyse", self.span(s, scope))
        self.assign(s.target, value, scope)

    def assign(self, t: ast.expr, value: Any, scope: Scope) -> None:
        if isinstance(t, ast.Name):
            scope.set(t.id, value)
        elif isinstance(t, (ast.Tuple, ast.List)):
            items = calls.iterate(self, value)
            stars = [i for i, e in enumerate(t.elts) if isinstance(e, ast.Starred)]
            n = len(t.elts)
            if items is not None and stars and len(items) >= n - 1:
                k = stars[0]
                tail = len(items) - (n - k - 1)
                items = items[:k] + [list(items[k:tail])] + items[tail:]
            if items is None or len(items) != n:
                reason = value.reason if isinstance(value, Opaque) else "cannot unpack value"
                items = [Opaque(reason, self.span(t, scope))] * n
            for e, v in zip(t.elts, items):
                self.assign(e.value if isinstance(e, ast.Starred) else e, v, scope)
        elif isinstance(t, ast.Subscript):
            obj = self.ev(t.value, scope)
            key = self.ev(t.slice, scope)
            if isinstance(obj, (dict, list)):
                try:
                    obj[key] = value
                except Exception:  # noqa: BLE001, S110 - a failing store leaves the container as it was
                    pass
            elif isinstance(obj, LaunchConfigsSym):
                if isinstance(key, str):
                    self.config_sets.append((key, value, self.span(t, scope)))
                else:  # a name known only at launch time: it may set any configuration
                    self.config_sets.append(("", value, self.span(t, scope)))
            else:  # stored into an object the evaluator does not follow: it may read it later
                self.escape([value])
        elif isinstance(t, ast.Starred):
            self.assign(t.value, value, scope)
        elif isinstance(t, ast.Attribute):
            if not classes.set_attr(self.ev(t.value, scope), t.attr, value):
                self.escape([value])  # loader.use_camera = LaunchConfiguration(...) on an unknown loader

    def st_FunctionDef(self, s: ast.FunctionDef, scope: Scope) -> None:
        value: Any = self.make_func(s, scope)
        for dec in reversed(s.decorator_list):
            value = classes.decorate(self, dec, value, scope, self.span(s, scope))
        scope.set(s.name, value)

    st_AsyncFunctionDef = st_FunctionDef

    def make_func(self, s: ast.FunctionDef | ast.AsyncFunctionDef | ast.Lambda, scope: Scope) -> UserFunc:
        a = s.args
        defaults = [self.ev(d, scope) for d in a.defaults]
        kw_defaults = {arg.arg: self.ev(d, scope) for arg, d in zip(a.kwonlyargs, a.kw_defaults) if d is not None}
        closure = scope.outer if isinstance(scope, classes.ClassScope) else scope
        return UserFunc(s, closure, scope.module, defaults, kw_defaults)

    def st_ClassDef(self, s: ast.ClassDef, scope: Scope) -> None:
        scope.set(s.name, classes.define_class(self, s, scope))

    def st_Return(self, s: ast.Return, scope: Scope) -> None:
        raise Return(self.ev(s.value, scope) if s.value is not None else None)

    def st_Pass(self, s: ast.Pass, scope: Scope) -> None:
        return None

    def st_Break(self, s: ast.Break, scope: Scope) -> None:
        raise Break()

    def st_Continue(self, s: ast.Continue, scope: Scope) -> None:
        raise Continue()

    def st_Raise(self, s: ast.Raise, scope: Scope) -> None:
        raise Raise()

    def st_Global(self, s: ast.Global, scope: Scope) -> None:
        scope.globals_decl.update(s.names)

    def st_Nonlocal(self, s: ast.Nonlocal, scope: Scope) -> None:
        scope.nonlocal_decl.update(s.names)

    def st_Assert(self, s: ast.Assert, scope: Scope) -> None:
        if self.tested(self.ev(s.test, scope), s.test, scope) is False:
            raise Raise()  # AssertionError; an unknown test may pass

    def st_Delete(self, s: ast.Delete, scope: Scope) -> None:
        for t in s.targets:
            if isinstance(t, ast.Name):
                scope.vars.pop(t.id, None)

    def st_Import(self, s: ast.Import, scope: Scope) -> None:
        for alias in s.names:
            if alias.asname:
                scope.set(alias.asname, calls.import_module(self, alias.name, 0, scope))
            else:
                top = alias.name.split(".")[0]
                scope.set(top, calls.import_module(self, top, 0, scope))

    def st_ImportFrom(self, s: ast.ImportFrom, scope: Scope) -> None:
        mod = calls.import_module(self, s.module or "", s.level, scope)
        for alias in s.names:
            if alias.name == "*":
                if isinstance(mod, ModuleValue):
                    scope.vars.update({k: v for k, v in mod.globals.items() if not k.startswith("_")})
                elif isinstance(mod, Ref) and mod.qual:
                    # a launch / launch_ros module: the names it binds (those of every distro)
                    from .facts import star_names

                    for name in sorted(star_names(s) or ()):
                        if name[:1].isupper():  # classes; submodules stay unknown names
                            scope.vars[name] = Ref(f"{mod.qual}.{name}")
                continue
            if isinstance(mod, ModuleValue):
                value = mod.globals.get(alias.name, Opaque(f'"{alias.name}" not found in "{mod.name}"'))
            elif isinstance(mod, Ref):
                value = Ref(f"{mod.qual}.{alias.name}" if mod.qual else alias.name)
            else:
                value = mod
            scope.set(alias.asname or alias.name, value)

    def st_If(self, s: ast.If, scope: Scope) -> None:
        test = self.ev(s.test, scope)
        t = self.tested(test, s.test, scope)
        taken = self.branches.setdefault(s, set())
        if t is True:
            taken.add(True)
            self.exec_block(s.body, scope)
        elif t is False:
            taken.add(False)
            self.exec_block(s.orelse, scope)
        else:
            taken.update((True, False))
            self.branch_both(test, s.body, s.orelse, s, scope)

    def dead_lines(self, nodes: list[ast.AST]) -> list[tuple[int, int]]:
        """Line ranges of the ``if`` branches among ``nodes`` that no run of them took (the
        ROS_DISTRO guard of a Dashing-era call), and of the ``except`` handlers of an API mismatch
        (``_COMPAT_ERRORS``) after a ``try`` body that always completed (``try: Node(executable=...)
        except TypeError: Node(node_executable=...)``): code that never runs under this launch."""
        out = []
        for node in nodes:
            if isinstance(node, ast.Try) or type(node).__name__ == "TryStar":
                if self.try_outcomes.get(node) == {True}:
                    out.extend((h.lineno, h.end_lineno or h.lineno) for h in node.handlers  # type: ignore[attr-defined]
                               if _catches_only(h, _COMPAT_ERRORS))
                continue
            taken = self.branches.get(node) if isinstance(node, ast.If) else None
            if taken is None:
                continue  # never reached: nothing known
            for outcome, block in ((True, node.body), (False, node.orelse)):
                if outcome not in taken and block:
                    out.append((block[0].lineno, block[-1].end_lineno or block[-1].lineno))
        return out

    def st_For(self, s: ast.For, scope: Scope) -> None:
        items = calls.iterate(self, self.ev(s.iter, scope))
        if items is None:
            reason = "loop over a value that cannot be evaluated statically"
            self.assign(s.target, Opaque(reason, self.span(s.iter, scope)), scope)
            self.branch_both(Opaque(reason), s.body, [], s, scope)
            return
        if len(items) > MAX_LOOP:
            raise Abort("loop iteration limit exceeded")
        for item in items:
            self.assign(s.target, item, scope)
            try:
                self.exec_block(s.body, scope)
            except Break:
                return
            except Continue:
                continue
        self.exec_block(s.orelse, scope)

    def st_While(self, s: ast.While, scope: Scope) -> None:
        for _ in range(MAX_LOOP):
            t = self.tested(self.ev(s.test, scope), s.test, scope)
            if t is None:
                self.branch_both(Opaque("loop condition cannot be evaluated statically"), s.body, [], s, scope)
                return
            if not t:
                self.exec_block(s.orelse, scope)
                return
            try:
                self.exec_block(s.body, scope)
            except Break:
                return
            except Continue:
                continue
        raise Abort("loop iteration limit exceeded")

    def st_Match(self, s: ast.Match, scope: Scope) -> None:
        matching.run_cases(self, self.ev(s.subject, scope), s.cases, scope)

    def st_MatchRest(self, s: matching.MatchRest, scope: Scope) -> None:
        matching.run_cases(self, s.subject, s.cases, scope)

    def st_Bind(self, s: matching.Bind, scope: Scope) -> None:
        for name, value in s.names.items():
            scope.set(name, value)

    def st_With(self, s: ast.With, scope: Scope) -> None:
        for item in s.items:
            v = self.ev(item.context_expr, scope)
            if item.optional_vars is not None:
                self.assign(item.optional_vars, v, scope)
        self.exec_block(s.body, scope)

    def st_Try(self, s: ast.Try, scope: Scope) -> None:
        outcomes = self.try_outcomes.setdefault(s, set())
        guarded = bool(s.handlers)  # an error raised in the body may be caught
        self.guarded += guarded
        try:
            try:
                self.exec_block(s.body, scope)
            finally:
                self.guarded -= guarded
        except Raise:
            outcomes.add(False)
            if s.handlers:
                self.exec_block(s.handlers[0].body, scope)
        except (Return, Break, Continue):  # the body left without raising
            outcomes.add(True)
            raise
        else:
            outcomes.add(True)
            self.exec_block(s.orelse, scope)
        finally:
            self.exec_block(s.finalbody, scope)

    st_TryStar = st_Try

    def tested(self, v: Any, node: ast.AST, scope: Scope) -> bool | None:
        """``truth(v)`` of a value Python tests as a bool here, noting a substitution object
        (always true: the argument it names decides nothing)."""
        if symbolic.is_subst(v):
            self.substitution_tested("truth", self.span(node, scope), v)
        elif symbolic.is_condition(v):  # IfCondition(a) and UnlessCondition(b): b alone decides
            self.substitution_tested("condition", self.span(node, scope), v)
        return truth(v)

    # ---- branches over values only known at launch time -------------------------------------
    def branch_both(self, test: Any, body: list[ast.stmt], orelse: list[ast.stmt], node: ast.AST,
                    scope: Scope) -> None:
        span = self.span(node, scope)
        if isinstance(test, SymBool):
            kinds = ("unless", "if") if test.negated else ("if", "unless")
            tags = (CondTag(Condition(kinds[0], test.value, span, "if")),
                    CondTag(Condition(kinds[1], test.value, span, "else")))
        else:
            self.undecided += 1
            # Both branches are kept, as launch-time conditions are: what they create gets a condition
            # whose value is unknown (active: unknown), "if" for the body and "unless" for the else.
            reason = test.reason if isinstance(test, Opaque) else "condition cannot be evaluated statically"
            unknown = (UnknownValue(f"a Python condition that cannot be evaluated statically ({reason})", span),)
            tags = (CondTag(Condition("if", unknown, span, "if")), CondTag(Condition("unless", unknown, span, "else")))
        snapshot = dict(scope.vars)
        watched = _lists_of(scope)
        envs: list[dict[str, Any]] = []
        rets: list[Any] = []
        try:
            for k, (tag, block) in enumerate(zip(tags, (body, orelse))):
                scope.vars = dict(snapshot)
                if k:
                    for w in watched:
                        w.start()
                self.cond_stack.append(tag)
                ret = NO
                try:
                    self.exec_block(block, scope)
                except Return as r:
                    ret = r.value
                except (Break, Continue, Raise):
                    pass
                finally:
                    self.cond_stack.pop()
                    for w in watched:
                        w.after(tag)
                envs.append(scope.vars)
                rets.append(ret)
        finally:  # also when the walk is aborted in a branch: both branches' items are kept
            for w in watched:
                w.mark()
        if rets[0] is not NO and rets[1] is not NO:
            raise Return(self.merge(rets[0], rets[1], tags))
        for i in (0, 1):
            if rets[i] is not NO:
                scope.vars = envs[1 - i]
                if self.pending:
                    self.pending[-1].append((rets[i], (tags[i], tags[1 - i])))
                    # the rest of the function runs only when this branch was not taken
                    self.cond_stack.append(tags[1 - i])
                    self.frame_tags[-1] += 1
                return
        merged = dict(envs[0])
        for name, v in envs[1].items():
            merged[name] = self.merge(merged[name], v, tags) if name in merged else v
        scope.vars = merged

    def merge(self, a: Any, b: Any, tags: tuple[CondTag, CondTag] | None = None) -> Any:
        """The value of a name (or a return value) after an ``if`` the evaluator could not decide,
        ``a`` from its body and ``b`` from its else (under ``tags``)."""
        if a is b:
            return a
        if tags is not None:
            options = _made_under(a, tags[0]) + _made_under(b, tags[1])
            if options and len(options) == len(_options(a)) + len(_options(b)):
                return Alternatives("value depends on a condition known only at launch time", None, options)
        if isinstance(a, (list, tuple)) and isinstance(b, (list, tuple)):
            return list(a) + [x for x in b if not any(x is y for y in a)]
        if is_concrete(a) and is_concrete(b):
            try:
                if a == b:
                    return a
            except Exception:  # noqa: BLE001, S110 - user data with a failing __eq__ is just unknown
                pass
        return Opaque("value depends on a condition known only at launch time")

    # ---- functions ------------------------------------------------------------------------
    def run_function(self, body: list[ast.stmt], fscope: Scope) -> Any:
        self.pending.append([])
        self.frame_tags.append(0)
        try:
            try:
                self.exec_block(body, fscope)
                result: Any = None
            except Return as r:
                result = r.value
            except Raise:
                result = Opaque("the function raises an exception")
        finally:
            pend = self.pending.pop()
            extra = self.frame_tags.pop()
            if extra:
                del self.cond_stack[len(self.cond_stack) - extra:]
        for p, tags in reversed(pend):  # the latest early return is decided last, just before the end
            result = p if result is None else self.merge(p, result, tags)
        return result


def _options(v: Any) -> tuple[Any, ...]:
    return v.options if isinstance(v, Alternatives) else (v,)


def _made_under(v: Any, tag: CondTag) -> tuple[Any, ...]:
    """The launch objects ``v`` stands for, when every one of them was made under ``tag`` (so the
    branch's condition follows each of them); else ()."""
    options = _options(v)
    if all(isinstance(o, LObj) and tag in o.tags for o in options):
        return options
    return ()


class _Watched:
    """A list that existed before an undecided ``if``. Each branch starts from the list as it was
    (``start``) and leaves it as it wants (``after``); ``mark`` then puts together what both left,
    by identity: an item both kept is there once, as it is; one only a branch kept or added is
    ``Branched`` under that branch's tag (a ``pop``/``remove`` in the body leaves the item to the
    else, and the other way round), in the order the branches left them."""

    def __init__(self, items: list[Any]) -> None:
        self.items = items
        self.before = list(items)
        self.results: list[tuple[list[Any], CondTag]] = []

    def start(self) -> None:
        if not _same(self.items, self.before):
            self.items[:] = self.before

    def after(self, tag: CondTag) -> None:
        self.results.append((self.before if _same(self.items, self.before) else list(self.items), tag))

    def mark(self) -> None:
        if len(self.results) != 2:
            return  # the walk was aborted in the body: the list stays as the body left it
        (first, tag0), (second, tag1) = self.results
        if first is self.before and second is self.before:
            return  # neither branch touched it
        # the common ends (an append-only branch leaves the whole list before as a prefix) need
        # no matching: what is left is short, and the matcher quadratic in it
        head = 0
        while head < min(len(first), len(second)) and first[head] is second[head]:
            head += 1
        tail = 0
        while tail < min(len(first), len(second)) - head and first[-1 - tail] is second[-1 - tail]:
            tail += 1
        mid0, mid1 = first[head:len(first) - tail], second[head:len(second) - tail]
        # an item both branches hold (reordered, or wrapped by a nested undecided if) is there
        # once: the wrapped form, which keeps the inner condition, when one side has it
        keys0, keys1 = [_key(x) for x in mid0], [_key(x) for x in mid1]
        counts0, counts1 = Counter(keys0), Counter(keys1)
        shared = {k: max(n, counts1[k]) for k, n in counts0.items() if k in counts1}  # how many times
        chosen = {k: x for k, x in zip(keys1, mid1) if k in shared}
        chosen.update((k, x) for k, x in zip(keys0, mid0) if k in shared and (
            isinstance(x, Branched) or not isinstance(chosen.get(k), Branched)))
        old = {_key(x) for x in self.before}
        merged: list[Any] = list(first[:head])
        placed: Counter[int] = Counter()
        for op, i1, i2, j1, j2 in SequenceMatcher(None, keys0, keys1, autojunk=False).get_opcodes():
            sides: tuple[tuple[list[Any], list[int], CondTag], ...] = (
                (mid0[i1:i2], keys0[i1:i2], tag0), (mid1[j1:j2], keys1[j1:j2], tag1))
            if op == "equal":
                sides = sides[:1]
            # where the branches differ: the items that were there before, then the new ones
            for keep in (True, False):
                for part, keys, tag in sides:
                    for x, k in zip(part, keys):
                        if (k in old) != keep:
                            continue
                        if k in shared:
                            if placed[k] < shared[k]:
                                placed[k] += 1
                                merged.append(chosen[k])
                        else:
                            merged.append(self._branched(x, tag))
        merged.extend(first[len(first) - tail:])
        self.items[:] = merged

    @staticmethod
    def _branched(item: Any, tag: CondTag) -> Any:
        return Branched("present only under a condition known only at launch time", None, item, tag)


def _key(item: Any) -> int:
    """An item's identity, through the ``Branched`` wrappers of nested undecided ifs."""
    while isinstance(item, Branched):
        item = item.value
    return id(item)


def _same(a: list[Any], b: list[Any]) -> bool:
    return len(a) == len(b) and all(x is y for x, y in zip(a, b))


def _lists_of(scope: Scope) -> list[_Watched]:
    """The lists a branch could change that ``_Watched`` follows: the list variables of this scope
    and of the scopes around it (the module's included), the lists that are values of their dicts,
    and the entities of their ``LaunchDescription`` objects (``ld.add_action``)."""
    out: dict[int, _Watched] = {}

    def watch(v: Any) -> None:
        if isinstance(v, LObj):
            v = v.extra.get("entities")
        if type(v) is list and id(v) not in out:
            out[id(v)] = _Watched(v)

    s: Scope | None = scope
    while s is not None:
        for v in s.vars.values():
            if type(v) is dict:
                for item in v.values():
                    watch(item)
            else:
                watch(v)
        s = s.parent
    return list(out.values())
