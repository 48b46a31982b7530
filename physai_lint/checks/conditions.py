"""Conditions that can never hold: L108 condition-never-true; L116 python-expression-error.

Conservative by design: a condition is reported only when every input is known: literals, values
a ``SetLaunchConfiguration`` / ``<let>`` without a condition surely set before it (walked in
execution order, ``_Known``), and launch arguments whose ``choices`` bound their values, never
changed by ``SetLaunchConfiguration`` / ``<let>`` / group-local configurations anywhere in the
checked files. ``PythonExpression`` / ``$(eval)`` are evaluated by ``resolve/safe_eval.py`` for
every combination of those values.
"""
from __future__ import annotations

import itertools
from collections.abc import Iterator
from typing import Any

from physai_lint.checks._util import once, suggestion
from physai_lint.checks.base import CheckContext, rule
from physai_lint.model import launch as ir
from physai_lint.model.findings import Diagnostic
from physai_lint.model.values import (
    UNSET_CONFIGURATION,
    BoolOp,
    Compare,
    IfElse,
    LaunchConfig,
    PythonExpr,
    Text,
    literal_of,
)
from physai_lint.resolve.evaluate import Evaluator, Scope

_TRUE = {"true", "1"}
_FALSE = {"false", "0"}


def _children(a: Any) -> tuple[Any, ...]:
    if isinstance(a, (ir.Group, ir.Timer, ir.EventHandler, ir.OpaqueAction)):
        return a.actions
    return ()


def _walk(actions: tuple[Any, ...]) -> Iterator[Any]:
    for a in actions:
        yield a
        yield from _walk(_children(a))


def _config_name(value: Any) -> str | None:
    """``$(var x)`` / ``LaunchConfiguration('x')`` without a default -> ``x``."""
    if not value or len(value) != 1 or not isinstance(value[0], LaunchConfig):
        return None
    return literal_of(value[0].name)


def _set_names(ctx: CheckContext) -> set[str] | None:
    """Names set by SetLaunchConfiguration / group configurations anywhere (None: unknown name)."""
    out: set[str] = set()
    for lf in ctx.launch_files.values():
        for a in _walk(lf.actions):
            pairs: list[Any] = []
            if isinstance(a, ir.SetLaunchConfiguration):
                pairs.append(a.name)
            elif isinstance(a, ir.Group):
                pairs.extend(k for k, _ in a.launch_configurations)
            elif isinstance(a, ir.OpaqueAction) and a.reason:
                return None
            for name in pairs:
                lit = literal_of(name)
                if lit is None:
                    return None
                out.add(lit)
    return out


def _choices(lf: ir.LaunchFile) -> dict[str, tuple[str, ...]]:
    out: dict[str, tuple[str, ...]] = {}
    for a in _walk(lf.actions):
        if isinstance(a, ir.DeclareArgument) and a.choices:
            if a.name in out and out[a.name] != a.choices:
                out[a.name] = ()  # declared twice, differently: unknown
            else:
                out[a.name] = a.choices
    return {k: v for k, v in out.items() if v}


def _compare_dead(cond: ir.Condition, domains: dict[str, tuple[str, ...]],
                  fixed: dict[str, tuple[str, Any]]) -> str | None:
    if len(cond.value) != 1 or not isinstance(cond.value[0], Compare):
        return None
    cmp = cond.value[0]
    name = _config_name(cmp.left)
    right = literal_of(cmp.right)
    if name is None or right is None:
        name, right = _config_name(cmp.right), literal_of(cmp.left)
    if name is None or right is None or name not in domains:
        return None
    options = domains[name]
    equal_possible = right in options
    never_true = (cond.kind == "if" and cmp.op == "equals" and not equal_possible) or \
                 (cond.kind == "unless" and cmp.op == "not-equals" and not equal_possible)
    if not never_true:
        return None
    if name in fixed:
        value, span = fixed[name]
        return (f'launch configuration "{name}" is "{value}" here (set at line {span.line}), and it is '
                f'compared with "{right}", so the condition is never true')
    listed = ", ".join(f'"{c}"' for c in options)
    return (f'launch argument "{name}" is compared with "{right}", which is not one of its choices '
            f"({listed}), so the condition is never true")


_MAX_COMBINATIONS = 512
_COMPUTED = (PythonExpr, BoolOp, Compare, IfElse)


def _parts(value: Any) -> Iterator[Any]:
    """Every substitution inside a value, nested ones included."""
    for part in value or ():
        yield part
        for attr in ("name", "default", "expression", "operands", "left", "right", "condition",
                     "if_value", "else_value", "parts", "command", "package", "path", "executable"):
            sub = getattr(part, attr, None)
            if isinstance(sub, tuple) and sub and isinstance(sub[0], tuple):
                for item in sub:
                    yield from _parts(item)
            elif isinstance(sub, tuple):
                yield from _parts(sub)


def _computed_dead(cond: ir.Condition, domains: dict[str, tuple[str, ...]],
                   fixed: dict[str, tuple[str, Any]]) -> str | None:
    """A PythonExpression / $(eval) / boolean / comparison condition, or a launch configuration a
    ``<let>`` set (``fixed``), that is false for every combination of the values its inputs can
    take (``domains``: set values, declared choices; safe evaluator only)."""
    parts = list(_parts(cond.value))
    computed = any(isinstance(p, _COMPUTED) for p in parts)
    names: list[str] = []
    for p in parts:
        if isinstance(p, LaunchConfig):
            name = literal_of(p.name)
            if name is None or name not in domains:
                return None
            if name not in names:
                names.append(name)
    if not computed and not any(n in fixed for n in names):
        return None  # a plain $(var x) over choices, or a literal: the other checks' cases
    combos = list(itertools.islice(itertools.product(*(domains[n] for n in names)), _MAX_COMBINATIONS + 1))
    if len(combos) > _MAX_COMBINATIONS:
        return None
    evaluator = Evaluator(None)
    for combo in combos:
        if evaluator.condition(cond.kind, cond.value, Scope(configs=dict(zip(names, combo)))) is not False:
            return None
    expr = "".join(_show(p) for p in cond.value)
    if not names:
        result = evaluator.eval(cond.value, Scope())
        return f'"{expr}" always evaluates to "{result}"'
    outcome = "false" if cond.kind == "if" else "true"
    if all(n in fixed for n in names):
        given = " and ".join(f'launch configuration "{n}" is "{fixed[n][0]}" here (set at line '
                             f"{fixed[n][1].line})" for n in names)
        return f'{given}, so "{expr}" is {outcome}'
    tried = "; ".join(f'"{n}" is "{fixed[n][0]}" (set at line {fixed[n][1].line})' if n in fixed else
                      f'"{n}" in ' + ", ".join(f'"{c}"' for c in domains[n]) for n in names)
    return (f'"{expr}" is {outcome} for every value of the launch configurations it reads '
            f"({tried})")


def _show(part: Any) -> str:
    """A substitution as XML spells it, for messages."""
    if isinstance(part, Text):
        return part.text
    if isinstance(part, LaunchConfig):
        return f"$(var {literal_of(part.name)})"
    if isinstance(part, PythonExpr):
        return '$(eval "' + "".join(_show(p) for p in part.expression) + '")'
    if isinstance(part, Compare):
        left, right = "".join(_show(p) for p in part.left), "".join(_show(p) for p in part.right)
        return f"$({part.op} {left} {right})"
    if isinstance(part, BoolOp):
        return f"$({part.op} " + " ".join("".join(_show(p) for p in o) for o in part.operands) + ")"
    return "$(...)"


def _literal_dead(cond: ir.Condition) -> str | None:
    if not cond.value or not all(isinstance(p, Text) for p in cond.value):
        return None
    text = (literal_of(cond.value) or "").strip().lower()
    if (cond.kind == "if" and text in _FALSE) or (cond.kind == "unless" and text in _TRUE):
        return f'the condition is the constant "{literal_of(cond.value)}", so it is never true'
    return None


def _nested(actions: tuple[Any, ...], outer: dict[str, tuple[str, Any]],
            out: list[tuple[Any, str]], set_names: set[str]) -> None:
    for a in actions:
        cond = getattr(a, "condition", None)
        inner = dict(outer)
        if isinstance(cond, ir.Condition):
            name = _config_name(cond.value)
            if name is not None and name not in set_names:
                prev = outer.get(name)
                if prev is not None and prev[0] != cond.kind:
                    out.append((cond, (f'it is "{cond.kind}" on launch configuration "{name}" inside a '
                                      f'group that is "{prev[0]}" on the same configuration (line '
                                      f"{prev[1].span.line}), so it is never true")))
                inner[name] = (cond.kind, cond)
        if isinstance(a, ir.Group):
            _nested(a.actions, inner, out, set_names)


class _Known:
    """Launch configurations whose value is surely known at a point of a file walked in execution
    order: set by a ``SetLaunchConfiguration`` / ``<let>`` without a condition to a literal, in this
    scope or an enclosing one, with nothing since that may have changed them (an include, whose
    arguments and configurations leak into the includer; a set whose name or value is unknown; a
    function the linter could not evaluate). Actions launch runs later (timers, event handlers)
    see none."""

    def __init__(self, choices: dict[str, tuple[str, ...]], set_names: set[str] | None,
                 include_sets: Any = None) -> None:
        self.choices = {n: c for n, c in choices.items() if set_names is not None and n not in set_names}
        self.found: list[tuple[ir.Condition, str]] = []
        # an include -> the names its file may set (None: any), when it was resolved
        self.include_sets = include_sets or (lambda _a: None)

    def walk(self, actions: tuple[Any, ...], fixed: dict[str, tuple[str, Any]]) -> None:
        for a in actions:
            for cond in _conditions(a):
                self.check(cond, fixed)
            if getattr(a, "condition", None) is not None:  # it may not run: what it sets is unknown
                inner = dict(fixed) if isinstance(a, ir.Group) and a.scoped else {}
                self.forget(a, fixed)
                if _children(a):
                    self.walk(_children(a), inner)
                continue
            if isinstance(a, ir.SetLaunchConfiguration):
                _set(fixed, a.name, a.value, a.span)
            elif isinstance(a, ir.Group):
                inner = dict(fixed) if a.scoped else fixed
                for k, v in a.launch_configurations:
                    _set(inner, k, v, a.span)
                self.walk(a.actions, inner)
            elif isinstance(a, (ir.Timer, ir.EventHandler)):
                self.walk(a.actions, {})  # run later, after whatever the rest sets
                self.forget(a, fixed)
            elif isinstance(a, ir.OpaqueAction):
                if a.reason:
                    fixed.clear()
                else:
                    self.walk(a.actions, fixed)
            elif isinstance(a, ir.Include):
                fixed.clear()
                # IncludeLaunchDescription.execute sets its arguments in the includer's scope
                # before the file runs: they hold after it unless that file sets them again
                sets = self.include_sets(a)
                if sets is not None:
                    for arg in a.arguments or ():
                        text = literal_of(arg.value)
                        if arg.name not in sets and text is not None:
                            fixed[arg.name] = (text, arg.span)
            elif isinstance(a, ir.ResetLaunchConfigurations):
                fixed.clear()

    @staticmethod
    def forget(action: Any, fixed: dict[str, tuple[str, Any]]) -> None:
        """What ``action`` may set (it may not run, or run later): no longer known."""
        if isinstance(action, ir.Include):
            fixed.clear()
            return
        for a in [action, *_walk(_children(action))]:
            if isinstance(a, ir.SetLaunchConfiguration):
                name = literal_of(a.name)
                if name is None:
                    fixed.clear()
                else:
                    fixed.pop(name, None)
            elif isinstance(a, (ir.Include, ir.ResetLaunchConfigurations)) or \
                    (isinstance(a, ir.OpaqueAction) and a.reason):
                fixed.clear()

    def check(self, cond: ir.Condition, fixed: dict[str, tuple[str, Any]]) -> None:
        domains = {**self.choices, **{n: (v,) for n, (v, _) in fixed.items()}}
        why = (_literal_dead(cond) or _compare_dead(cond, domains, fixed)
               or _computed_dead(cond, domains, fixed))
        if why:
            self.found.append((cond, why))


def _set(fixed: dict[str, tuple[str, Any]], name: Any, value: Any, span: Any) -> None:
    """A configuration set to ``value``: known when both are literals; a name not known statically
    may be any, so nothing stays known."""
    key, text = literal_of(name), literal_of(value)
    if key is None:
        fixed.clear()
    elif text is None:
        fixed.pop(key, None)
    else:
        fixed[key] = (text, span)


def _conditions(a: Any) -> list[Any]:
    conds = [getattr(a, "condition", None)]
    if isinstance(a, ir.NodeAction):
        conds += [x for c in a.composable_nodes for x in (c.branch, c.condition)]
    return [c for c in conds if isinstance(c, ir.Condition)]


def _include_sets(ctx: CheckContext) -> Any:
    """For an include the resolution followed, the launch configurations its file may set (what
    leaks back into the includer); None when that is not known (the file includes others, runs a
    function the linter cannot follow, or sets a name not known statically)."""
    targets: dict[Any, str | None] = {}
    for launch in ctx.launches:
        for rec in launch.includes:
            ok = rec.status == "ok" and rec.target_source in ctx.launch_files
            if targets.setdefault(rec.span, rec.target_source if ok else None) != \
                    (rec.target_source if ok else None):
                targets[rec.span] = None  # reached with different targets: not one file
    memo: dict[str, set[str] | None] = {}

    def sets(a: ir.Include) -> set[str] | None:
        target = targets.get(a.span)
        if target is None:
            return None
        if target not in memo:
            names: set[str] | None = set()
            for b in _walk(ctx.launch_files[target].actions):
                if isinstance(b, (ir.Include, ir.ResetLaunchConfigurations)) or \
                        (isinstance(b, ir.OpaqueAction) and b.reason):
                    names = None
                    break
                if isinstance(b, ir.SetLaunchConfiguration):
                    name = literal_of(b.name)
                    if name is None:
                        names = None
                        break
                    names.add(name)
                elif isinstance(b, ir.Group):
                    group_names = [literal_of(k) for k, _ in b.launch_configurations]
                    if None in group_names:
                        names = None
                        break
                    names.update(n for n in group_names if n is not None)
            memo[target] = names
        return memo[target]

    return sets


@rule("L108", "condition-never-true")
def condition_never_true(ctx: CheckContext) -> Iterator[Diagnostic]:
    set_names = _set_names(ctx)
    include_sets = _include_sets(ctx)
    for path in sorted(ctx.launch_files):
        lf = ctx.launch_files[path]
        known = _Known(_choices(lf), set_names, include_sets)
        known.walk(lf.actions, {})
        found = known.found
        if set_names is not None:
            _nested(lf.actions, {}, found, set_names)
        seen: set[object] = set()
        for cond, why in found:
            if cond.span in seen:
                continue
            seen.add(cond.span)
            raw = cond.raw or cond.kind
            yield Diagnostic(
                "L108", cond.span,
                f"{raw}: {why}; the action is never run",
                help="fix the compared value or the condition, or remove the action if it is dead code",
                key=raw)
    yield from _equals_unset(ctx, set_names)


def _equals_unset(ctx: CheckContext, set_names: set[str] | None) -> Iterator[Diagnostic]:
    """``LaunchConfigurationEquals('x', 'v')`` where no launch file declares, sets or passes ``x``
    and no run gives it: launch's ``_predicate_func`` catches the unset configuration's KeyError
    and compares it as never equal (it does not raise, unlike LaunchConfiguration), so the action
    never runs. Mostly a misspelt argument name."""
    if set_names is None:
        return
    declared: set[str] = set()
    for lf in ctx.launch_files.values():
        for a in _walk(lf.actions):
            if isinstance(a, ir.DeclareArgument):
                declared.add(a.name)
            elif isinstance(a, ir.Include):
                if a.arguments is None:
                    return  # an include passing arguments not known may pass it
                declared.update(arg.name for arg in a.arguments)
    given = {r.name for launch in ctx.launches for r in launch.config_reads if r.defined}
    seen: set[object] = set()
    for path in sorted(ctx.launch_files):
        for a in _walk(ctx.launch_files[path].actions):
            cond = getattr(a, "condition", None)
            if cond is None or cond.span in seen or not (cond.raw or "").startswith("LaunchConfigurationEquals"):
                continue
            cmp = cond.value[0] if len(cond.value) == 1 and isinstance(cond.value[0], Compare) else None
            if cmp is None or cmp.op != "equals" or not cmp.left or not isinstance(cmp.left[0], LaunchConfig):
                continue
            name = literal_of(cmp.left[0].name)
            if name is None or name in declared or name in set_names or name in given \
                    or literal_of(cmp.right) == UNSET_CONFIGURATION:  # expected_value=None: "unset?"
                continue
            seen.add(cond.span)
            hint = suggestion(name, declared)
            yield Diagnostic(
                "L108", cond.span,
                f'LaunchConfigurationEquals(...) compares launch configuration "{name}", which no launch '
                "file declares, sets or passes: launch compares an unset configuration as equal to "
                f"nothing (it does not raise), so the action is never run{'; ' + hint if hint else ''}",
                help=f'use the declared argument\'s name, or declare "{name}" with DeclareLaunchArgument',
                key=f"unset:{name}")


@rule("L116", "python-expression-error")
def python_expression_error(ctx: CheckContext) -> Iterator[Diagnostic]:
    for span, text, why in once(ctx, "expression_errors", lambda e: e):
        name = why.startswith("NameError")
        yield Diagnostic(
            "L116", span,
            f"PythonExpression / $(eval) evaluates {text!r}, which raises {why}; launch stops with "
            "that error when it performs the substitution",
            help=("if a launch argument's value is pasted into the expression, it is code, not a string: "
                  "compare it quoted (\"'$(var mode)' == 'mapping'\", PythonExpression([\"'\", mode, \"' == "
                  "'mapping'\"])), or give the value Python spells (True/False, not true/false); otherwise "
                  "use a builtin, one of math's names or a module the expression imports")
            if name else "fix the expression so that it is valid Python once its substitutions are "
                         "replaced by their values",
            key=(text, why))
