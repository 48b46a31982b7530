"""Walk the launch IR the way ``LaunchService`` visits entities (SEMANTICS §1-§4).

Mirrored oddities: includes do not scope launch configurations; ``GroupAction`` copies the
configuration dict shallowly, so ``SetRemap``/``SetParameter`` lists created in an outer scope leak
out of scoped groups; timers and event handlers run after the description was processed, with the
top-level configurations (they lose a group's namespace and remaps); ``$(dirname)`` after an include
points at the included file's folder.
"""
from __future__ import annotations

import posixpath
from collections.abc import Callable
from dataclasses import dataclass, field, replace
from typing import TYPE_CHECKING, Any

from physai_lint.model import launch as ir
from physai_lint.model import values as vals
from physai_lint.model.fields import objects
from physai_lint.model.span import Span
from physai_lint.resolve import names
from physai_lint.resolve.evaluate import Evaluator, Scope
from physai_lint.resolve.model import (
    ConfigRead,
    DeclaredArg,
    IncludeRecord,
    LaunchResult,
    StartEdge,
)
from physai_lint.resolve.nodes import NodeBuilder, lifecycle_mismatch

if TYPE_CHECKING:
    from physai_lint.workspace import PackageIndex

Loader = Callable[[str], "ir.LaunchFile | None"]
# (file, the OpaqueAction, its performed values with the strings found for them) -> the action
# evaluated with them, or None (``files.FileStore.specialize``)
Specializer = Callable[[str, "ir.OpaqueAction", "tuple[tuple[Any, str], ...]"], "ir.OpaqueAction | None"]
# OpaqueFunctions evaluated again per entry: each costs a parse of its file (~2-20 ms).
MAX_SPECIALIZED = 200
MAX_ACTIONS = 200_000
# Events that change a lifecycle node's state (an event not known statically may be one)
_CHANGE_STATE = frozenset({"launch_ros.events.lifecycle.ChangeState", "unknown"})

REMAPS, PARAMS, NS = "ros_remaps", "global_params", "ros_namespace"


@dataclass
class Frame:
    """Where the walker is: file, activity, include chain, deferred context (the scoped groups
    are ``Instantiator.open_groups``)."""

    file: str
    active: bool | None
    chain: tuple[str, ...]
    deferred: str | None = None  # "timer" / event kind when run after the description
    delay: float | None = 0.0
    trigger: list[tuple[str, str, Span]] = field(default_factory=list)  # (action key, reason, span)
    lost: tuple[str, ...] = ()
    passed: frozenset[str] = frozenset()  # args the include that loaded this file passed
    passed_at: tuple[tuple[str, Span], ...] = ()  # where the include gives each of them
    # the directory launch runs the file from: the include's path (an installed share directory
    # for FindPackageShare), not where its source is; "" for the file's own directory
    dir: str = ""
    # which load of the file's actions this is: each include and each run of an OpaqueFunction
    # builds new action objects (the same action twice in one load is one object run twice)
    load: int = 0
    ran_by: Span | None = None  # the actions of the event handler that runs these (on_exit=[...])
    at_shutdown: bool = False  # run by an OnShutdown handler, directly or through a timer or handler


@dataclass(slots=True)
class Leak:
    """A SetRemap/SetParameter/SetParametersFromFile appended, inside a scoped group, to a list an
    outer scope created (``GroupAction`` copies the configurations shallowly): reported when a node
    launched after the group receives it (``receivers``: node ids, and where)."""

    item: Any  # kept: its id is the key of the leak
    span: Span
    what: str
    group: int  # the innermost group the action ran in
    outer: Span  # the outer action that created the list
    receivers: dict[str, Span] = field(default_factory=dict)  # node id -> its action


def combine(a: bool | None, b: bool | None) -> bool | None:
    if a is False or b is False:
        return False
    if a is None or b is None:
        return None
    return True


class Instantiator:
    def __init__(self, loader: Loader, packages: PackageIndex | None, explicit_entry: bool,
                 specialize: Specializer | None = None) -> None:
        self.loader = loader
        self.specialize = specialize
        self.specialized = 0  # OpaqueFunctions evaluated again with known values (MAX_SPECIALIZED)
        self.packages = packages
        self.explicit_entry = explicit_entry
        self.result: LaunchResult
        self.frame: Frame
        self.budget = MAX_ACTIONS
        # actions run later: (actions, locals, frame, the TimerAction whose period is performed first)
        self.deferred: list[tuple[tuple[ir.Action, ...], dict[str, Any], Frame, ir.Timer | None]] = []
        self.handlers: list[tuple[ir.EventHandler, Frame, dict[str, Any]]] = []
        # id(global list) -> (the scoped-group depth it was created at, the action that created it)
        self.list_origin: dict[int, tuple[int, Span]] = {}
        self.open_groups: list[int] = []  # the scoped groups being walked, outermost first
        self._groups = 0
        self.leaks: dict[int, Leak] = {}  # id(list item) -> a leak waiting for a node after its group
        self.ev = Evaluator(packages, self._on_read, self._on_package, self._on_bad_condition)
        self.ev.on_bad_expression = self._on_bad_expression
        self.ev.on_glued_command = self._on_glued_command
        self.ev.on_unused_rewrite = self._on_unused_rewrite
        self.ev.on_dirname = self._on_dirname
        self.nodes = NodeBuilder(self)
        self.visited: dict[str, bool | None] = {}
        self.loads = 0  # Frame.load of the last file loaded or function run
        self.executed: dict[tuple[int, str], str] = {}  # (Frame.load, process action key) -> first node id
        # Which actions start: those visited outside any event handler (``free``), and, for those
        # visited only in handlers' actions, the targets each visit waits for (``triggered``: key
        # -> (the action, [target keys of one visit, ...])); ``NodeBuilder.finish`` closes it.
        self.free: set[str] = set()
        # OnExecutionComplete handlers registered after their target was visited: target key ->
        # the handlers (emptied when the target is visited again)
        self.late_handlers: dict[str, list[ir.EventHandler]] = {}
        # actions visited in launch's synchronous first pass (outside timers and handlers), and
        # those visited in a deferred one: only the first pass's order is the order they run in
        self.first_pass: set[str] = set()
        self.deferred_visits: set[str] = set()
        self.read_note = ""  # what ConfigReads made now are (``ConfigRead.note``)
        self.read_site: Span | None = None  # the condition being evaluated (``ConfigRead.site``)
        self.triggered: dict[str, tuple[ir.Action, list[tuple[tuple[str, str, Span], ...]]]] = {}
        # lifecycle node action key -> (key, span) of the EmitEvent(ChangeState) actions naming it
        self.change_requests: dict[str, list[tuple[str, Span]]] = {}
        # the files in which an action or include the linter cannot follow ran: it may have
        # declared or set any launch configuration their later reads ask for (includes and opaque
        # functions do not scope them). Reads in other files stay checked: in a large system
        # (Autoware) some include is always outside the workspace, and a configuration its
        # includer reads after it is the includer's mistake far more often than its doing.
        self.configs_open: set[str] = set()

    # ---- hooks -------------------------------------------------------------------------------
    def _on_read(self, name: str, span: Span | None, defined: bool, has_default: bool) -> None:
        if span is None:
            return
        # after an action or include the linter cannot follow, "nothing set it" is not known
        defined = defined or self.frame.file in self.configs_open
        self.result.config_reads.append(ConfigRead(name, span, defined, has_default, self.frame.active,
                                                   self.read_note, self.read_site))
        for arg in self.declared_by_name.get(name, ()):
            arg.reads += 1

    def reads_every_configuration(self, span: Span) -> None:
        """Something at ``span`` may read any launch configuration (a parameter file with
        ``allow_substs`` whose path is unknown): an open read along the chain of files that leads
        to it. No argument passed to an include holding it counts as ignored (L106,
        ``resolve/includes.py``), nor one declared along the chain as unused (L102)."""
        self.result.open_reads.append((span, self.frame.chain))

    def _on_package(self, name: str, span: Span | None, from_config: bool | str) -> None:
        self.result.package_refs.append((name, span, self.frame.file, from_config))

    def _on_dirname(self, span: Span | None, scope: Scope) -> None:
        owner = scope.locals.get("_owner")
        if span is not None and owner and owner != self.frame.file and self.frame.deferred is None:
            got = scope.locals.get("current_launch_file_directory", "")
            own = self.frame.dir or posixpath.dirname(self.frame.file)
            self.result.dirname_traps.append((span, str(got), own))

    def _on_bad_condition(self, span: Span | None, text: str, how: str) -> None:
        if span is not None and self.frame.active is not False:
            self.result.invalid_conditions.append((span, text, how))

    def _on_bad_expression(self, span: Span | None, text: str, why: str) -> None:
        if span is not None and self.frame.active is not False:
            self.result.expression_errors.append((span, text, why))

    def _on_unused_rewrite(self, span: Span, key: str, source: str) -> None:
        if self.frame.active is not False:
            self.result.unused_rewrites.append((span, key, source))

    def _on_glued_command(self, span: Span | None, left: str, right: str, line: str) -> None:
        if span is not None and self.frame.active is not False:
            self.result.glued_commands.append((span, left, right, line))

    # ---- entry -------------------------------------------------------------------------------
    def run(self, entry: str, cli_args: dict[str, str]) -> LaunchResult:
        self.result = LaunchResult(entry=entry, arguments=dict(cli_args), given=tuple(sorted(cli_args)))
        self.declared_by_name: dict[str, list[DeclaredArg]] = {}  # result.declared_args by name
        scope = Scope(configs=dict(cli_args))
        self.top_configs = scope.configs
        self.frame = Frame(entry, True, (entry,), passed=frozenset(cli_args))
        lf = self.loader(entry)
        if lf is None:
            return self.result
        self.result.files.append(entry)
        # ros2 launch includes the entry with the command line's arguments, and refuses to run it
        # unless each required one is given (IncludeLaunchDescription.execute): set, whatever
        # their value, before the first action reads them.
        from physai_lint.resolve.includes import required_missing

        for d in required_missing(lf.actions, scope.configs):
            scope.configs.setdefault(d.name, None)
        # ``ros2 launch <package> <file>`` runs the installed copy: ThisLaunchFileDir() / $(dirname)
        # is its folder in the install space, where only what the package installs is beside it
        shown = (self.packages.installed_copy(entry) if self.packages is not None else None) or entry
        if shown != entry:
            self.frame = replace(self.frame, dir=posixpath.dirname(shown))
        scope.locals = {"current_launch_file_directory": posixpath.dirname(shown),
                        "current_launch_file_path": shown, "_owner": entry}
        self.lookups(lf, scope)
        self._walk(lf.actions, scope)
        self._run_deferred(scope)
        for arg in self.result.declared_args:
            if arg.file == entry and arg.name not in self.result.arguments:
                self.result.arguments[arg.name] = arg.value
        self.nodes.finish()
        return self.result

    def lookups(self, lf: ir.LaunchFile, scope: Scope) -> None:
        """The package lookups building a Python file's description surely makes
        (``PythonFacts.lookups``): each package is looked up when the file is loaded."""
        if lf.python is None:
            return
        for value in lf.python.lookups:
            self.ev.eval(value, scope)
        for value, span in lf.python.opens:
            path = self.ev.eval(value, scope)
            if path is not None:
                self.result.opened_files.append((path, span))

    # ---- walking -----------------------------------------------------------------------------
    def _walk(self, actions: tuple[ir.Action, ...], scope: Scope) -> None:
        for action in actions:
            self.budget -= 1
            if self.budget < 0:
                self.result.opaque.append((action.span, "too many actions: resolution stopped"))
                return
            self._visit(action, scope)

    def _visit(self, a: ir.Action, scope: Scope) -> None:
        outer = self.frame
        active = outer.active
        if a.condition is not None:
            # elsewhere the LaunchConfiguration's own place says more (a value a helper builds, what
            # an OpaqueFunction's body performs)
            self.read_site = a.condition.span
            try:
                active = combine(active, self.ev.condition(a.condition.kind, a.condition.value, scope,
                                                           a.condition.span))
            finally:
                self.read_site = None
        # Frames are never mutated: an action that changes nothing keeps its parent's frame (most
        # do; a dataclasses.replace per action was a tenth of resolving a large workspace).
        self.frame = outer if active is outer.active else replace(outer, active=active)
        key = f"{outer.file}#{a.id}"
        prev = self.visited.get(key, False)
        self.visited[key] = True if (prev is True or self.frame.active is True) else (
            None if (prev is None or self.frame.active is None) else False)
        if self.late_handlers and key in self.late_handlers:
            del self.late_handlers[key]  # visited again: now with the handler registered
        if self.frame.deferred is None:
            self.first_pass.add(key)
        else:
            self.deferred_visits.add(key)
        if self.frame.active is not False:
            if not self.frame.trigger:
                self.free.add(key)
            elif key not in self.free:
                entry = self.triggered.get(key)
                if entry is None:
                    entry = self.triggered[key] = (a, [])
                entry[1].append(tuple(self.frame.trigger))
        try:
            if self.frame.active is False and outer.active is not False:
                # Skipped by real launch: walk a throwaway copy so its nodes show as inactive.
                shadow = Scope(configs=scope.copy_configs(), locals=dict(scope.locals))
                self._dispatch(a, shadow)
            else:
                self._dispatch(a, scope)
        finally:
            self.frame = outer

    def _dispatch(self, a: ir.Action, scope: Scope) -> None:
        if isinstance(a, ir.DeclareArgument):
            self._declare(a, scope)
        elif isinstance(a, ir.SetLaunchConfiguration):
            name = self.ev.eval(a.name, scope)
            value = self.ev.eval(a.value, scope)
            if name is not None:
                scope.configs[name] = value
        elif isinstance(a, ir.Include):
            self._include(a, scope)
        elif isinstance(a, ir.Group):
            self._group(a, scope)
        elif isinstance(a, ir.ResetLaunchConfigurations):
            keep = {}
            for k, val in a.keep or ():
                kn = self.ev.eval(k, scope)
                if kn is not None:
                    keep[kn] = self.ev.eval(val, scope)
            scope.configs.clear()
            scope.configs.update(keep)
        elif isinstance(a, ir.PushNamespace):
            self._push_namespace(a, scope)
        elif isinstance(a, ir.SetRemap):
            src, dst = self.ev.eval(a.src, scope), self.ev.eval(a.dst, scope)
            self._append_global(scope, REMAPS, (src, dst, a.span, []), a.span, f'remap "{src}:={dst}"')
            self.result.set_remaps.append((a.span, src, dst, scope.configs[REMAPS][-1][3]))
        elif isinstance(a, ir.SetParameter):
            # SetParameter.execute evaluates the value then, not when a node reads the list
            name = self.ev.eval(a.name, scope)
            typed, cli = self.nodes.global_parameter(name, a.value, scope, a.span) if name is not None \
                else (None, None)
            self._append_global(scope, PARAMS, ("param", name, typed, a.span, cli), a.span,
                                f'parameter "{name}"')
        elif isinstance(a, ir.SetParametersFromFile):
            self._append_global(scope, PARAMS, ("file", self.ev.eval(a.path, scope), a.path, a.span),
                                a.span, "parameter file")
        elif isinstance(a, ir.SetUseSimTime):
            self.result.use_sim_time_actions.append(a.span)
            self.ev.eval(a.value, scope)
        elif isinstance(a, ir.NodeAction):
            self.nodes.node(a, scope)
        elif isinstance(a, ir.LoadComposableNodes):
            self.nodes.load(a, scope)
        elif isinstance(a, ir.ExecuteProcess):
            self.nodes.process(a, scope)
        elif isinstance(a, ir.Timer):
            self._timer(a, scope)
        elif isinstance(a, ir.EventHandler):
            fr = replace(self.frame, lost=self._scope_losses(scope))
            self.handlers.append((a, fr, dict(scope.locals)))
            if a.event == "on_state_transition" and fr.active is not False:
                why = lifecycle_mismatch(a.start_state, a.goal_state)
                if why is not None:
                    self.result.never_started.append((a.span, why))
            if a.event == "on_execution_complete" and a.target_id and fr.active is not False:
                # Action.visit arranges ExecutionComplete only if a handler for it is registered
                # by then: a target already visited (and not visited again) never emits it
                target = f"{fr.file}#{a.target_id}"
                # certain only for a target visited in the first pass alone: that pass precedes
                # every deferred one, where the walk's order is not the order actions run in
                if self.visited.get(target, False) is not False and target not in self.deferred_visits:
                    self.late_handlers.setdefault(target, []).append(a)
        elif isinstance(a, ir.OpaqueAction):
            outer = self.frame
            self.frame = replace(outer, load=self.next_load())  # the function builds new objects
            try:
                if (a.reason and a.other or a.again) and self.specialize is not None \
                        and self.specialized < MAX_SPECIALIZED:
                    self._opaque_function(a, scope)
                    return
                if a.reason:
                    self._open(a)
                for value in a.other:
                    self.ev.eval(value, scope)
                self._walk(a.actions, scope)
            finally:
                self.frame = outer
        elif isinstance(a, ir.EmitEvent):
            if a.event in _CHANGE_STATE and self.frame.active is not False:
                target = f"{self.frame.file}#{a.target_id}" if a.target_id else None
                self.result.lifecycle_changes.append((target, a.span))
                if target is not None:
                    self.change_requests.setdefault(target, []).append((f"{self.frame.file}#{a.id}", a.span))
                if a.matcher_span is not None and (target or a.target_name):
                    self.result.change_matchers.append(
                        ("action", target, a.matcher_span) if target else ("name", a.target_name, a.matcher_span))
        elif isinstance(a, (ir.Log, ir.Shutdown)):
            for val in (getattr(a, "message", None), getattr(a, "reason", None)):
                self.ev.eval(val, scope)
        elif isinstance(a, ir.SetEnvironment):
            name = self.ev.eval(a.name, scope)
            if self.frame.active is not False:
                self.ev.env_set.add(name)
            self.ev.eval(a.value, scope)

    def _open(self, a: ir.OpaqueAction) -> None:
        self.note_opaque((a.span, a.reason))
        if self.frame.active is not False:
            self.configs_open.add(self.frame.file)  # its actions may set any configuration

    def _opaque_function(self, a: ir.OpaqueAction, scope: Scope) -> None:
        """An OpaqueFunction whose body the frontend lost track of, given what it performs
        (``a.other``), or whose body lost values a launch configuration may decide (``a.again``):
        evaluated again with the values found here (``frontends.python.specialize``), as launch runs
        it with the launch configurations of this moment. If it cannot be, the first evaluation
        stands: opaque, or its actions. The values are read once, before either (a read the
        function makes either way)."""
        values = a.other if a.reason else a.again
        found = tuple((value, text) for value in values if (text := self.ev.eval(value, scope)) is not None)
        done = None
        if found and self.specialize is not None:  # (set: the caller checked; for the type checker)
            try:
                done = self.specialize(self.frame.file, a, found)
            except Exception as exc:  # noqa: BLE001 - a crash is a finding (X003), and the function stays opaque
                from physai_lint.files import internal_error

                self.result.diagnostics.append(internal_error(self.frame.file, "python frontend (OpaqueFunction "
                                                              "evaluated with its arguments)", exc))
        if done is None:
            if a.reason:
                self._open(a)
            self._walk(a.actions, scope)
            return
        self.specialized += 1
        for value in done.other:  # what it performs once past the point the first evaluation reached
            if value not in values:
                self.ev.eval(value, scope)
        self._walk(done.actions, scope)
        # What the first evaluation's actions read that these do not: reads in the branches these
        # values did not take, which launch makes under other arguments; kept as reads of
        # inactive actions are (an argument only they read is not unused, L102).
        taken = {name for name, _ in _config_reads(done.actions)}
        for name, config in _config_reads(a.actions):
            if name not in taken and config.span is not None:
                self.result.config_reads.append(ConfigRead(name, config.span, True, config.default is not None, False))
                for arg in self.declared_by_name.get(name, ()):
                    arg.reads += 1

    # ---- arguments -----------------------------------------------------------------------------
    def _declare(self, a: ir.DeclareArgument, scope: Scope) -> None:
        default = self.ev.eval(a.default, scope) if a.default is not None else None
        origin = "none"
        if a.name in scope.configs:
            val = scope.configs[a.name]
            value = val if isinstance(val, str) else None
            if a.name in self.frame.passed:
                origin = "command-line" if self.frame.file == self.result.entry else "include"
            else:
                origin = "include"
        elif a.default is not None:
            value, origin = default, "default"
            scope.configs[a.name] = default
        else:
            value = None
            scope.configs[a.name] = None  # real launch raises; keep going with an unknown value
        decl = DeclaredArg(
            name=a.name, span=a.name_span or a.span, file=self.frame.file, default=default,
            default_known=a.default is None or default is not None, has_default=a.default is not None,
            choices=a.choices, value=value, value_origin=origin,  # type: ignore[arg-type]
            value_span=dict(self.frame.passed_at).get(a.name) if origin == "include" else None,
        )
        self.result.declared_args.append(decl)
        self.declared_by_name.setdefault(a.name, []).append(decl)

    # ---- namespaces and global lists -------------------------------------------------------------
    def _push_namespace(self, a: ir.PushNamespace, scope: Scope) -> None:
        raw = self.ev.eval(a.namespace, scope)
        base = scope.configs.get(NS)
        if raw is None or (NS in scope.configs and base is None):
            scope.configs[NS] = None
            self.result.pushed_namespaces.append((a.span, raw, None))
            return
        new = names.make_namespace_absolute(names.prefix_namespace(base, raw))
        scope.configs[NS] = new
        self.result.pushed_namespaces.append((a.span, raw, new))

    def _append_global(self, scope: Scope, key: str, item: Any, span: Span, what: str) -> None:
        lst = scope.configs.get(key)
        if not isinstance(lst, list):
            lst = []
            scope.configs[key] = lst
            self.list_origin[id(lst)] = (len(self.open_groups), span)
        else:
            depth, outer = self.list_origin.get(id(lst), (0, span))
            if len(self.open_groups) > depth and self.frame.deferred is None:
                # Appended to an outer scope's list: a leak once a node outside the group this
                # action runs in (the innermost) reads it.
                self.leaks[id(item)] = Leak(item, span, what, self.open_groups[-1], outer)
        lst.append(item)

    def leaks_reaching(self, lst: list[Any], node_id: str, node_span: Span,
                       effective: Callable[[list[Any], int], bool]) -> None:
        """A node (``node_id``, at ``node_span``) reads a global list: the leaked items in it whose
        group is over (the node comes after the group, or in a later one) reach it, unless
        ``effective`` says they change nothing for it."""
        for i, item in enumerate(lst):
            leak = self.leaks.get(id(item))
            if leak is None or leak.group in self.open_groups or node_id in leak.receivers \
                    or not effective(lst, i):
                continue
            if not leak.receivers:
                self.result.scope_leaks.append((leak.span, leak.what, leak.outer, leak.receivers))
            leak.receivers[node_id] = node_span

    # ---- groups and includes ---------------------------------------------------------------------
    def _group(self, a: ir.Group, scope: Scope) -> None:
        sets = [(self.ev.eval(k, scope), self.ev.eval(val, scope)) for k, val in a.launch_configurations]
        if not a.scoped:
            for k, val in sets:
                if k is not None:
                    scope.configs[k] = val
            self._walk(a.actions, scope)
            return
        saved = scope.configs
        inner = dict(saved) if a.forwarding else {}
        for k, val in sets:
            if k is not None:
                inner[k] = val
        scope.configs = inner
        self._groups += 1
        self.open_groups.append(self._groups)
        try:
            self._walk(a.actions, scope)
        finally:
            self.open_groups.pop()
            scope.configs = saved

    def _include(self, a: ir.Include, scope: Scope) -> None:
        from physai_lint.resolve.includes import include

        before = len(self.result.includes)
        include(self, a, scope)
        rec = self.result.includes[before] if len(self.result.includes) > before else None
        if rec is not None and rec.status not in ("ok", "cycle") and rec.active is not False:
            self.configs_open.add(self.frame.file)  # the file it names may set any configuration

    # ---- deferred: timers and event handlers -----------------------------------------------------
    def _timer(self, a: ir.Timer, scope: Scope) -> None:
        # TimerAction.execute only schedules _wait_to_fire_event, which performs the period when
        # the loop next runs: after the whole description was visited, so with the launch
        # configurations (and locals) left at the top, not this scope's (a group around it has
        # popped its own by then). Its actions run later still (_run_deferred).
        lost = self._scope_losses(scope)
        fr = replace(self.frame, deferred="timer", lost=tuple(lost), trigger=list(self.frame.trigger))
        self.deferred.append((a.actions, dict(scope.locals), fr, a))

    def _timer_fires(self, a: ir.Timer, top: Scope) -> Frame:
        """The period of timer ``a`` (``self.frame`` is the timer's), performed as
        ``_wait_to_fire_event`` does; the frame its actions run in."""
        self.read_note = "timer period"
        try:
            text = self.ev.eval(a.period, top)
        finally:
            self.read_note = ""
        period: float | None = None
        if text is not None:
            try:
                period = float(text)
            except ValueError:
                period = None
        self.result.timers.append((a.span, period, text if text is not None else "unknown"))
        fr = self.frame
        delay = None if period is None or fr.delay is None else fr.delay + period
        return replace(fr, delay=delay)

    def _scope_losses(self, scope: Scope) -> tuple[str, ...]:
        """What actions deferred from here lose: they run with the top-level configurations."""
        if self.frame.deferred is not None:
            return self.frame.lost
        lost = []
        ns = scope.configs.get(NS)
        if ns and ns != "/" and ns != self.top_configs.get(NS):  # PushRosNamespace('') pushes "/"
            lost.append(f'namespace "{ns}"')
        top_remaps = self.top_configs.get(REMAPS) or []
        for item in scope.configs.get(REMAPS) or []:
            if not any(item is t for t in top_remaps):
                lost.append(f'remap "{item[0]}:={item[1]}"')
        return tuple(lost)

    def _run_deferred(self, top: Scope) -> None:
        rounds = 0
        while (self.deferred or self.handlers) and rounds < 50:
            rounds += 1
            handlers, self.handlers = self.handlers, []
            for h, fr, locals_ in handlers:
                self._handler(h, fr, locals_, top)
            deferred, self.deferred = self.deferred, []
            for actions, locals_, fr, timer in deferred:
                scope = Scope(configs=top.configs, locals=locals_)
                outer = self.frame
                self.frame = fr
                try:
                    if timer is not None:
                        self.frame = self._timer_fires(timer, top)
                    self._walk(actions, scope)
                finally:
                    self.frame = outer

    def _handler(self, h: ir.EventHandler, fr: Frame, locals_: dict[str, Any], top: Scope) -> None:
        key = f"{fr.file}#{h.target_id}" if h.target_id else None
        trigger = list(fr.trigger)
        if key is not None and h.event in ("on_process_start", "on_process_exit",
                                           "on_execution_complete", "on_state_transition"):
            trigger.append((key, h.event, h.span))
        self.nodes.watch(h, key, fr)
        self.deferred.append((h.actions, locals_,
                              replace(fr, deferred=h.event, trigger=trigger, ran_by=h.actions_span or h.span,
                                      active=fr.active if h.event != "on_shutdown" else None,
                                      at_shutdown=fr.at_shutdown or h.event == "on_shutdown"), None))

    def add_edge(self, before: str, after: str, reason: str, span: Span, delay: float | None) -> None:
        self.result.edges.append(StartEdge(before, after, reason, span, delay))

    def close(self) -> None:
        """Drop the references back to this walker (the evaluator's hooks are its bound methods,
        the node builder points at it): a finished walk is then freed by reference counting
        instead of waiting for the cyclic collector."""
        ev = self.ev
        ev.on_read = ev.on_package = ev.on_bad_condition = ev.on_dirname = ev.on_bad_expression = None
        ev.on_glued_command = ev.on_unused_rewrite = None
        self.nodes.inst = None  # type: ignore[assignment]
        self.deferred.clear()
        self.handlers.clear()

    # ---- includes helpers used by resolve.includes ------------------------------------------------
    def next_load(self) -> int:
        self.loads += 1
        return self.loads

    def new_record(self, rec: IncludeRecord) -> None:
        self.result.includes.append(rec)

    def note_opaque(self, part: tuple[Span, str]) -> None:
        """A part of the launch that cannot be known statically (``LaunchResult.opaque``), and
        whether its condition disables it in this run (``inactive_opaque``)."""
        self.result.opaque.append(part)
        if self.frame.active is False:
            self.result.inactive_opaque.append(part)


def _config_reads(actions: tuple[ir.Action, ...]) -> list[tuple[str, vals.LaunchConfig]]:
    """The launch configurations of literal name that ``actions`` read, with their substitutions."""
    return [(o.name[0].text, o) for o in objects(actions)
            if isinstance(o, vals.LaunchConfig) and len(o.name) == 1 and isinstance(o.name[0], vals.Text)]


def resolve_launch(entry: str, cli_args: dict[str, str], loader: Loader,
                   packages: PackageIndex | None, explicit_entry: bool = True,
                   specialize: Specializer | None = None) -> LaunchResult:
    """Resolve one entry launch file as ``ros2 launch`` would, with ``NAME:=VALUE`` arguments.
    ``specialize``: evaluates a Python launch file's OpaqueFunction again with the values its
    substitutions have here (``files.FileStore.specialize``); without it such functions stay opaque."""
    inst = Instantiator(loader, packages, explicit_entry, specialize)
    try:
        return inst.run(entry, cli_args)
    finally:
        inst.close()

