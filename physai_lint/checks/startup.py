"""Startup order: S101 startup-cycle, S102 handler-never-fires, S103 invalid-timer-period,
S104 process-run-twice, S105 process-started-at-shutdown, S106 exit-of-long-running-node."""
from __future__ import annotations

import math
from collections.abc import Iterator

from physai_lint.checks._params import effective, interface
from physai_lint.checks._util import ACTION_CLASSES, command_words, once
from physai_lint.checks.base import CheckContext, rule
from physai_lint.model.findings import Diagnostic, Related
from physai_lint.resolve.model import NodeInstance
from physai_lint.resolve.nodes import EVENT_VERB, never_fires_help


@rule("S101", "startup-cycle")
def startup_cycle(ctx: CheckContext) -> Iterator[Diagnostic]:
    from physai_lint.graph.plan import startup_cycles

    for span, text, steps, others, lifecycle in once(ctx, "trigger_cycles", lambda e: e[:2]):
        yield Diagnostic(
            "S101", span,
            f"startup cycle {text}: {steps}; " + (
                "the lifecycle node never changes state, so nothing waiting for its transitions runs"
                if lifecycle else "each only starts from another's event handler, so none of them ever starts"),
            help="request the first transition outside the cycle: emit its ChangeState at the top level, or "
                 "from an OnProcessStart of the lifecycle node" if lifecycle else
                 "add one of them to the launch description directly (it is the root of the chain)",
            related=tuple(Related(s, "handler in the cycle") for s in others),
            key=text)
    seen: set[object] = set()
    for launch in ctx.launches:
        if not launch.edges:
            continue
        plan = startup_cycles(launch, lambda n: effective(ctx, n))
        labels = plan.labels
        for cyc in plan.cycles:
            if not cyc.deadlock:
                continue  # a member starts: launch runs an action twice, not a deadlock
            handlers = sorted({e.span for e in cyc.edges if e.span is not None and e.reason in EVENT_VERB},
                              key=lambda s: (s.file, s.line, s.col))
            if not handlers:
                continue
            span = handlers[0]
            key = frozenset(cyc.nodes)
            if (span, key) in seen:
                continue
            seen.add((span, key))
            steps = []
            for e in cyc.edges:
                what = EVENT_VERB.get(e.reason, e.reason)
                steps.append(f'"{labels[e.after]}" waits for {what} of "{labels[e.before]}"')
            yield Diagnostic(
                "S101", span,
                f"startup cycle {cyc.text(labels)}: " + ", ".join(steps)
                + "; each only starts from another's event handler, so none of them ever starts",
                help="add one of them to the launch description directly (it is the root of the chain)",
                related=tuple(Related(s, "handler in the cycle") for s in handlers[1:]),
                key=cyc.text(labels))


@rule("S102", "handler-never-fires")
def handler_never_fires(ctx: CheckContext) -> Iterator[Diagnostic]:
    for span, why in once(ctx, "never_started"):
        yield Diagnostic("S102", span, f"this event handler never fires: {why}, so its actions never run",
                         help=never_fires_help(why), key=why)


@rule("S103", "invalid-timer-period")
def invalid_timer_period(ctx: CheckContext) -> Iterator[Diagnostic]:
    seen: set[object] = set()
    for launch in ctx.launches:
        for span, period, text in launch.timers:
            if span in seen:
                continue
            if period is not None and (period < 0 or math.isnan(period)):
                msg = f"TimerAction period {text} is negative: not a number of seconds to wait"
            elif period is None and text != "unknown":
                msg = f'TimerAction period "{text}" is not a number: launch raises when the timer runs'
            else:
                continue
            seen.add(span)
            yield Diagnostic("S103", span, msg, help="give the period as a non-negative float, e.g. 3.0",
                             key=text)


@rule("S104", "process-run-twice")
def process_run_twice(ctx: CheckContext) -> Iterator[Diagnostic]:
    from physai_lint.graph.plan import startup_cycles

    seen: set[object] = set()
    for launch in ctx.launches:
        if not launch.repeated:
            continue
        nodes = {n.id: n for n in launch.nodes}
        never: set[str] | None = None
        for first, again, where in launch.repeated:
            a, b = nodes.get(first), nodes.get(again)
            if a is None or b is None or a.active is not True or b.active is not True:
                continue  # a condition may keep one of the runs from happening
            if never is None:  # a handler that never fires runs nothing
                never = startup_cycles(launch, lambda n: effective(ctx, n)).never_starts
            if first in never or again in never:
                continue
            span = where or b.span
            if (span, b.span) in seen:
                continue
            seen.add((span, b.span))
            what = a.executable or "process"
            how = (f"the event handler at line {where.line} runs it again" if where is not None
                   and a.span.file == where.file else "an event handler runs it again" if where is not None
                   else "a timer runs it again" if b.in_timer else "the launch description runs it twice")
            yield Diagnostic(
                "S104", span,
                f'the {ACTION_CLASSES.get(a.kind, "process")} action "{a.fqn or what}" ({a.package}/{what}) is one object run '
                f"twice: {how}; launch runs an action object once, and the second run raises "
                f"\"ExecuteLocal action '{what}-N': executed more than once\", which ends the launch",
                help="run it once: drop the second reference, or build a second action (a function that "
                     "returns a new Node(...) each time it is called)",
                related=(Related(a.span, "the action"),) if span != a.span else (),
                key=f"{a.action_id}")


@rule("S105", "process-started-at-shutdown")
def process_started_at_shutdown(ctx: CheckContext) -> Iterator[Diagnostic]:
    seen: set[object] = set()
    for launch in ctx.launches:
        if not launch.at_shutdown:
            continue
        nodes = {n.id: n for n in launch.nodes}
        for node_id, handler in launch.at_shutdown:
            node = nodes.get(node_id)
            if node is None or node.active is False or node.span in seen:
                continue
            seen.add(node.span)
            yield Diagnostic(
                "S105", handler or node.span,
                f"the {ACTION_CLASSES.get(node.kind, 'ExecuteProcess')} action {_label(node)} is started by an OnShutdown "
                "handler: when the launch ends on Ctrl-C (SIGINT) or because its processes have all "
                "exited, launch marks itself as shutting down before the handlers run, and "
                "ExecuteLocal.execute starts nothing then; it runs only when the launch file emits "
                "Shutdown itself",
                help="do the work before shutdown (an OnProcessExit of the process whose end should "
                     "trigger it, or the node's own shutdown callback), or end the launch with the "
                     "Shutdown action / EmitEvent(event=Shutdown()) instead of Ctrl-C",
                related=(Related(node.span, "the action"),) if handler is not None and handler != node.span else (),
                key=node.action_id)


@rule("S106", "exit-of-long-running-node")
def exit_of_long_running_node(ctx: CheckContext) -> Iterator[Diagnostic]:
    """An OnProcessExit handler that starts processes when a node exits that runs until the launch
    shuts down: they start only if it crashes (then launch is not shutting down), never in normal
    operation, and not on Ctrl-C either (``ExecuteLocal.execute`` starts nothing once launch is
    shutting down). Usually meant: OnProcessStart."""
    seen: set[object] = set()
    for launch in ctx.launches:
        if not launch.edges:
            continue
        nodes = {n.id: n for n in launch.nodes}
        started: dict[tuple[str, object], list[NodeInstance]] = {}
        for edge in launch.edges:
            if edge.reason != "on_process_exit":
                continue
            before, after = nodes.get(edge.before), nodes.get(edge.after)
            if before is None or after is None or before.active is False or after.active is False:
                continue
            started.setdefault((edge.before, edge.span), []).append(after)
        for (before_id, span), afters in started.items():
            before = nodes[before_id]
            why = _runs_until_shutdown(ctx, before)
            if why is None or (span, before.span) in seen:
                continue
            seen.add((span, before.span))
            names = sorted({_label(a) for a in afters})
            what = names[0] if len(names) == 1 else ", ".join(names[:3]) + (" ..." if len(names) > 3 else "")
            yield Diagnostic(
                "S106", span,
                f"this OnProcessExit handler starts {what} when {_label(before)} exits, but that node runs "
                f"until the launch shuts down ({why}), and launch starts nothing once it is shutting down "
                "(ExecuteLocal.execute): the handler's processes start only if the node crashes",
                help="to start them once the node is up, use OnProcessStart (or a TimerAction); keep "
                     "OnProcessExit for processes that end by themselves (spawners, one-shot scripts)",
                related=(Related(before.span, "the long-running node"),) if before.span != span else (),
                key=f"{before.action_id}")


def _runs_until_shutdown(ctx: CheckContext, node: NodeInstance) -> str | None:
    """Why ``node`` serves until shutdown, or None when it may end by itself (or that is not
    known): a container, a lifecycle node, a node whose code offers services or actions, or a
    node of a bundled description that both subscribes and publishes (a processing node; a
    bundled one-shot tool such as ros_gz_sim ``create`` only subscribes, if at all)."""
    if node.kind == "container":
        return "a component container"
    if node.kind == "lifecycle_node":
        return "a lifecycle node"
    iface = interface(ctx, node) if node.kind == "node" else None
    if iface is None:
        return None
    if iface.lifecycle:
        return "its code makes a lifecycle node"
    for kind, noun in (("services", "services"), ("action_servers", "actions")):
        if iface.endpoints(kind) or any(k == kind for k, _ in iface.unnamed):
            return f"it offers {noun}: {iface.source}" if iface.source else f"it offers {noun}"
    if iface.source.startswith("bundled") and iface.endpoints("subscribers") and iface.endpoints("publishers"):
        return f"it subscribes and publishes: {iface.source}"
    return None


def _label(node: NodeInstance) -> str:
    """How S105 names a process: its full name and package/executable, else package/executable,
    else an ExecuteProcess's command line."""
    what = node.executable or "process"
    if node.package:
        return f'"{node.fqn}" ({node.package}/{what})' if node.fqn else f'"{node.package}/{what}"'
    words = command_words(node) if node.kind == "process" else None
    return f'"{" ".join(w or "<unknown>" for w in words)}"' if words else f'"{what}"'
