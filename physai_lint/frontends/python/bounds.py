"""Memory bounds for the evaluator: values it builds stay small, whatever the launch file computes.

The step budget bounds time, not size: ``y = y + y`` in a 200-round loop, ``'a'.center(10**10)``,
``x = x * x`` or ``y = [y, y]`` each take few steps and would need terabytes. Every expression
result is weighed (items and characters, nested containers counted through, shared ones once per
reference) and anything over ``MAX_WEIGHT`` becomes unknown; operations that can multiply a size in
one step are checked before they run.
"""
from __future__ import annotations

import re
from typing import Any

MAX_WEIGHT = 1_000_000
MAX_INT_BITS = 65_536
MAX_WORK = 5_000_000  # items weighed per file: beyond it the evaluation stops (Abort), as for steps
_WIDTH_METHODS = frozenset(["center", "ljust", "rjust", "zfill", "expandtabs"])
_DIGITS = re.compile(r"\d+")


class SizeGuard:
    """Weighs evaluator values; remembers the weight of each container (by identity and length)."""

    def __init__(self) -> None:
        self._memo: dict[int, tuple[int, int, Any]] = {}
        self.work = 0

    def weight(self, v: Any) -> int:
        seen = self._memo.get(id(v))
        if seen is not None and seen[2] is v and seen[0] == len(v):
            return seen[1]
        if isinstance(v, (str, bytes)):
            return len(v) + 1
        if isinstance(v, int) and not isinstance(v, bool):
            return v.bit_length() // 64 + 1
        if not isinstance(v, (list, tuple, dict, set, frozenset)):
            inner = getattr(v, "value", None)  # SymStr and friends hold a tuple of parts
            return len(inner) + 1 if isinstance(inner, tuple) else 1
        self.work += len(v)
        if self.work > MAX_WORK:
            from .core import Abort

            raise Abort("evaluation size budget exhausted")
        self._memo[id(v)] = (len(v), MAX_WEIGHT + 1, v)  # a container that holds itself is too big
        items = [x for kv in v.items() for x in kv] if isinstance(v, dict) else v
        total = 1
        for x in items:
            total += self.weight(x)
            if total > MAX_WEIGHT:
                break
        self._memo[id(v)] = (len(v), total, v)
        return total

    def too_big(self, v: Any) -> bool:
        return self.weight(v) > MAX_WEIGHT


def int_op_too_big(op: str, left: Any, right: Any) -> bool:
    """``*``, ``**`` and ``<<`` on integers whose result would exceed ``MAX_INT_BITS``."""
    if not (isinstance(left, int) and isinstance(right, int)):
        return False
    lb, rb = abs(left).bit_length(), abs(right).bit_length()
    if op == "mul":
        return lb + rb > MAX_INT_BITS
    if op == "pow":
        return right > 0 and lb > 1 and lb * right > MAX_INT_BITS
    if op == "lshift":
        return right > 0 and lb + right > MAX_INT_BITS
    return False


def wide_format(spec: Any) -> bool:
    """A format string or spec asking for a field wider than ``MAX_WEIGHT`` (``'%9999999999d'``)."""
    return isinstance(spec, str) and any(len(m) > 6 and int(m) > MAX_WEIGHT for m in _DIGITS.findall(spec))


def str_method_too_big(obj: str, name: str, args: list[Any]) -> bool:
    """``str`` methods that can grow a string far beyond their inputs in one call."""
    if name in _WIDTH_METHODS:
        return any(isinstance(a, int) and a > MAX_WEIGHT for a in args)
    if name == "replace" and len(args) >= 2 and isinstance(args[0], str) and isinstance(args[1], str):
        count = obj.count(args[0]) if args[0] else len(obj) + 1
        return len(obj) + count * len(args[1]) > MAX_WEIGHT
    return False


def join_too_big(sep: str, items: list[Any]) -> bool:
    total = len(sep) * max(len(items) - 1, 0)
    for x in items:
        total += len(x) if isinstance(x, str) else 1
        if total > MAX_WEIGHT:
            return True
    return False
