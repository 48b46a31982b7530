"""Evaluated launch objects -> IR actions, with file-unique ids."""
from __future__ import annotations

from typing import TYPE_CHECKING, Any

from physai_lint.model import launch as L
from physai_lint.model.span import Span
from physai_lint.model.values import BoolOp, Text, Unknown, Value, literal_of

from . import api
from .convert_values import (
    item_spans,
    opt_value,
    span_at,
    to_condition,
    to_params,
    to_pvalue,
    to_value,
)
from .runtime import Alternatives, Branched, CondTag, LObj, Opaque, type_name

if TYPE_CHECKING:
    from .evaluator import Evaluator

_SOURCES = {
    "PythonLaunchDescriptionSource": "python", "XMLLaunchDescriptionSource": "xml",
    "YAMLLaunchDescriptionSource": "yaml", "FrontendLaunchDescriptionSource": "frontend",
    "AnyLaunchDescriptionSource": "any", "LaunchDescriptionSource": "any",
}
_EVENTS = {
    "OnProcessStart": ("on_process_start", "on_start"), "OnProcessExit": ("on_process_exit", "on_exit"),
    "OnExecutionComplete": ("on_execution_complete", "on_completion"),
    "OnShutdown": ("on_shutdown", "on_shutdown"), "OnStateTransition": ("on_state_transition", "entities"),
    "OnProcessIO": ("on_process_io", "on_stdout"),
    "OnIncludeLaunchDescription": ("on_include_launch_description", "entities"),
}
_NODE_KINDS = {"Node": "node", "LifecycleNode": "lifecycle_node", "ComposableNodeContainer": "container"}
_ENV_OPS = {"SetEnvironmentVariable": "set", "UnsetEnvironmentVariable": "unset",
            "AppendEnvironmentVariable": "append", "ResetEnvironment": "reset"}


# Arguments that launch turns into substitutions (``normalize_to_list_of_substitutions``), per
# action: (position, keyword). A bool or a number there is neither a str nor a Substitution nor an
# iterable of them, so building or running the action raises TypeError ("'bool' object is not
# iterable"). ``_TEXT_ITEMS``: lists whose every item is normalized the same way.
_NODE_TEXT = ((-1, "package"), (-1, "executable"), (-1, "name"), (-1, "namespace"), (-1, "exec_name"))
_TEXT_ARGS: dict[str, tuple[tuple[int, str], ...]] = {
    "DeclareLaunchArgument": ((-1, "default_value"),),
    "SetLaunchConfiguration": ((0, "name"), (1, "value")),
    "SetEnvironmentVariable": ((0, "name"), (1, "value")),
    "AppendEnvironmentVariable": ((0, "name"), (1, "value")),
    "UnsetEnvironmentVariable": ((0, "name"),),
    "LogInfo": ((-1, "msg"),),
    "PushRosNamespace": ((0, "namespace"),),
    "PushROSNamespace": ((0, "namespace"),),
    "SetRemap": ((0, "src"), (1, "dst")),
    "ExecuteProcess": ((-1, "name"), (-1, "cwd")),
    "Node": _NODE_TEXT, "LifecycleNode": _NODE_TEXT, "ComposableNodeContainer": _NODE_TEXT,
}
_TEXT_ITEMS: dict[str, tuple[str, ...]] = {
    "ExecuteProcess": ("cmd",),
    "Node": ("arguments", "ros_arguments"), "LifecycleNode": ("arguments", "ros_arguments"),
    "ComposableNodeContainer": ("arguments", "ros_arguments"),
}


def _not_text(v: Any) -> bool:
    return type(v) in (bool, int, float)


# ExecuteLocal arguments normalized to substitutions that no rule models (``NodeAction.other``).
_OTHER_ARGS = ("output", "prefix", "cwd", "sigterm_timeout", "sigkill_timeout")


# Arguments launch keeps as given and uses as a plain bool or number, never substituting them
# (``ExecuteLocal.__init__``, ``GroupAction.__init__``): a substitution or a string there is always
# true, or fails a comparison with a number when the process exits and is respawned.
_PROCESS_PLAIN = (("respawn_delay", "number"), ("respawn_max_retries", "number"),
                  ("emulate_tty", "bool"), ("shell", "bool"))
# Actions whose on_exit= takes actions (or a function returning them): launch wraps it in an
# OnProcessExit (launch ExecuteProcess.execute, event_handlers/on_action_event_base.py).
_PROCESS_ACTIONS = frozenset({"ExecuteProcess", "Node", "LifecycleNode", "ComposableNodeContainer"})
_PLAIN_ARGS: dict[str, tuple[tuple[str, str], ...]] = {
    **{n: _PROCESS_PLAIN for n in ("Node", "LifecycleNode", "ComposableNodeContainer",
                                    "ExecuteProcess", "ExecuteLocal")},
    "GroupAction": (("scoped", "bool"), ("forwarding", "bool")),
}
# A string for a plain bool is true whatever it says: one that says so does what it reads.
_TRUE_WORDS = frozenset({"true", "1", "yes", "on"})


class ActionBuilder:
    def __init__(self, ev: Evaluator) -> None:
        self.ev = ev
        self.applied: list[CondTag] = []
        self.opaque_ids: dict[str, int] = {}

    def id_of(self, obj: LObj) -> str:
        prefix = obj.extra.get("prefix", "")
        site = (prefix, obj.span.line, obj.span.col)
        base = f"{prefix}{obj.span.line}:{obj.span.col}"
        return f"{base}#{obj.index}" if self.ev.site_counts.get(site, 1) > 1 else base

    def _unique_id(self, base: str) -> str:
        """``base``, or ``base#n`` for its n-th use in this file."""
        n = self.opaque_ids.get(base, 0) + 1
        self.opaque_ids[base] = n
        return base if n == 1 else f"{base}#{n}"

    def _opaque(self, reason: str, span: Span) -> L.OpaqueAction:
        return L.OpaqueAction(self._unique_id(f"opaque@{span.line}:{span.col}"), span, None, reason)

    def actions(self, entities: Any, span: Span) -> tuple[L.Action, ...]:
        if isinstance(entities, (list, tuple)):
            out: list[L.Action] = []
            for i, item in enumerate(entities):
                out.extend(self.entity(item, span_at(entities, i, span)))
            return tuple(out)
        return tuple(self.entity(entities, span))

    def entity(self, v: Any, span: Span) -> list[L.Action]:
        if v is None:
            return []
        if isinstance(v, (list, tuple)):
            return list(self.actions(v, span))
        if isinstance(v, Alternatives):  # each under the condition of the branch it was made in
            return [a for o in v.options for a in self.entity(o, span)]
        if isinstance(v, Branched):  # under the condition of the branch that added it
            return self._under(v.tag, v.value, span)
        if isinstance(v, Opaque):
            return [self._opaque(v.reason, v.span or span)]
        if isinstance(v, LObj) and v.qual == "launch.LaunchDescription":
            return list(self.actions(v.extra.get("entities", []), v.span))
        if isinstance(v, LObj) and v.qual in api.ACTION_KINDS:
            return self.wrapped(v)
        return [self._opaque(f"not a launch action ({type_name(v)})", span)]

    def _under(self, tag: CondTag, value: Any, span: Span) -> list[L.Action]:
        """``value``'s actions under ``tag``'s condition (unless an enclosing action carries it)."""
        if tag in self.applied:
            return self.entity(value, span)
        if tag.condition is None:
            return [self._opaque(tag.reason, span)]
        self.applied.append(tag)
        try:
            inner = self.entity(value, span)
        finally:
            self.applied.pop()
        if not inner:
            return []
        c = tag.condition
        gid = self._unique_id(f"{inner[0].id}/{c.raw}@{c.span.line}:{c.span.col}")
        return [L.Group(gid, c.span, c, tuple(inner), scoped=False)]

    def _new_tags(self, obj: LObj) -> list[CondTag]:
        """The branches ``obj`` was made under that no enclosing action carries already."""
        return [t for t in obj.tags if t not in self.applied]

    def wrapped(self, obj: LObj) -> list[L.Action]:
        """``obj``'s action, followed by the handler of its ``on_exit`` (``_on_exit``), in a Group
        for each branch it was made under that no enclosing action carries."""
        new_tags = self._new_tags(obj)
        for t in new_tags:
            if t.condition is None:
                return [L.OpaqueAction(self.id_of(obj), obj.span, None, t.reason)]
        self.applied.extend(new_tags)
        try:
            action = self.action(obj)
            out = [action, *self._on_exit(obj, action)]
        finally:
            del self.applied[len(self.applied) - len(new_tags):]
        for depth, t in enumerate(reversed(new_tags)):
            assert t.condition is not None
            out = [L.Group(f"{self.id_of(obj)}/{t.condition.raw}{depth}", t.condition.span, t.condition,
                           tuple(out), scoped=False)]
        return out

    def _on_exit(self, obj: LObj, action: L.Action) -> list[L.Action]:
        """A process action's ``on_exit=`` actions (or the actions its function returns) as the
        ``OnProcessExit(target_action=self, on_exit=...)`` handler launch registers when the action
        runs (``ExecuteLocal.execute``): under the action's own condition, so nothing of it exists
        when the process never starts."""
        if api.short(obj.qual) not in _PROCESS_ACTIONS or isinstance(action, L.OpaqueAction):
            return []
        entities = obj.extra.get("entities_result", obj.kwargs.get("on_exit"))
        if "entities_result" not in obj.extra and not isinstance(entities, (list, tuple)) and not (
                isinstance(entities, LObj) and entities.qual in api.ACTION_KINDS):
            # none, one of a type launch refuses (_check_text), or a callable the evaluator cannot
            # follow: left out, as before, rather than made an unknown part of the launch
            return []
        span = obj.arg_span(-1, "on_exit")
        return [L.EventHandler(f"{action.id}/on_exit", span, action.condition, "on_process_exit",
                               action.id, True, self.actions(entities, span))]

    # ---- one action -----------------------------------------------------------------------
    def action(self, o: LObj) -> L.Action:
        n = api.short(o.qual)
        i, s = self.id_of(o), o.span
        self._check_text(o, n)
        cond = to_condition(o.kwargs.get("condition"), o.arg_span(-1, "condition"))
        if n == "DeclareLaunchArgument":
            name = o.arg(0, "name")
            if not isinstance(name, str):
                return L.OpaqueAction(i, s, cond, "launch argument name cannot be evaluated statically")
            desc = o.arg(-1, "description")
            choices = o.arg(-1, "choices")
            ch = tuple(str(c) for c in choices) if isinstance(choices, (list, tuple)) and all(isinstance(c, str) for c in choices) else None
            return L.DeclareArgument(i, s, cond, str(name), opt_value(o, -1, "default_value"),
                                     str(desc) if isinstance(desc, str) else None, ch, o.arg_span(0, "name"))
        if n == "SetLaunchConfiguration":
            return L.SetLaunchConfiguration(i, s, cond, self._v(o, 0, "name"), self._v(o, 1, "value"))
        if n == "IncludeLaunchDescription":
            return self._include(o, i, s, cond)
        if n == "GroupAction":
            scoped, fwd = o.arg(-1, "scoped", True), o.arg(-1, "forwarding", True)
            lcs = o.arg(-1, "launch_configurations") or {}
            pairs = tuple((to_value(k, s), to_value(v, s)) for k, v in lcs.items()) if isinstance(lcs, dict) else ()
            return L.Group(i, s, cond, self.actions(o.arg(0, "actions", []), s), scoped is not False,
                           fwd is not False, pairs)
        if n in ("PushRosNamespace", "PushROSNamespace"):
            return L.PushNamespace(i, s, cond, self._v(o, 0, "namespace"))
        if n == "SetRemap":
            return L.SetRemap(i, s, cond, self._v(o, 0, "src"), self._v(o, 1, "dst"))
        if n == "SetParameter":
            return L.SetParameter(i, s, cond, self._v(o, 0, "name"), to_pvalue(o.arg(1, "value"), o.arg_span(1, "value")))
        if n == "SetParametersFromFile":
            return L.SetParametersFromFile(i, s, cond, self._v(o, 0, "filename"))
        if n == "SetUseSimTime":
            return L.SetUseSimTime(i, s, cond, self._v(o, 0, "value"))
        if n in _NODE_KINDS:
            return self._node(o, i, s, cond, _NODE_KINDS[n])
        if n == "LoadComposableNodes":
            tgt = o.arg(-1, "target_container")
            nodes = self._composables(o.arg(-1, "composable_node_descriptions"), s)
            if isinstance(tgt, LObj) and tgt.qual in api.ACTION_KINDS:
                return L.LoadComposableNodes(i, s, cond, None, self.id_of(tgt), nodes)
            return L.LoadComposableNodes(i, s, cond, to_value(tgt, o.arg_span(-1, "target_container")), None, nodes)
        if n == "ExecuteProcess":
            return L.ExecuteProcess(i, s, cond, self._list_values(o.arg(-1, "cmd"), o.arg_span(-1, "cmd")),
                                    opt_value(o, -1, "name"), self._other(o), _respawn(o),
                                    o.kw_spans.get("respawn"))
        if n in ("TimerAction", "RosTimer"):
            period = o.arg(0, "period")
            if isinstance(period, int):  # ensure_argument_type: str, substitutions or float; bool is an int
                self.ev.wrong_type("period", f"{n}(period=...)", period, o.arg_span(0, "period"))
            return L.Timer(i, s, cond, self._v(o, 0, "period"), self.actions(o.arg(1, "actions", []), s), n == "RosTimer")
        if n == "RegisterEventHandler":
            return self._handler(o, i, s, cond)
        if n == "EmitEvent":
            return self._emit(o, i, s, cond)
        if n == "LogInfo":
            return L.Log(i, s, cond, self._v(o, -1, "msg"))
        if n == "ReadyToTest":  # launch_testing: the tests may start; nothing is launched
            return L.Log(i, s, cond, ())
        if n in _ENV_OPS:
            return L.SetEnvironment(i, s, cond, _ENV_OPS[n], opt_value(o, 0, "name"), opt_value(o, 1, "value"))  # type: ignore[arg-type]
        if n == "Shutdown":
            return L.Shutdown(i, s, cond, opt_value(o, -1, "reason"))
        if n == "OpaqueFunction":
            result = o.extra.get("result")
            performed = tuple(v for v in o.extra.get("performed", ()) if v)
            # What it substituted or looked up: the resolver reads these and evaluates the function
            # again with their values (``frontends.python.specialize``) when the evaluation lost
            # track, or lost values on the way (an ``if`` over a performed string).
            read = _distinct(performed + tuple(v for v in o.extra.get("peeked", ()) if v))
            if isinstance(result, Opaque):
                return L.OpaqueAction(i, s, cond, result.reason, (), read)
            # ``read`` as what it reads: a looked-up value compared or tested (``.get(name, d) ==
            # 'true'``) reaches no action, and is still a read (L102)
            return L.OpaqueAction(i, s, cond, "", self._config_sets(o, i) + self.actions(result, s), read,
                                  read if o.extra.get("undecided") else ())
        if n == "ResetLaunchConfigurations":
            lcs = o.arg(0, "launch_configurations")
            keep = tuple((to_value(k, s), to_value(v, s)) for k, v in lcs.items()) if isinstance(lcs, dict) else None
            return L.ResetLaunchConfigurations(i, s, cond, keep)
        return L.OpaqueAction(i, s, cond, f"{n} is not modelled")

    def _check_text(self, o: LObj, n: str) -> None:
        """Record the bool and number values launch cannot turn into substitutions."""
        for pos, name in _TEXT_ARGS.get(n, ()):
            v = o.arg(pos, name)
            if _not_text(v):
                self.ev.wrong_type("text", f"{n}({name}=...)", v, o.arg_span(pos, name))
        for name in _TEXT_ITEMS.get(n, ()):
            items = o.arg(-1, name)
            if isinstance(items, (list, tuple)):
                span = o.arg_span(-1, name)
                for k, v in enumerate(items):
                    if _not_text(v):
                        self.ev.wrong_type("text", f"{n}({name}=[...])", v, span_at(items, k, span))
        for name, want in _PLAIN_ARGS.get(n, ()):
            v = o.arg(-1, name)
            if not (isinstance(v, str) or (isinstance(v, LObj) and api.is_substitution(v.qual))):
                continue
            if want == "number" and o.arg(-1, "respawn", False) is False:
                continue  # only compared when the process is respawned
            if want == "bool" and isinstance(v, str) and v.strip().lower() in _TRUE_WORDS:
                continue  # emulate_tty='True': on, as written (only a false-looking one misleads)
            self.ev.wrong_type(f"plain-{want}", f"{n}({name}=...)", v, o.arg_span(-1, name))  # type: ignore[arg-type]
        if n in _PROCESS_ACTIONS:
            v = o.arg(-1, "respawn")
            if isinstance(v, str) or type(v) in (int, float):
                self.ev.wrong_type("typed-bool", f"{n}(respawn=...)", v, o.arg_span(-1, "respawn"))
            v = o.arg(-1, "on_exit")
            if isinstance(v, (str, bool, int, float)) or (isinstance(v, LObj) and api.is_substitution(v.qual)):
                self.ev.wrong_type("entities", f"{n}(on_exit=...)", v, o.arg_span(-1, "on_exit"))
        if n == "GroupAction":
            lcs = o.arg(-1, "launch_configurations")
            if isinstance(lcs, dict):
                for key, v in lcs.items():
                    if _not_text(v):
                        self.ev.wrong_type("text", f"GroupAction(launch_configurations={{{key!r}: ...}})", v,
                                           o.arg_span(-1, "launch_configurations"))

    @staticmethod
    def _config_sets(o: LObj, i: str) -> tuple[L.Action, ...]:
        """``context.launch_configurations[name] = value`` in the function: sets made when it runs,
        before the actions it returns (launch's context hands out the live mapping)."""
        out: list[L.Action] = []
        for k, (name, value, span) in enumerate(o.extra.get("sets", ())):
            if not name:
                out.append(L.OpaqueAction(f"{i}.set{k}", span, None,
                                          "a launch configuration named only at launch time is set"))
            else:
                out.append(L.SetLaunchConfiguration(f"{i}.set{k}", span, None, (Text(name, span),),
                                                    to_value(value, span)))
        return tuple(out)

    def _v(self, o: LObj, pos: int, name: str) -> Value:
        return opt_value(o, pos, name) or ()

    def _list_values(self, v: Any, span: Span) -> tuple[Value, ...] | None:
        if v is None:
            return ()
        if isinstance(v, (list, tuple)):
            return tuple(to_value(x, span_at(v, k, span)) for k, x in enumerate(v))
        if isinstance(v, str):
            return (to_value(v, span),)
        return None

    def _include(self, o: LObj, i: str, s: Span, cond: L.Condition | None) -> L.Action:
        src = o.arg(0, "launch_description_source")
        kind = "any"
        if isinstance(src, LObj) and api.short(src.qual) in _SOURCES:
            kind = _SOURCES[api.short(src.qual)]
            path = to_value(src.arg(0, "launch_file_path"), src.arg_span(0, "launch_file_path"))
        else:
            path = to_value(src, o.arg_span(0, "launch_description_source"))
        la = o.arg(1, "launch_arguments")
        la_span = o.arg_span(1, "launch_arguments")
        args: tuple[L.IncludeArgument, ...] | None = ()
        if isinstance(la, dict):
            if la:  # launch iterates it as (name, value) pairs: it gets the keys
                self.ev.wrong_type("pairs", "IncludeLaunchDescription(launch_arguments=...)", la, la_span)
            la = [(k, v) for k, v in la.items()]
        if isinstance(la, (list, tuple)):
            out = []
            for k, pair in enumerate(la):
                if not isinstance(pair, (list, tuple)) or len(pair) != 2:
                    out = None
                    break
                if _not_text(pair[1]):  # SetLaunchConfiguration(name, value) when the include runs
                    self.ev.wrong_type("text", f"IncludeLaunchDescription(launch_arguments=[({pair[0]!r}, ...)])",
                                       pair[1], span_at(la, k, la_span))
                name = pair[0] if isinstance(pair[0], str) else literal_of(to_value(pair[0], la_span))
                if name is None:
                    out = None
                    break
                out.append(L.IncludeArgument(str(name), to_value(pair[1], la_span), span_at(la, k, la_span)))
            args = tuple(out) if out is not None else None
        elif la is not None:
            args = None
        return L.Include(i, s, cond, path, args, kind)  # type: ignore[arg-type]

    def _remaps(self, v: Any, span: Span, call: str) -> tuple[L.Remapping, ...]:
        if v is None:
            return ()
        if isinstance(v, dict):
            if v:  # launch_ros iterates it: each rule is a key, a str, not a tuple
                self.ev.wrong_type("remap", f"{call}(remappings=...)", v, span)
            v = list(v.items())
        elif isinstance(v, (set, frozenset)):
            # launch_ros only iterates the rules ({('cmd_vel', '/x')}, husky): in hash order, which
            # matters only between rules that match the same name; here in a fixed order
            v = sorted(v, key=repr)
        if isinstance(v, (list, tuple)):
            if v and all(isinstance(rule, str) for rule in v):
                # one rule without its list (remappings=('cmd_vel', 'cmd_vel_joy')): each string is
                # taken for a rule
                self.ev.wrong_type("remap-bare", f"{call}(remappings=...)", v, span)
            for k, rule in enumerate(v):
                if isinstance(rule, list) and len(rule) == 2:  # normalize_remap_rule wants a tuple
                    self.ev.wrong_type("remap", f"{call}(remappings=[...])", rule, span_at(v, k, span))
        if not isinstance(v, (list, tuple)):
            reason = v.reason if isinstance(v, Opaque) else "remappings cannot be evaluated statically"
            return (L.Remapping((Unknown(reason, span),), (Unknown(reason, span),), span),)
        out = []
        for k, pair in enumerate(v):
            ps = span_at(v, k, span)
            if isinstance(pair, (list, tuple)) and len(pair) == 2:
                out.append(L.Remapping(to_value(pair[0], ps), to_value(pair[1], ps), ps))
            else:
                reason = pair.reason if isinstance(pair, Opaque) else "remapping is not a pair"
                out.append(L.Remapping((Unknown(reason, ps),), (Unknown(reason, ps),), ps))
        return tuple(out)

    def _node(self, o: LObj, i: str, s: Span, cond: L.Condition | None, kind: str) -> L.Action:
        kw = o.kwargs
        fields = tuple((k, o.kw_spans[k]) for k in kw if k in o.kw_spans)
        return L.NodeAction(
            i, s, cond, kind,  # type: ignore[arg-type]
            opt_value(o, -1, "package"), opt_value(o, -1, "executable"), opt_value(o, -1, "name"),
            opt_value(o, -1, "namespace"),
            to_params(kw.get("parameters"), o.arg_span(-1, "parameters")),
            self._remaps(kw.get("remappings"), o.arg_span(-1, "remappings"), api.short(o.qual)),
            self._list_values(kw.get("arguments"), o.arg_span(-1, "arguments")),
            self._list_values(kw.get("ros_arguments"), o.arg_span(-1, "ros_arguments")),
            self._composables(kw.get("composable_node_descriptions"), s) if kind == "container" else (),
            fields, opt_value(o, -1, "exec_name"), self._other(o), _autostart(kw), _respawn(o))

    def _other(self, o: LObj) -> tuple[Value, ...]:
        """Process arguments launch substitutes that no rule models (``NodeAction.other``)."""
        out: list[Value] = []
        for name in _OTHER_ARGS:
            v = o.arg(-1, name)
            if v is None or type(v) in (bool, int, float):
                continue
            value = opt_value(o, -1, name)
            if value:
                out.append(value)
        env = o.arg(-1, "additional_env")
        if isinstance(env, dict):
            span = o.arg_span(-1, "additional_env")
            for k, v in env.items():
                out.extend(x for x in (to_value(k, span), to_value(v, span)) if x)
        return tuple(out)

    def _composables(self, v: Any, span: Span) -> tuple[L.ComposableNode, ...]:
        if v is None:
            return ()
        items = v if isinstance(v, (list, tuple)) else [v]
        items = [o for c in items for o in (c.options if isinstance(c, Alternatives) else (c,))]
        out = []
        for c in items:
            added: list[CondTag] = []
            while isinstance(c, Branched):  # added under an undecided if: its condition
                added.append(c.tag)
                c = c.value
            if not (isinstance(c, LObj) and api.short(c.qual) == "ComposableNode"):
                continue
            extra: list[tuple[str, Value, Span]] = []
            ea = c.kwargs.get("extra_arguments")
            whole = c.arg_span(-1, "extra_arguments")
            for d in ea if isinstance(ea, (list, tuple)) else []:
                if isinstance(d, dict):
                    _extra_entries(d, "", whole, extra)
            out.append(L.ComposableNode(
                opt_value(c, -1, "package"), opt_value(c, -1, "plugin"), opt_value(c, -1, "name"),
                opt_value(c, -1, "namespace"), to_params(c.kwargs.get("parameters"), c.arg_span(-1, "parameters")),
                self._remaps(c.kwargs.get("remappings"), c.arg_span(-1, "remappings"), "ComposableNode"), tuple(extra),
                c.span, to_condition(c.kwargs.get("condition"), c.span), self.id_of(c),
                self._branch_condition(c, None, added)))
        return tuple(out)

    def _branch_condition(self, obj: LObj, own: L.Condition | None, added: list[CondTag] | None = None
                          ) -> L.Condition | None:
        """A description (not an action, so no Group can carry it) made under an ``if`` the
        evaluator could not decide, or ``added`` to a list under one, gets that ``if`` as a
        condition, and-ed with ``own``: otherwise both branches of ``if mode == "a": ... else: ...``
        load their components. (A ComposableNode keeps the branches apart from the condition it
        was given, ``ComposableNode.branch``: humble's LoadComposableNodes ignores only that one.)"""
        tags = self._new_tags(obj) + [t for t in added or () if t not in obj.tags and t not in self.applied]
        conds = [t.condition or L.Condition("if", (Unknown(t.reason, obj.span),), obj.span, "if ...")
                 for t in tags]
        if not conds:
            return own
        if own is not None:
            conds.append(own)
        if len(conds) == 1:
            return conds[0]
        operands = tuple(c.value if c.kind == "if" else (BoolOp("not", (c.value,), c.span),) for c in conds)
        return L.Condition("if", (BoolOp("and", operands, obj.span),), obj.span, " and ".join(c.raw for c in conds))

    def _handler(self, o: LObj, i: str, s: Span, cond: L.Condition | None) -> L.Action:
        h = o.arg(0, "event_handler")
        if not (isinstance(h, LObj) and api.short(h.qual) in _EVENTS):
            return L.OpaqueAction(i, s, cond, "event handler cannot be evaluated statically")
        event, key = _EVENTS[api.short(h.qual)]
        tkey = "target_lifecycle_node" if event == "on_state_transition" else "target_action"
        target = h.kwargs.get(tkey)
        target_id, known = None, target is None
        if isinstance(target, LObj) and target.qual in api.ACTION_KINDS:
            target_id, known = self.id_of(target), True
        entities = h.extra.get("entities_result", h.kwargs.get(key))
        if event == "on_process_io" and entities is None:
            entities = h.kwargs.get("on_stderr")
        goal, start = h.kwargs.get("goal_state"), h.kwargs.get("start_state")
        if h.kwargs.get("matcher") is not None:  # OnStateTransition then compares nothing else
            goal = start = None
        return L.EventHandler(i, s, cond, event, target_id, known, self.actions(entities, h.span),  # type: ignore[arg-type]
                              str(goal) if isinstance(goal, str) else None, str(start) if isinstance(start, str) else None,
                              h.arg_span(-1, key) if key in h.kwargs else None)

    def _emit(self, o: LObj, i: str, s: Span, cond: L.Condition | None) -> L.Action:
        e = o.arg(-1, "event")
        if isinstance(e, str) or (isinstance(e, LObj) and e.qual in api.ACTION_KINDS):
            # EmitEvent.__init__: "expected an event instance" (launch.actions.Shutdown for
            # launch.events.Shutdown)
            self.ev.wrong_type("event", "EmitEvent(event=...)", e, o.arg_span(-1, "event"))
        if not isinstance(e, LObj):
            return L.EmitEvent(i, s, cond, "unknown")
        target_id = target_name = matcher_span = None
        matcher = e.kwargs.get("lifecycle_node_matcher")
        if isinstance(matcher, LObj):
            matcher_span = matcher.span
            if api.short(matcher.qual) == "matches_node_name":
                name = matcher.arg(0, "node_name")
                target_name = name if isinstance(name, str) else None
            elif isinstance(action := matcher.arg(0, "target_action"), LObj):
                target_id = self.id_of(action)
        return L.EmitEvent(i, s, cond, e.qual, target_id, target_name, matcher_span)


def _distinct(values: tuple[Any, ...]) -> tuple[Any, ...]:
    """``values`` without repeats, in order (compared by equality: a value may not hash)."""
    out: list[Any] = []
    for v in values:
        if v not in out:
            out.append(v)
    return tuple(out)


def _respawn(o: LObj) -> Value | None:
    """``NodeAction.respawn``: the value when it is substitutions. A bool literal is typed
    already; any other literal, a string included, fails ``normalize_typed_substitution`` when
    the action is built (L008, ``_check_text``)."""
    v = o.arg(-1, "respawn")
    if v is None or isinstance(v, (str, bool, int, float)):
        return None
    return opt_value(o, -1, "respawn")


def _autostart(kw: dict[str, Any]) -> bool | None:
    """``NodeAction.autostart``: launch_ros tests the value's truth (a substitution object is
    true); None when the value is not known."""
    if "autostart" not in kw:
        return False
    v = kw["autostart"]
    if isinstance(v, Opaque):
        return None
    return bool(v)


def _extra_entries(d: dict[Any, Any], prefix: str, span: Span, out: list[tuple[str, Any, Span]]) -> None:
    """A component's ``extra_arguments`` dict as launch_ros normalizes it (``normalize_parameter_dict``:
    nested dicts joined with "."); a key that is not a literal string has a name known only at
    launch time (""), which no rule takes for a wrong one."""
    found = item_spans(d)
    spans = found if isinstance(found, dict) else {}
    for k, x in d.items():
        kspan, vspan = spans.get(k, (span, span))
        name = f"{prefix}.{k}" if prefix and isinstance(k, str) else (k if isinstance(k, str) else "")
        if isinstance(x, dict) and name:
            _extra_entries(x, name, vspan, out)
        else:
            out.append((name, to_pvalue(x, vspan), kspan))
