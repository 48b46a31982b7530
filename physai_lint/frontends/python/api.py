"""The launch/launch_ros API we recognise, keyed by canonical qualified name.

Names are canonicalised to ``<root>.<subpackage>.<Name>`` (``launch_ros.actions.node.Node`` ->
``launch_ros.actions.Node``) so every import form maps to one key.
"""
from __future__ import annotations

from typing import Any

ROOTS = ("launch", "launch_ros", "launch_xml", "launch_yaml", "nav2_common")

_ACTIONS_LAUNCH = (
    "DeclareLaunchArgument SetLaunchConfiguration IncludeLaunchDescription GroupAction ExecuteProcess "
    "TimerAction RegisterEventHandler EmitEvent LogInfo SetEnvironmentVariable "
    "UnsetEnvironmentVariable AppendEnvironmentVariable ResetEnvironment Shutdown OpaqueFunction "
    "ResetLaunchConfigurations UnregisterEventHandler ExecuteLocal OpaqueCoroutine SetLaunchConfiguration"
)
_ACTIONS_ROS = (
    "Node LifecycleNode ComposableNodeContainer LoadComposableNodes PushRosNamespace PushROSNamespace "
    "SetRemap SetParameter SetParametersFromFile SetUseSimTime RosTimer SetROSLogDir LifecycleTransition"
)
_SUBST_LAUNCH = (
    "TextSubstitution LaunchConfiguration PathJoinSubstitution PathSubstitution EnvironmentVariable ThisLaunchFileDir "
    "ThisLaunchFile Command PythonExpression AnonName NotSubstitution AndSubstitution OrSubstitution "
    "AnySubstitution AllSubstitution EqualsSubstitution NotEqualsSubstitution IfElseSubstitution "
    "FindExecutable LocalSubstitution FileContent LaunchLogDir BooleanSubstitution"
)
_SUBST_ROS = "FindPackageShare FindPackagePrefix ExecutableInPackage Parameter"
_CONDITIONS = "IfCondition UnlessCondition LaunchConfigurationEquals LaunchConfigurationNotEquals"
_HANDLERS_LAUNCH = "OnProcessStart OnProcessExit OnExecutionComplete OnShutdown OnProcessIO OnIncludeLaunchDescription"
_SOURCES = "PythonLaunchDescriptionSource AnyLaunchDescriptionSource FrontendLaunchDescriptionSource LaunchDescriptionSource"

KNOWN: set[str] = {"launch.LaunchDescription", "launch.LaunchContext"}
KNOWN |= {f"launch.actions.{n}" for n in _ACTIONS_LAUNCH.split()}
KNOWN |= {f"launch_ros.actions.{n}" for n in _ACTIONS_ROS.split()}
KNOWN |= {f"launch.substitutions.{n}" for n in _SUBST_LAUNCH.split()}
KNOWN |= {f"launch_ros.substitutions.{n}" for n in _SUBST_ROS.split()}
KNOWN |= {f"launch.conditions.{n}" for n in _CONDITIONS.split()}
KNOWN |= {f"launch.event_handlers.{n}" for n in _HANDLERS_LAUNCH.split()}
KNOWN |= {"launch_ros.event_handlers.OnStateTransition"}
KNOWN |= {f"launch.launch_description_sources.{n}" for n in _SOURCES.split()}
# nav2_common.launch: substitutions nav2 and the robots built on it use (modelled as data)
NAV2_SUBSTITUTIONS = frozenset(
    f"nav2_common.launch.{n}" for n in ("RewrittenYaml", "ReplaceString", "LaunchConfigAsBool", "HasNodeParams"))
KNOWN |= NAV2_SUBSTITUTIONS
KNOWN |= {
    "launch_xml.launch_description_sources.XMLLaunchDescriptionSource",
    "launch_yaml.launch_description_sources.YAMLLaunchDescriptionSource",
    "launch_ros.descriptions.ComposableNode",
    "launch_ros.parameter_descriptions.ParameterValue",
    "launch_ros.parameter_descriptions.ParameterFile",
    "launch.events.Shutdown",
    "launch_ros.events.lifecycle.ChangeState",
    "launch.events.process.ShutdownProcess",
    "launch.utilities.perform_substitutions",
    "launch_ros.events.matches_action",
    "launch.events.matches_action",
    # launch_ros.events.matchers / .lifecycle(.lifecycle_node_matchers) re-export it
    "launch_ros.events.matches_node_name",
    # launch_testing's marker that the processes are up and the tests may start: it starts nothing
    "launch_testing.actions.ReadyToTest",
}
FUNCTIONS = {
    "ament_index_python.packages.get_package_share_directory",
    "ament_index_python.packages.get_package_prefix",
    "launch.utilities.perform_substitutions",
}

# launch_ros.descriptions re-exports ParameterValue / ParameterFile
_ALIASES = {
    "launch_ros.descriptions.ParameterValue": "launch_ros.parameter_descriptions.ParameterValue",
    "launch_ros.descriptions.ParameterFile": "launch_ros.parameter_descriptions.ParameterFile",
    "launch_ros.actions.PushROSNamespace": "launch_ros.actions.PushRosNamespace",
    "launch.substitutions.FindExecutable": "launch.substitutions.FindExecutable",
    "ament_index_python.get_package_share_directory": "ament_index_python.packages.get_package_share_directory",
    "ament_index_python.get_package_prefix": "ament_index_python.packages.get_package_prefix",
    "launch.frontend.launch_description_sources.FrontendLaunchDescriptionSource":
        "launch.launch_description_sources.FrontendLaunchDescriptionSource",
    "launch_ros.lifecycle.ChangeState": "launch_ros.events.lifecycle.ChangeState",
}

_BY_ROOT_NAME: dict[tuple[str, str], list[str]] = {}
for _q in sorted(KNOWN):
    _BY_ROOT_NAME.setdefault((_q.split(".")[0], _q.rsplit(".", 1)[1]), []).append(_q)


def canonical(qual: str) -> str | None:
    """The canonical known qualname for ``qual``, or None when it is not a recognised API."""
    if qual in _ALIASES:
        qual = _ALIASES[qual]
    if qual in KNOWN or qual in FUNCTIONS:
        return qual
    parts = qual.split(".")
    if parts[0] == "ament_index_python" and parts[-1] in ("get_package_share_directory", "get_package_prefix"):
        return "ament_index_python.packages." + parts[-1]
    if parts[0] not in ROOTS or len(parts) < 2:
        return None
    if len(parts) >= 3:
        short = ".".join(parts[:2] + parts[-1:])
        if short in _ALIASES:
            short = _ALIASES[short]
        if short in KNOWN:
            return short
    cands = _BY_ROOT_NAME.get((parts[0], parts[-1]), [])
    if len(cands) == 1:
        return cands[0]
    return None


def short(qual: str) -> str:
    return qual.rsplit(".", 1)[-1]


def is_substitution(qual: str) -> bool:
    return ".substitutions." in qual or qual.endswith(".ParameterValue") or qual in NAV2_SUBSTITUTIONS


ACTION_KINDS = {
    q for q in KNOWN
    if ".actions." in q or q == "launch.LaunchDescription"
}


def path_parts(obj: Any) -> Any:
    """The components argument of a PathJoinSubstitution / PathSubstitution (launch >= 3.x, jazzy
    on) as written: a list/tuple of components, or one component; None for any other class.

    ``PathSubstitution(path)`` normalises ``path`` to a list of substitutions and makes each one a
    component; ``PathJoinSubstitution(components)`` takes the components as given.
    """
    n = short(obj.qual)
    if n == "PathJoinSubstitution":
        return obj.arg(0, "substitutions")
    if n == "PathSubstitution":
        return obj.arg(0, "path")
    return None
