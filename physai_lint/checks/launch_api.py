"""Python launch API signatures: L001 unknown-keyword-argument (SEMANTICS §8)."""
from __future__ import annotations

from collections.abc import Iterator

from physai_lint.checks._util import suggestion
from physai_lint.checks.base import CheckContext, rule
from physai_lint.model.findings import Diagnostic

_ACTION = frozenset({"condition"})
_EXEC_PROCESS = frozenset({"cmd", "prefix", "name", "cwd", "env", "additional_env"})
_EXEC_LOCAL = frozenset({
    "shell", "sigterm_timeout", "sigkill_timeout", "emulate_tty", "output", "output_format",
    "cached_output", "log_cmd", "on_exit", "respawn", "respawn_delay",
})
_JAZZY_LOCAL = frozenset({"respawn_max_retries"})
_NODE_OWN = frozenset({"executable", "package", "name", "namespace", "exec_name", "parameters",
                       "remappings", "ros_arguments", "arguments"})


def _tables(distro: str) -> dict[str, frozenset[str]]:
    local = _EXEC_LOCAL | (_JAZZY_LOCAL if distro != "humble" else frozenset())
    process = _ACTION | _EXEC_PROCESS | local
    node = _ACTION | _NODE_OWN | ((_EXEC_PROCESS - {"cmd", "name"}) | local)
    a, r = "launch.actions.", "launch_ros.actions."
    return {
        a + "ExecuteProcess": process,
        a + "ExecuteLocal": _ACTION | local | {"process_description"},
        r + "Node": node,
        r + "LifecycleNode": node | ({"autostart"} if distro != "humble" else frozenset()),
        r + "ComposableNodeContainer": node | {"composable_node_descriptions"},
        "launch_ros.descriptions.ComposableNode": frozenset({
            "package", "plugin", "name", "namespace", "parameters", "remappings", "extra_arguments",
            "condition"}),
        r + "LoadComposableNodes": _ACTION | {"composable_node_descriptions", "target_container"},
        r + "PushRosNamespace": _ACTION | {"namespace"},
        r + "SetRemap": _ACTION | {"src", "dst"},
        r + "SetParameter": _ACTION | {"name", "value"},
        r + "SetParametersFromFile": _ACTION | {"filename"},
        a + "IncludeLaunchDescription": _ACTION | {"launch_description_source", "launch_arguments"},
        a + "GroupAction": _ACTION | {"actions", "scoped", "forwarding", "launch_configurations"},
        a + "TimerAction": _ACTION | {"period", "actions", "cancel_on_shutdown"},
        a + "DeclareLaunchArgument": _ACTION | {"name", "default_value", "description", "choices"},
        a + "LogInfo": _ACTION | {"msg"},
        a + "RegisterEventHandler": _ACTION | {"event_handler"},
        a + "OpaqueFunction": _ACTION | {"function", "args", "kwargs"},
        a + "SetLaunchConfiguration": _ACTION | {"name", "value"},
        a + "SetEnvironmentVariable": _ACTION | {"name", "value"},
    }


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


@rule("L001", "unknown-keyword-argument")
def unknown_keyword_argument(ctx: CheckContext) -> Iterator[Diagnostic]:
    tables = _tables(ctx.distro)
    jazzy_tables = _tables("jazzy") if ctx.distro == "humble" else tables
    for path in sorted(ctx.launch_files):
        facts = ctx.launch_files[path].python
        if facts is None:
            continue
        for call in facts.calls:
            allowed = tables.get(call.qualname)
            if allowed is None:
                continue
            cls = call.qualname.rsplit(".", 1)[-1]
            for kw, span in call.kwargs:
                if kw in allowed:
                    continue
                old = (_DASHING_COMPONENT if cls == "ComposableNode" else
                       _DASHING if call.qualname in _NODE_LIKE else {}).get(kw)
                if old:
                    yield Diagnostic(
                        "L001", span,
                        f'{cls}() has no keyword argument "{kw}" (a Dashing-era name, removed since '
                        f'Eloquent); launch fails with "TypeError: ... unexpected keyword argument '
                        f"'{kw}'\"",
                        help=f'rename it to "{old}"', key=f"{cls}:{kw}")
                    continue
                if kw in jazzy_tables.get(call.qualname, frozenset()):
                    yield Diagnostic(
                        "L001", span,
                        f'{cls}() keyword argument "{kw}" does not exist in {ctx.distro} '
                        "(it was added in jazzy)",
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
