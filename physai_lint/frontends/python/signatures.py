"""Keyword signatures of the launch and launch_ros classes the Python frontend builds (L001's
tables; SEMANTICS §8). Kept apart from the rule so that the frontend can ask them while it parses
without importing the checks."""
from __future__ import annotations

import functools

ACTIONS, ROS_ACTIONS = "launch.actions.", "launch_ros.actions."
HANDLERS, ROS_HANDLERS = "launch.event_handlers.", "launch_ros.event_handlers."

_ACTION = frozenset({"condition"})
_EXEC_PROCESS = frozenset({"cmd", "prefix", "name", "cwd", "env", "additional_env"})
_EXEC_LOCAL = frozenset({
    "shell", "sigterm_timeout", "sigkill_timeout", "emulate_tty", "output", "output_format",
    "cached_output", "log_cmd", "on_exit", "respawn", "respawn_delay",
})
_JAZZY_LOCAL = frozenset({"respawn_max_retries"})
_HANDLER = frozenset({"handle_once"})
_NODE_OWN = frozenset({"executable", "package", "name", "namespace", "exec_name", "parameters",
                       "remappings", "ros_arguments", "arguments"})


@functools.lru_cache(maxsize=None)
def keyword_tables(distro: str) -> dict[str, frozenset[str]]:
    """The keywords each launch API class takes in ``distro`` (L001), by canonical name."""
    local = _EXEC_LOCAL | (_JAZZY_LOCAL if distro != "humble" else frozenset())
    process = _ACTION | _EXEC_PROCESS | local
    node = _ACTION | _NODE_OWN | ((_EXEC_PROCESS - {"cmd", "name"}) | local)
    a, r, h = ACTIONS, ROS_ACTIONS, HANDLERS
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
        # keyword-only; what they do not name goes through **kwargs to BaseEventHandler(matcher,
        # handle_once), which takes nothing else (launch event_handlers/*.py, event_handler.py)
        h + "OnProcessExit": _HANDLER | {"target_action", "on_exit"},
        h + "OnProcessStart": _HANDLER | {"target_action", "on_start"},
        h + "OnExecutionComplete": _HANDLER | {"target_action", "on_completion"},
        h + "OnProcessIO": _HANDLER | {"target_action", "on_stdin", "on_stdout", "on_stderr"},
        h + "OnShutdown": _HANDLER | {"on_shutdown"},
        ROS_HANDLERS + "OnStateTransition": _HANDLER | {
            "entities", "target_lifecycle_node", "transition", "start_state", "goal_state", "matcher"},
    }



def accepted_keywords(qualname: str) -> frozenset[str] | None:
    """The keywords a launch API class takes in any distro (None: not a class known here). The
    Python frontend notes the configurations in the others' values as read by code it cannot
    follow: the action is never built as written, and its reads are not "unused" (L102)."""
    return keyword_tables("rolling").get(qualname)


def passes_unknown_keywords(qualname: str) -> bool:
    """Whether the class hands keywords it does not know on to ``Action.__init__`` or
    ``EventHandler.__init__`` (``**kwargs``), so that a missing required argument is what Python
    reports first: every action and event handler; a
    description (``ComposableNode``) raises on the unexpected keyword instead."""
    return qualname.startswith((ACTIONS, ROS_ACTIONS, HANDLERS, ROS_HANDLERS))
