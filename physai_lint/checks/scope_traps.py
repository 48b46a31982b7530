"""Scope traps of real launch (SEMANTICS §1): L109 invalid-condition-value, L110 timer-loses-scope,
L111 scoped-group-leak, L112 dirname-after-include, L113 set-use-sim-time-no-effect,
L115 component-condition-ignored."""
from __future__ import annotations

from collections.abc import Iterator

from physai_lint.checks._util import all_nodes, once, where
from physai_lint.checks.base import CheckContext, rule
from physai_lint.model.findings import Diagnostic, Related
from physai_lint.model.launch import NodeAction
from physai_lint.model.values import literal_of


@rule("L109", "invalid-condition-value")
def invalid_condition_value(ctx: CheckContext) -> Iterator[Diagnostic]:
    for span, value, how in once(ctx, "invalid_conditions", lambda e: e):
        if how == "condition":
            yield Diagnostic(
                "L109", span,
                f'condition value "{value}" is not one of "true", "false", "1", "0" (any case); '
                f'launch fails with InvalidConditionExpressionError',
                help="pass a boolean string (true/false/1/0), or compare explicitly with "
                     "LaunchConfigurationEquals / $(equals ...) / PythonExpression",
                key=value)
            continue
        if how == "respawn":
            yield Diagnostic(
                "L109", span,
                f'respawn gets "{value}", which is not a YAML boolean (true/false, yes/no, on/off); launch '
                f"types it with yaml.safe_load when it starts the process (ExecuteLocal.prepare), so the "
                f"launch fails with ValueError: \"Cannot convert value '{value}' to '<class 'bool'>'\"",
                help='pass "true" or "false" (IfCondition also takes "1"/"0", respawn does not), or a bool '
                     "literal in Python (respawn=True)",
                key=(how, value))
            continue
        # NotSubstitution & co. type the operand with yaml.safe_load (type_utils.coerce_to_type)
        yield Diagnostic(
            "L109", span,
            f'{_BOOL_OP.get(how, how)} gets "{value}", which is not a YAML boolean '
            f"(true/false, yes/no, on/off); it types its operands with yaml.safe_load, so "
            f"launch fails with SubstitutionFailure: \"Cannot convert value '{value}' to "
            f"'<class 'bool'>'\"",
            help='pass "true" or "false" (IfCondition also takes "1"/"0", the boolean substitutions do '
                 "not), or compare explicitly with PythonExpression (EqualsSubstitution from iron on)",
            key=(how, value))


# the substitution classes behind ``BoolOp.op`` (Python name / XML form)
_BOOL_OP = {"not": "NotSubstitution ($(not))", "and": "AndSubstitution ($(and))",
            "or": "OrSubstitution ($(or))", "any": "AnySubstitution ($(any))",
            "all": "AllSubstitution ($(all))"}


def _namespace_absolute(node: object) -> bool:
    action = getattr(node, "action", None)
    if not isinstance(action, NodeAction) or action.namespace is None:
        return False
    ns = literal_of(action.namespace)
    return ns is not None and ns.startswith("/")


def _who(node: object) -> str:
    fqn = getattr(node, "fqn", None)
    return f'node "{fqn}"' if fqn else where(node)  # type: ignore[arg-type]


@rule("L110", "timer-loses-scope")
def timer_loses_scope(ctx: CheckContext) -> Iterator[Diagnostic]:
    seen: set[object] = set()
    for _, node in all_nodes(ctx, include_inactive=False):
        if not node.in_timer or not node.timer_lost:
            continue
        # a namespace is not lost when the node gives an absolute one, or ends up in that very
        # namespace anyway (its own namespace= names it: create3's "not pushed in EventHandler")
        lost = [item for item in node.timer_lost
                if not (item.startswith("namespace ") and
                        (_namespace_absolute(node) or item == f'namespace "{node.namespace}"'))]
        if not lost or node.span in seen:
            continue
        seen.add(node.span)
        what = " and ".join(lost)
        yield Diagnostic(
            "L110", node.span,
            f"{_who(node)} is started by a TimerAction/event handler and loses {what} of its "
            "enclosing group: deferred actions run after the group's scope has been popped",
            help="put PushRosNamespace/SetRemap inside the timer's (or handler's) actions, e.g. "
                 "TimerAction(actions=[GroupAction([PushRosNamespace(...), Node(...)])]), "
                 "or give the node its own namespace=/remappings=",
            key=f"{node.package}/{node.executable}:{what}")


@rule("L111", "scoped-group-leak")
def scoped_group_leak(ctx: CheckContext) -> Iterator[Diagnostic]:
    seen: set[object] = set()
    for launch in ctx.launches:
        by_id = {n.id: n for n in launch.nodes} if launch.scope_leaks else {}
        for span, what, outer, receivers in launch.scope_leaks:
            if span in seen:
                continue
            seen.add(span)
            names = sorted({_who(by_id[i]) for i in receivers if i in by_id})
            more = f" and {len(names) - 3} more" if len(names) > 3 else ""
            yield Diagnostic(
                "L111", span,
                f"{what} inside a scoped group also applies after the group, to {', '.join(names[:3])}{more}: "
                "it is appended to a list created outside the group, which the group's scope does "
                "not restore",
                help="give the nodes inside the group remappings=/parameters= directly, or move the "
                     "outer SetRemap/SetParameter (which created the shared list) after the group",
                related=(Related(outer, "the list was created here, outside the group"),
                         *(Related(s, "a node after the group that receives it")
                           for s in sorted(set(receivers.values()), key=lambda s: (s.file, s.line, s.col)))),
                key=what)


@rule("L112", "dirname-after-include")
def dirname_after_include(ctx: CheckContext) -> Iterator[Diagnostic]:
    seen: set[object] = set()
    for launch in ctx.launches:
        for span, got, own in launch.dirname_traps:
            if span in seen or got == own:
                continue
            seen.add(span)
            yield Diagnostic(
                "L112", span,
                f'ThisLaunchFileDir()/$(dirname) evaluates to "{got}" here, not this file\'s '
                f'directory "{own}": an earlier include set it and never restored it',
                help="use FindPackageShare('<pkg>') / $(find-pkg-share <pkg>) to build the path, or "
                     "evaluate the directory before the include",
                key=got)


@rule("L113", "set-use-sim-time-no-effect")
def set_use_sim_time_no_effect(ctx: CheckContext) -> Iterator[Diagnostic]:
    for span in once(ctx, "use_sim_time_actions", lambda s: s):
        yield Diagnostic(
            "L113", span,
            "SetUseSimTime / <set_use_sim_time> does not set the use_sim_time parameter of the "
            "nodes launched after it",
            help="use SetParameter(name='use_sim_time', value=True) / "
                 '<set_parameter name="use_sim_time" value="true"/>, or pass use_sim_time in '
                 "each node's parameters",
            key="use_sim_time")


@rule("L115", "component-condition-ignored")
def component_condition_ignored(ctx: CheckContext) -> Iterator[Diagnostic]:
    for span, raw, fqn in once(ctx, "ignored_conditions"):
        who = f'component "{fqn}"' if fqn else "this component"
        what = f"the condition {raw}" if raw else "the condition"
        yield Diagnostic(
            "L115", span,
            f"{what} of {who} is never evaluated on {ctx.distro}: "
            "LoadComposableNodes loads every composable node description it is given, so the "
            "component is loaded whatever the condition says",
            help="put the condition on the LoadComposableNodes / <load_composable_node> (one "
                 "per condition), or list the component in its container's "
                 "composable_node_descriptions, where humble does evaluate it",
            key=raw or "condition")
