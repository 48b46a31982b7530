"""Python launch API signatures: L001 unknown-keyword-argument (SEMANTICS §8)."""
from __future__ import annotations

from collections.abc import Iterator

from physai_lint.checks._util import did_you_mean, python_facts, suggestion
from physai_lint.checks.base import CheckContext, rule
from physai_lint.frontends.python.signatures import ACTIONS as _A
from physai_lint.frontends.python.signatures import HANDLERS as _H
from physai_lint.frontends.python.signatures import ROS_ACTIONS as _R
from physai_lint.frontends.python.signatures import keyword_tables as _tables
from physai_lint.frontends.python.signatures import passes_unknown_keywords
from physai_lint.model.findings import Diagnostic
from physai_lint.model.launch import CallFact

# Parameters that may be given positionally, in order (the rest are keyword-only), and the
# parameters without a default; the same in humble, jazzy and rolling (launch f31c1ff1/02595baf,
# launch_ros 25a207ca/f9ab9371 ``__init__`` signatures).
_POSITIONAL: dict[str, tuple[str, ...]] = {
    _A + "IncludeLaunchDescription": ("launch_description_source",),
    _A + "DeclareLaunchArgument": ("name",),
    _A + "GroupAction": ("actions",),
    _A + "RegisterEventHandler": ("event_handler",),
    _A + "SetLaunchConfiguration": ("name", "value"),
    _A + "SetEnvironmentVariable": ("name", "value"),
    _R + "PushRosNamespace": ("namespace",),
    _R + "SetRemap": ("src", "dst"),
    _R + "SetParameter": ("name", "value"),
    _R + "SetParametersFromFile": ("filename",),
}
_REQUIRED: dict[str, tuple[str, ...]] = {
    _A + "ExecuteProcess": ("cmd",),
    _A + "ExecuteLocal": ("process_description",),
    _R + "Node": ("executable",),
    _R + "LifecycleNode": ("name", "namespace", "executable"),
    _R + "ComposableNodeContainer": ("name", "namespace", "executable"),
    "launch_ros.descriptions.ComposableNode": ("package", "plugin"),
    _R + "LoadComposableNodes": ("composable_node_descriptions", "target_container"),
    _A + "TimerAction": ("period", "actions"),
    _A + "LogInfo": ("msg",),
    _A + "OpaqueFunction": ("function",),
    _H + "OnProcessExit": ("on_exit",),
    _H + "OnProcessStart": ("on_start",),
    _H + "OnExecutionComplete": ("on_completion",),
    _H + "OnShutdown": ("on_shutdown",),
    "launch_ros.event_handlers.OnStateTransition": ("entities",),
    **_POSITIONAL,
}

_HANDLER_ENTITIES = frozenset({"on_exit", "on_start", "on_completion", "on_shutdown", "entities"})
_NODE_LIKE = ("launch_ros.actions.Node", "launch_ros.actions.LifecycleNode",
              "launch_ros.actions.ComposableNodeContainer")
_DASHING = {
    "node_executable": "executable", "node_name": "name", "node_namespace": "namespace",
}
_DASHING_COMPONENT = {"package_name": "package", "node_plugin": "plugin", "node_name": "name",
                      "node_namespace": "namespace"}
_WHY = {
    "namespace": "only Node/LifecycleNode/ComposableNodeContainer know namespaces; wrap the action in "
                 "GroupAction([PushRosNamespace(...), ...]) instead",
}


def _missing(call: CallFact, cls: str) -> list[str]:
    """The required arguments ``call`` gives neither by position nor by keyword."""
    positional = _POSITIONAL.get(call.qualname, ())
    given = set(positional[:call.positional]) | {kw for kw, _ in call.kwargs}
    aliases = _DASHING_COMPONENT if cls == "ComposableNode" else _DASHING if call.qualname in _NODE_LIKE else {}
    given |= {aliases[kw] for kw in given if kw in aliases}  # reported as a rename instead
    return [p for p in _REQUIRED.get(call.qualname, ()) if p not in given]


def _misspelt_required(call: CallFact, cls: str, allowed: frozenset[str]) -> dict[str, str]:
    """Unknown keywords that are a required argument misspelt (``TimerAction(action=...)``):
    keyword -> the required argument. Reported once, at the keyword."""
    if call.splat or call.positional > len(_POSITIONAL.get(call.qualname, ())):
        return {}
    missing = _missing(call, cls)
    out = {}
    for kw, _span in call.kwargs:
        if kw not in allowed and missing:
            # another handler's keyword (OnProcessExit(on_start=...)) is the same slip
            close = did_you_mean(kw, missing) or (
                missing[:1] if kw in _HANDLER_ENTITIES and missing[0] in _HANDLER_ENTITIES else [])
            if close:
                out[kw] = close[0]
    return out


def _signature_problems(call: CallFact, cls: str, misspelt: dict[str, str]) -> Iterator[Diagnostic]:
    """Too many positional arguments, and required arguments given neither way (not for splats;
    nor those ``misspelt``, reported at the misspelt keyword)."""
    if call.splat:
        return
    positional = _POSITIONAL.get(call.qualname, ())
    if call.positional > len(positional):
        yield Diagnostic(
            "L001", call.span,
            f"{cls}() takes {len(positional)} positional argument{'s' if len(positional) != 1 else ''} "
            f"but {call.positional} {'were' if call.positional != 1 else 'was'} given; building the "
            'launch description fails with "TypeError: ... positional argument"',
            help=(f"pass them by keyword: {', '.join(f'{p}=...' for p in _REQUIRED.get(call.qualname, ()))}"
                  if not positional else f"only {', '.join(positional)} may be positional; pass the "
                  "rest by keyword"),
            key=f"{cls}:positional")
        return
    missing = [p for p in _missing(call, cls)
               if p not in misspelt.values() or not passes_unknown_keywords(call.qualname)]
    if missing:
        listed = ", ".join(f'"{m}"' for m in missing)
        yield Diagnostic(
            "L001", call.span,
            f"{cls}() is missing the required argument{'s' if len(missing) > 1 else ''} {listed}; "
            f"building the launch description fails with \"TypeError: ... missing {len(missing)} required "
            f"argument{'s' if len(missing) > 1 else ''}\"",
            help="add " + ", ".join(f"{m}=..." for m in missing), key=f"{cls}:missing:{','.join(missing)}")


@rule("L001", "unknown-keyword-argument")
def unknown_keyword_argument(ctx: CheckContext) -> Iterator[Diagnostic]:
    tables = _tables(ctx.distro)
    jazzy_tables = _tables("jazzy") if ctx.distro == "humble" else tables
    for path, facts in python_facts(ctx):
        for call in facts.calls:
            allowed = tables.get(call.qualname)
            if allowed is None:
                continue
            cls = call.qualname.rsplit(".", 1)[-1]
            misspelt = _misspelt_required(call, cls, allowed)
            yield from _signature_problems(call, cls, misspelt)
            for kw, span in call.kwargs:
                if kw in allowed:
                    continue
                if kw in misspelt and passes_unknown_keywords(call.qualname):
                    # an action passes unknown keywords on to Action.__init__ (**kwargs): the missing
                    # argument is what Python reports first; a description has no **kwargs
                    req = misspelt[kw]
                    yield Diagnostic(
                        "L001", span,
                        f'{cls}() has no keyword argument "{kw}" (did you mean "{req}"?), and its required '
                        f'argument "{req}" is not given; building the launch description fails with '
                        f"\"TypeError: ... missing 1 required "
                        f"{'positional' if req in _POSITIONAL.get(call.qualname, ()) else 'keyword-only'} "
                        f"argument: '{req}'\"",
                        help=f'rename "{kw}" to "{req}"', key=f"{cls}:{kw}")
                    continue
                old = (_DASHING_COMPONENT if cls == "ComposableNode" else
                       _DASHING if call.qualname in _NODE_LIKE else {}).get(kw)
                if old:
                    yield Diagnostic(
                        "L001", span,
                        f'{cls}() has no keyword argument "{kw}" (its name before Foxy, deprecated '
                        f'in Foxy and removed in Galactic); launch fails with "TypeError: ... unexpected keyword argument '
                        f"'{kw}'\"",
                        help=f'rename it to "{old}"', key=f"{cls}:{kw}")
                    continue
                if kw in jazzy_tables.get(call.qualname, frozenset()):
                    yield Diagnostic(
                        "L001", span,
                        f'{cls}() keyword argument "{kw}" does not exist in {ctx.distro} '
                        "(jazzy has it)",
                        help=f'remove "{kw}", or target a newer distro with --distro',
                        key=f"{cls}:{kw}")
                    continue
                hint = "" if kw in _WHY else suggestion(kw, allowed)
                yield Diagnostic(
                    "L001", span,
                    f'{cls}() has no keyword argument "{kw}"; launch fails with "TypeError: ... '
                    f"unexpected keyword argument '{kw}'\"" + (f"; {hint}" if hint else ""),
                    help=_WHY.get(kw) or f"use one of: {', '.join(sorted(allowed))}",
                    key=f"{cls}:{kw}")
