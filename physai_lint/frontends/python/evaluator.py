"""Statement and expression evaluation over stdlib ``ast`` nodes (calls live in ``calls.py``).

Bounded: a global step budget, a per-loop iteration limit and a call-depth limit; exceeding one
turns the affected call's result into ``Opaque``. ``RecursionError`` is caught the same way.
"""
from __future__ import annotations

import ast
import builtins
import operator
from typing import Any, Callable

from physai_lint.model.launch import Condition
from physai_lint.model.span import Span

from . import calls, symbolic
from .positions import SpanMaker
from .runtime import CondTag, ModuleValue, Opaque, Ref, SStr, SymBool, UserFunc

MAX_STEPS = 400_000
MAX_LOOP = 10_000
MAX_DEPTH = 50

BUILTIN_NAMES = frozenset(dir(builtins)) | {"__file__", "__name__", "__doc__", "__spec__", "__package__"}
_NO = object()


class Abort(Exception):
    def __init__(self, reason: str) -> None:
        super().__init__(reason)
        self.reason = reason


class _Return(Exception):
    def __init__(self, value: Any) -> None:
        self.value = value


class _Break(Exception):
    pass


class _Continue(Exception):
    pass


class _Raise(Exception):
    pass


class Scope:
    __slots__ = ("vars", "parent", "module", "globals_decl")

    def __init__(self, parent: "Scope | None", module: "ModuleCtx | None") -> None:
        self.vars: dict[str, Any] = {}
        self.parent = parent
        self.module = module
        self.globals_decl: set[str] = set()

    def set(self, name: str, value: Any) -> None:
        if name in self.globals_decl and self.module is not None:
            self.module.scope.vars[name] = value
        else:
            self.vars[name] = value


class ModuleCtx:
    def __init__(self, path: str, spans: SpanMaker, prefix: str) -> None:
        self.path = path
        self.spans = spans
        self.prefix = prefix  # id prefix for actions created in helper modules
        self.scope = Scope(None, self)


_BINOPS: dict[type, Callable[[Any, Any], Any]] = {
    ast.Add: operator.add, ast.Sub: operator.sub, ast.Mult: operator.mul, ast.Div: operator.truediv,
    ast.FloorDiv: operator.floordiv, ast.Mod: operator.mod, ast.Pow: operator.pow,
    ast.BitAnd: operator.and_, ast.BitOr: operator.or_, ast.BitXor: operator.xor,
    ast.LShift: operator.lshift, ast.RShift: operator.rshift,
}
_CMPOPS: dict[type, Callable[[Any, Any], Any]] = {
    ast.Eq: operator.eq, ast.NotEq: operator.ne, ast.Lt: operator.lt, ast.LtE: operator.le,
    ast.Gt: operator.gt, ast.GtE: operator.ge, ast.Is: operator.is_, ast.IsNot: operator.is_not,
    ast.In: lambda a, b: a in b, ast.NotIn: lambda a, b: a not in b,
}
_CONCRETE = (str, int, float, bool, bytes, type(None), list, tuple, dict, set, frozenset)


def is_concrete(v: Any) -> bool:
    if isinstance(v, (list, tuple, set, frozenset)):
        return all(is_concrete(x) for x in v)
    if isinstance(v, dict):
        return all(is_concrete(k) and is_concrete(x) for k, x in v.items())
    return isinstance(v, _CONCRETE)


def truth(v: Any) -> bool | None:
    """Python truthiness when known, else None."""
    if isinstance(v, (Opaque, SymBool)) or symbolic.is_symstr(v):
        return None
    if isinstance(v, (str, int, float, bool, bytes, type(None), list, tuple, dict, set)):
        return bool(v)
    return True


class Evaluator(symbolic.Recorder):
    def __init__(self, path: str, text: str, read_file: Callable[[str], str | None] | None) -> None:
        super().__init__()
        self.path = path
        self.read_file = read_file
        self.main = ModuleCtx(path, SpanMaker(path, text), "")
        self.steps = 0
        self.depth = 0
        self.cond_stack: list[CondTag] = []
        self.pending: list[list[Any]] = []
        self.frame_tags: list[int] = []
        self.modules: dict[str, Any] = {}

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
        cur = self.ev(s.target, scope) if not isinstance(s.target, ast.Attribute) else Opaque("attribute")
        rhs = self.ev(s.value, scope)
        if isinstance(s.op, ast.Add) and isinstance(cur, list) and isinstance(rhs, (list, tuple)):
            cur.extend(rhs)  # in place, like list.__iadd__
            return
        self.assign(s.target, self.binop(s.op, cur, rhs, s, scope), scope)

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
                except Exception:
                    pass
        elif isinstance(t, ast.Starred):
            self.assign(t.value, value, scope)

    def st_FunctionDef(self, s: ast.FunctionDef, scope: Scope) -> None:
        scope.set(s.name, self.make_func(s, scope))

    st_AsyncFunctionDef = st_FunctionDef

    def make_func(self, s: ast.FunctionDef | ast.AsyncFunctionDef | ast.Lambda, scope: Scope) -> UserFunc:
        a = s.args
        defaults = [self.ev(d, scope) for d in a.defaults]
        kw_defaults = {arg.arg: self.ev(d, scope) for arg, d in zip(a.kwonlyargs, a.kw_defaults) if d is not None}
        return UserFunc(s, scope, scope.module, defaults, kw_defaults)

    def st_ClassDef(self, s: ast.ClassDef, scope: Scope) -> None:
        scope.set(s.name, Opaque(f'class "{s.name}" is not evaluated', self.span(s, scope)))

    def st_Return(self, s: ast.Return, scope: Scope) -> None:
        raise _Return(self.ev(s.value, scope) if s.value is not None else None)

    def st_Pass(self, s: ast.Pass, scope: Scope) -> None:
        return None

    def st_Break(self, s: ast.Break, scope: Scope) -> None:
        raise _Break()

    def st_Continue(self, s: ast.Continue, scope: Scope) -> None:
        raise _Continue()

    def st_Raise(self, s: ast.Raise, scope: Scope) -> None:
        raise _Raise()

    def st_Global(self, s: ast.Global, scope: Scope) -> None:
        scope.globals_decl.update(s.names)

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
        t = truth(test)
        if t is True:
            self.exec_block(s.body, scope)
        elif t is False:
            self.exec_block(s.orelse, scope)
        else:
            self.branch_both(test, s.body, s.orelse, s, scope)

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
            except _Break:
                return
            except _Continue:
                continue
        self.exec_block(s.orelse, scope)

    def st_While(self, s: ast.While, scope: Scope) -> None:
        for _ in range(MAX_LOOP):
            t = truth(self.ev(s.test, scope))
            if t is None:
                self.branch_both(Opaque("loop condition cannot be evaluated statically"), s.body, [], s, scope)
                return
            if not t:
                self.exec_block(s.orelse, scope)
                return
            try:
                self.exec_block(s.body, scope)
            except _Break:
                return
            except _Continue:
                continue
        raise Abort("loop iteration limit exceeded")

    def st_With(self, s: ast.With, scope: Scope) -> None:
        for item in s.items:
            v = self.ev(item.context_expr, scope)
            if item.optional_vars is not None:
                self.assign(item.optional_vars, v, scope)
        self.exec_block(s.body, scope)

    def st_Try(self, s: ast.Try, scope: Scope) -> None:
        try:
            self.exec_block(s.body, scope)
        except _Raise:
            if s.handlers:
                self.exec_block(s.handlers[0].body, scope)
        else:
            self.exec_block(s.orelse, scope)
        finally:
            self.exec_block(s.finalbody, scope)

    # ---- branches over values only known at launch time -------------------------------------
    def branch_both(self, test: Any, body: list[ast.stmt], orelse: list[ast.stmt], node: ast.AST,
                    scope: Scope) -> None:
        span = self.span(node, scope)
        if isinstance(test, SymBool):
            kinds = ("unless", "if") if test.negated else ("if", "unless")
            tags = (CondTag(Condition(kinds[0], test.value, span, "if")),
                    CondTag(Condition(kinds[1], test.value, span, "else")))
        else:
            reason = test.reason if isinstance(test, Opaque) else "condition cannot be evaluated statically"
            tags = (CondTag(None, f"created under a condition that cannot be evaluated statically ({reason})"),) * 2
        snapshot = dict(scope.vars)
        envs: list[dict[str, Any]] = []
        rets: list[Any] = []
        for tag, block in zip(tags, (body, orelse)):
            scope.vars = dict(snapshot)
            self.cond_stack.append(tag)
            ret = _NO
            try:
                self.exec_block(block, scope)
            except _Return as r:
                ret = r.value
            except (_Break, _Continue, _Raise):
                pass
            finally:
                self.cond_stack.pop()
            envs.append(scope.vars)
            rets.append(ret)
        if rets[0] is not _NO and rets[1] is not _NO:
            raise _Return(self.merge(rets[0], rets[1]))
        for i in (0, 1):
            if rets[i] is not _NO:
                scope.vars = envs[1 - i]
                if self.pending:
                    self.pending[-1].append(rets[i])
                    # the rest of the function runs only when this branch was not taken
                    self.cond_stack.append(tags[1 - i])
                    self.frame_tags[-1] += 1
                return
        merged = dict(envs[0])
        for name, v in envs[1].items():
            merged[name] = self.merge(merged[name], v) if name in merged else v
        scope.vars = merged

    def merge(self, a: Any, b: Any) -> Any:
        if a is b:
            return a
        if isinstance(a, (list, tuple)) and isinstance(b, (list, tuple)):
            return list(a) + [x for x in b if not any(x is y for y in a)]
        if is_concrete(a) and is_concrete(b):
            try:
                if a == b:
                    return a
            except Exception:
                pass
        return Opaque("value depends on a condition known only at launch time")

    # ---- expressions ----------------------------------------------------------------------
    def ev(self, node: ast.expr, scope: Scope) -> Any:
        self.tick()
        handler = getattr(self, "ex_" + type(node).__name__, None)
        if handler is None:
            return Opaque(f"unsupported expression ({type(node).__name__})", self.span(node, scope))
        return handler(node, scope)

    def ex_Constant(self, n: ast.Constant, scope: Scope) -> Any:
        if isinstance(n.value, str):
            return SStr(n.value, self.span(n, scope))
        return n.value

    def ex_Name(self, n: ast.Name, scope: Scope) -> Any:
        s: Scope | None = scope
        while s is not None:
            if n.id in s.vars:
                return s.vars[n.id]
            s = s.parent
        if n.id == "__file__":
            return (scope.module or self.main).path
        if n.id in BUILTIN_NAMES:
            return Ref("builtins." + n.id)
        return Opaque(f'undefined name "{n.id}"', self.span(n, scope))

    def ex_Attribute(self, n: ast.Attribute, scope: Scope) -> Any:
        return calls.get_attr(self, self.ev(n.value, scope), n.attr, self.span(n, scope))

    def ex_Call(self, n: ast.Call, scope: Scope) -> Any:
        func = self.ev(n.func, scope)
        args: list[Any] = []
        arg_spans: list[Span] = []
        for a in n.args:
            if isinstance(a, ast.Starred):
                items = calls.iterate(self, self.ev(a.value, scope))
                if items is None:
                    return Opaque("call with an unknown *args", self.span(n, scope))
                args.extend(items)
                arg_spans.extend([self.span(a, scope)] * len(items))
            else:
                args.append(self.ev(a, scope))
                arg_spans.append(self.span(a, scope))
        kwargs: dict[str, Any] = {}
        kw_spans: dict[str, Span] = {}
        for kw in n.keywords:
            v = self.ev(kw.value, scope)
            if kw.arg is None:
                if not isinstance(v, dict):
                    return Opaque("call with an unknown **kwargs", self.span(n, scope))
                for k, x in v.items():
                    kwargs[str(k)] = x
                    kw_spans[str(k)] = self.span(kw.value, scope)
            else:
                kwargs[kw.arg] = v
                kw_spans[kw.arg] = self.span(kw.value, scope)
        return calls.call(self, func, args, kwargs, n, scope, arg_spans, kw_spans)

    def ex_BinOp(self, n: ast.BinOp, scope: Scope) -> Any:
        return self.binop(n.op, self.ev(n.left, scope), self.ev(n.right, scope), n, scope)

    def binop(self, op: ast.operator, left: Any, right: Any, n: ast.AST, scope: Scope) -> Any:
        span = self.span(n, scope)
        for v in (left, right):
            if isinstance(v, Opaque):
                return Opaque(v.reason, span)
        if isinstance(op, ast.Add) and type(left) is type(right) and isinstance(left, (list, tuple)):
            spans = (self.item_spans(left) or [span] * len(left), self.item_spans(right) or [span] * len(right))
            joined = left + right
            if isinstance(spans[0], list) and isinstance(spans[1], list):
                self.register(joined, spans[0] + spans[1])
            return joined
        sym = symbolic.binop(self, op, left, right, span)
        if sym is not None:
            return sym
        if not (is_concrete(left) and is_concrete(right)):
            return Opaque("operation on values that cannot be evaluated statically", span)
        if isinstance(op, (ast.Mult, ast.Pow, ast.LShift)) and not symbolic.small_enough(op, left, right):
            return Opaque("result too large", span)
        try:
            result = _BINOPS[type(op)](left, right)
        except Exception:
            return Opaque("operation fails", span)
        return result

    def ex_UnaryOp(self, n: ast.UnaryOp, scope: Scope) -> Any:
        v = self.ev(n.operand, scope)
        if isinstance(n.op, ast.Not):
            if isinstance(v, SymBool):
                return SymBool(v.value, not v.negated)
            t = truth(v)
            return Opaque("negation of an unknown value") if t is None else (not t)
        if isinstance(v, (int, float)) and not isinstance(v, Opaque):
            ops = {ast.USub: operator.neg, ast.UAdd: operator.pos, ast.Invert: operator.invert}
            return ops[type(n.op)](v)
        return Opaque("unary operation on an unknown value", self.span(n, scope))

    def ex_BoolOp(self, n: ast.BoolOp, scope: Scope) -> Any:
        is_and = isinstance(n.op, ast.And)
        syms: list[SymBool] = []
        last: Any = None
        for e in n.values:
            last = self.ev(e, scope)
            if isinstance(last, SymBool):
                syms.append(last)
                continue
            t = truth(last)
            if t is None:
                return Opaque("boolean operation on an unknown value", self.span(n, scope))
            if t is not is_and:
                return last if not syms else Opaque("mixed condition", self.span(n, scope))
        if syms:
            return symbolic.combine(syms, "and" if is_and else "or", self.span(n, scope))
        return last

    def ex_Compare(self, n: ast.Compare, scope: Scope) -> Any:
        left = self.ev(n.left, scope)
        result: Any = True
        for op, comp in zip(n.ops, n.comparators):
            right = self.ev(comp, scope)
            r = symbolic.compare(op, left, right, self.span(n, scope))
            if r is None:
                if isinstance(op, (ast.Is, ast.IsNot)) and not isinstance(left, Opaque) and not isinstance(right, Opaque):
                    r = _CMPOPS[type(op)](left, right)
                elif is_concrete(left) and is_concrete(right):
                    try:
                        r = bool(_CMPOPS[type(op)](left, right))
                    except Exception:
                        r = Opaque("comparison fails")
                else:
                    r = Opaque("comparison of values that cannot be evaluated statically", self.span(n, scope))
            if len(n.ops) == 1:
                return r
            if r is not True:
                return r
            left = right
        return result

    def ex_IfExp(self, n: ast.IfExp, scope: Scope) -> Any:
        test = self.ev(n.test, scope)
        t = truth(test)
        if t is None:
            return symbolic.if_else(self, test, self.ev(n.body, scope), self.ev(n.orelse, scope), self.span(n, scope))
        return self.ev(n.body if t else n.orelse, scope)

    def _elts(self, elts: list[ast.expr], scope: Scope) -> tuple[list[Any], list[Span]] | None:
        out: list[Any] = []
        spans: list[Span] = []
        for e in elts:
            if isinstance(e, ast.Starred):
                items = calls.iterate(self, self.ev(e.value, scope))
                if items is None:
                    return None
                out.extend(items)
                spans.extend([self.span(e, scope)] * len(items))
            else:
                out.append(self.ev(e, scope))
                spans.append(self.span(e, scope))
        return out, spans

    def ex_List(self, n: ast.List, scope: Scope) -> Any:
        r = self._elts(n.elts, scope)
        if r is None:
            return Opaque("list with an unknown *item", self.span(n, scope))
        return self.register(r[0], r[1])

    def ex_Tuple(self, n: ast.Tuple, scope: Scope) -> Any:
        r = self._elts(n.elts, scope)
        if r is None:
            return Opaque("tuple with an unknown *item", self.span(n, scope))
        return self.register(tuple(r[0]), r[1])

    def ex_Set(self, n: ast.Set, scope: Scope) -> Any:
        r = self._elts(n.elts, scope)
        try:
            return set(r[0]) if r is not None else Opaque("set")
        except TypeError:
            return Opaque("set of unhashable values")

    def ex_Dict(self, n: ast.Dict, scope: Scope) -> Any:
        out: dict[Any, Any] = {}
        spans: dict[Any, tuple[Span, Span]] = {}
        for k, v in zip(n.keys, n.values):
            value = self.ev(v, scope)
            if k is None:
                if not isinstance(value, dict):
                    return Opaque("dict with an unknown **item", self.span(n, scope))
                out.update(value)
                continue
            key = self.ev(k, scope)
            try:
                out[key] = value
            except TypeError:
                return Opaque("dict with an unhashable key", self.span(n, scope))
            spans[key] = (self.span(k, scope), self.span(v, scope))
        return self.register(out, spans)

    def ex_Subscript(self, n: ast.Subscript, scope: Scope) -> Any:
        obj = self.ev(n.value, scope)
        key = self.ev(n.slice, scope)
        return calls.subscript(self, obj, key, self.span(n, scope))

    def ex_Slice(self, n: ast.Slice, scope: Scope) -> Any:
        parts = [self.ev(p, scope) if p is not None else None for p in (n.lower, n.upper, n.step)]
        if not all(p is None or isinstance(p, int) for p in parts):
            return Opaque("slice with unknown bounds")
        return slice(*parts)

    def ex_JoinedStr(self, n: ast.JoinedStr, scope: Scope) -> Any:
        parts: list[Any] = []
        for v in n.values:
            if isinstance(v, ast.Constant):
                parts.append(str(v.value))
                continue
            assert isinstance(v, ast.FormattedValue)
            x = self.ev(v.value, scope)
            spec = self.ev(v.format_spec, scope) if v.format_spec is not None else ""
            parts.append(symbolic.format_value(self, x, v.conversion, spec, self.span(v, scope)))
        return symbolic.join_parts(self, parts, self.span(n, scope))

    def ex_Lambda(self, n: ast.Lambda, scope: Scope) -> Any:
        return self.make_func(n, scope)

    def ex_NamedExpr(self, n: ast.NamedExpr, scope: Scope) -> Any:
        v = self.ev(n.value, scope)
        self.assign(n.target, v, scope)
        return v

    def ex_Starred(self, n: ast.Starred, scope: Scope) -> Any:
        return self.ev(n.value, scope)

    def _comp(self, gens: list[ast.comprehension], scope: Scope, emit: Callable[[Scope], None]) -> bool:
        inner = Scope(scope, scope.module)
        count = [0]

        def loop(i: int) -> bool:
            if i == len(gens):
                count[0] += 1
                if count[0] > MAX_LOOP:
                    raise Abort("comprehension iteration limit exceeded")
                emit(inner)
                return True
            g = gens[i]
            items = calls.iterate(self, self.ev(g.iter, inner if i else scope))
            if items is None:
                return False
            for item in items:
                self.assign(g.target, item, inner)
                ok = True
                for cond in g.ifs:
                    t = truth(self.ev(cond, inner))
                    if t is None:
                        return False
                    ok = ok and t
                if ok and not loop(i + 1):
                    return False
            return True

        return loop(0)

    def ex_ListComp(self, n: ast.ListComp, scope: Scope) -> Any:
        out: list[Any] = []
        if not self._comp(n.generators, scope, lambda s: out.append(self.ev(n.elt, s))):
            return Opaque("comprehension over values that cannot be evaluated statically", self.span(n, scope))
        return self.register(out, [self.span(n.elt, scope)] * len(out))

    ex_GeneratorExp = ex_ListComp

    def ex_SetComp(self, n: ast.SetComp, scope: Scope) -> Any:
        r = self.ex_ListComp(n, scope)  # type: ignore[arg-type]
        try:
            return set(r) if isinstance(r, list) else r
        except TypeError:
            return Opaque("set of unhashable values")

    def ex_DictComp(self, n: ast.DictComp, scope: Scope) -> Any:
        out: dict[Any, Any] = {}

        def emit(s: Scope) -> None:
            k = self.ev(n.key, s)
            try:
                out[k] = self.ev(n.value, s)
            except TypeError:
                pass

        if not self._comp(n.generators, scope, emit):
            return Opaque("comprehension over values that cannot be evaluated statically", self.span(n, scope))
        return out

    # ---- functions ------------------------------------------------------------------------
    def run_function(self, body: list[ast.stmt], fscope: Scope) -> Any:
        self.pending.append([])
        self.frame_tags.append(0)
        try:
            try:
                self.exec_block(body, fscope)
                result: Any = None
            except _Return as r:
                result = r.value
            except _Raise:
                result = Opaque("the function raises an exception")
        finally:
            pend = self.pending.pop()
            extra = self.frame_tags.pop()
            if extra:
                del self.cond_stack[len(self.cond_stack) - extra:]
        for p in pend:
            result = p if result is None else self.merge(p, result)
        return result


