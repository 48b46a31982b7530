"""Expression evaluation (a mixin of ``Evaluator``): literals, names, operators, containers,
comprehensions and f-strings over known data and symbolic launch values."""
from __future__ import annotations

import ast
import operator
from collections.abc import Callable
from typing import Any

from physai_lint.model.span import Span

from . import calls, symbolic
from .bounds import MAX_WEIGHT, SizeGuard
from .core import BINOPS, BUILTIN_NAMES, CMPOPS, MAX_LOOP, Abort, Scope, is_concrete, truth
from .runtime import LObj, Opaque, Ref, SStr, SymBool

_SCALARS = frozenset([int, float, bool, type(None), Opaque])


class ExpressionsMixin:
    bounds: SizeGuard
    env: dict[str, str]

    # ---- expressions ----------------------------------------------------------------------
    def ev(self, node: ast.expr, scope: Scope) -> Any:
        self.tick()
        handler = getattr(self, "ex_" + type(node).__name__, None)
        if handler is None:
            return Opaque(f"unsupported expression ({type(node).__name__})", self.span(node, scope))
        result = handler(node, scope)
        # A name gives back a value weighed when it was built (in-place growth is checked in calls).
        kind = type(result)
        if kind in _SCALARS or isinstance(node, ast.Name):
            return result
        if (len(result) >= MAX_WEIGHT if kind is str or kind is SStr else self.bounds.too_big(result)):
            return Opaque("value too large to analyse", self.span(node, scope))
        return result

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
        if _output_only(n, func):
            # print(str(lc)), logger.info(f"{lc}"): the text only goes to the terminal, where a
            # substitution's description is harmless; it reaches no action
            before = set(self.concats)
            try:
                return self._call(n, func, scope)
            finally:
                for key in [k for k in self.concats if k not in before]:
                    del self.concats[key]
        return self._call(n, func, scope)

    def _call(self, n: ast.Call, func: Any, scope: Scope) -> Any:
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
                    self.escape([v])  # f(**context.launch_configurations) reads every one
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
        if isinstance(op, ast.Div) and isinstance(left, LObj):
            joined = _path_div(left, right, span)
            if joined is not None:
                return joined
        sym = symbolic.binop(self, op, left, right, span)
        if sym is not None:
            return sym
        if not (is_concrete(left) and is_concrete(right)):
            return Opaque("operation on values that cannot be evaluated statically", span)
        if isinstance(op, (ast.Mult, ast.Pow, ast.LShift, ast.Mod)) and not symbolic.small_enough(op, left, right):
            return Opaque("result too large", span)
        try:
            result = BINOPS[type(op)](left, right)
        except Exception:  # noqa: BLE001 - the real operation on known data fails: unknown
            return Opaque("operation fails", span)
        return result

    def ex_UnaryOp(self, n: ast.UnaryOp, scope: Scope) -> Any:
        v = self.ev(n.operand, scope)
        if isinstance(n.op, ast.Not):
            if isinstance(v, SymBool):
                return SymBool(v.value, not v.negated)
            t = self.tested(v, n.operand, scope)
            return Opaque("negation of an unknown value") if t is None else (not t)
        if isinstance(v, (int, float)) and not isinstance(v, Opaque):
            ops = {ast.USub: operator.neg, ast.UAdd: operator.pos, ast.Invert: operator.invert}
            return ops[type(n.op)](v)
        return Opaque("unary operation on an unknown value", self.span(n, scope))

    def ex_BoolOp(self, n: ast.BoolOp, scope: Scope) -> Any:
        is_and = isinstance(n.op, ast.And)
        syms: list[SymBool] = []
        last: Any = None
        for k, e in enumerate(n.values):
            last = self.ev(e, scope)
            if isinstance(last, SymBool):
                syms.append(last)
                continue
            t = self.tested(last, e, scope) if k < len(n.values) - 1 else truth(last)  # the last is not tested
            if t is None:
                # the operands after it may run: what they read (``b.perform(context)``) is read
                for rest in n.values[k + 1:]:
                    self.ev(rest, scope)
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
            r: Any
            if isinstance(op, (ast.Eq, ast.NotEq)) and (symbolic.is_subst(left) or symbolic.is_subst(right)):
                # a substitution object has no __eq__: Python compares identities, whatever it names
                subst, other = (left, right) if symbolic.is_subst(left) else (right, left)
                self.substitution_tested("equals" if isinstance(op, ast.Eq) else "not-equals",
                                         self.span(n, scope), subst, other)
                r = (left is right) == isinstance(op, ast.Eq)
            else:
                r = symbolic.compare(op, left, right, self.span(n, scope))
            if r is None and isinstance(op, (ast.In, ast.NotIn)):
                r = calls.contains(self, right, left, self.span(n, scope))
                if isinstance(op, ast.NotIn) and isinstance(r, bool):
                    r = not r
            if r is None:
                if isinstance(op, (ast.Is, ast.IsNot)) and not isinstance(left, Opaque) and not isinstance(right, Opaque):
                    r = CMPOPS[type(op)](left, right)
                elif is_concrete(left) and is_concrete(right):
                    try:
                        r = bool(CMPOPS[type(op)](left, right))
                    except Exception:  # noqa: BLE001
                        r = Opaque("comparison fails")
                else:
                    unknown = left if isinstance(left, Opaque) else right
                    reason = unknown.reason if isinstance(unknown, Opaque) else "comparison of values that cannot be evaluated statically"
                    r = Opaque(reason, self.span(n, scope))
            if len(n.ops) == 1:
                return r
            if r is not True:
                return r
            left = right
        return result

    def ex_IfExp(self, n: ast.IfExp, scope: Scope) -> Any:
        test = self.ev(n.test, scope)
        t = self.tested(test, n.test, scope)
        if t is None:
            out = symbolic.if_else(self, test, self.ev(n.body, scope), self.ev(n.orelse, scope), self.span(n, scope))
            if not isinstance(test, SymBool) or isinstance(out, Opaque):
                self.undecided += 1  # a value lost (``Recorder.undecided``)
            return out
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
                    self.escape([value])  # {**context.launch_configurations} reads every one
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
                    t = self.tested(self.ev(cond, inner), cond, inner)
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



def _path_div(left: LObj, right: Any, span: Span) -> LObj | None:
    """``PathJoinSubstitution.__truediv__``: a new PathJoinSubstitution with one more component."""
    from . import api

    if api.short(left.qual) not in ("PathJoinSubstitution", "PathSubstitution"):
        return None
    parts = api.path_parts(left)
    components = list(parts) if isinstance(parts, (list, tuple)) else [parts]
    qual = left.qual.rsplit(".", 1)[0] + ".PathJoinSubstitution"
    return LObj(qual, [components + [right]], {}, left.node, span, [span], {})


# Methods of Python's and rclpy's loggers, and of files, that only write their text somewhere.
_OUTPUT_METHODS = frozenset({"debug", "info", "warning", "warn", "error", "critical", "fatal", "exception",
                             "write"})


def _output_only(n: ast.Call, func: Any) -> bool:
    """Whether the call only writes its arguments out: ``print(...)``, ``logger.info(...)``."""
    if isinstance(func, Ref):
        return func.qual == "builtins.print"
    return isinstance(n.func, ast.Attribute) and n.func.attr in _OUTPUT_METHODS and isinstance(func, Opaque)
