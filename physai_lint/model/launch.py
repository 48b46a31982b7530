"""The launch IR shared by the Python, XML and YAML frontends.

One ``LaunchFile`` per parsed file. Actions are frozen dataclasses in a closed union. Every action
has an ``id`` unique within its file (frontends use ``"<line>:<col>"`` of the call/tag, plus a suffix
when one source position yields several actions, e.g. a helper called in a loop) so that event
handlers and ``LoadComposableNodes`` can refer to other actions (``target_id``).

The same launch system written in Python, XML or YAML must give the same IR up to spans and ids.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Literal, Union

from physai_lint.model.pickling import fast_init, fast_pickle_module

from .span import Span
from .values import PValue, Value


@dataclass(frozen=True, slots=True)
class Condition:
    """``IfCondition(v)`` -> kind "if"; ``UnlessCondition(v)`` -> "unless".

    ``LaunchConfigurationEquals('x', 'v')`` is ``Condition("if", (Compare("equals", $(var x), v),))``;
    ``LaunchConfigurationNotEquals`` uses ``"not-equals"``. An unknown condition class -> value
    ``(Unknown(...),)``. ``raw`` keeps how it was written for messages (``IfCondition(...)``, ``if=``).
    """

    kind: Literal["if", "unless"]
    value: Value
    span: Span
    raw: str = ""


@dataclass(frozen=True, slots=True)
class ActionBase:
    id: str
    span: Span
    condition: Condition | None


@fast_init
@dataclass(frozen=True, slots=True)
class DeclareArgument(ActionBase):
    name: str
    default: Value | None
    description: str | None = None
    choices: tuple[str, ...] | None = None
    name_span: Span | None = None


@dataclass(frozen=True, slots=True)
class SetLaunchConfiguration(ActionBase):
    """``SetLaunchConfiguration`` / XML ``<let>``."""

    name: Value
    value: Value


@dataclass(frozen=True, slots=True)
class IncludeArgument:
    name: str
    value: Value
    span: Span


@dataclass(frozen=True, slots=True)
class Include(ActionBase):
    """``IncludeLaunchDescription`` / ``<include file=...>``. ``path`` is the file path value;
    ``arguments`` is ``None`` when they cannot be known (e.g. an unknown iterable)."""

    path: Value
    arguments: tuple[IncludeArgument, ...] | None
    source_kind: Literal["python", "xml", "yaml", "frontend", "any"] = "any"


@dataclass(frozen=True, slots=True)
class Group(ActionBase):
    """``GroupAction`` / ``<group>``. ``launch_configurations`` are set inside the group's scope
    (``GroupAction(launch_configurations=)``, XML ``<keep>`` is not this: see ``keep``)."""

    actions: tuple["Action", ...]
    scoped: bool = True
    forwarding: bool = True
    launch_configurations: tuple[tuple[Value, Value], ...] = ()


@dataclass(frozen=True, slots=True)
class ResetLaunchConfigurations(ActionBase):
    keep: tuple[tuple[Value, Value], ...] | None = None


@dataclass(frozen=True, slots=True)
class PushNamespace(ActionBase):
    namespace: Value


@dataclass(frozen=True, slots=True)
class SetRemap(ActionBase):
    src: Value
    dst: Value


@dataclass(frozen=True, slots=True)
class SetParameter(ActionBase):
    name: Value
    value: PValue


@dataclass(frozen=True, slots=True)
class SetParametersFromFile(ActionBase):
    path: Value


@dataclass(frozen=True, slots=True)
class SetUseSimTime(ActionBase):
    value: Value


@dataclass(frozen=True, slots=True)
class Remapping:
    src: Value
    dst: Value
    span: Span


# ---- parameter sources on a node ---------------------------------------------------------------


@dataclass(frozen=True, slots=True)
class ParamFile:
    """A parameter YAML file path (str, substitutions, ``ParameterFile(...)``, ``<param from=>``)."""

    path: Value
    span: Span
    allow_substs: bool = False


@dataclass(frozen=True, slots=True)
class ParamEntry:
    """One parameter of a dict, already flattened to a dotted name."""

    name: str
    value: PValue
    span: Span


@dataclass(frozen=True, slots=True)
class ParamDict:
    """A dict of parameters (one Python dict; one XML/YAML ``<param name=...>`` each -- SEMANTICS §4a)."""

    entries: tuple[ParamEntry, ...]
    span: Span


@dataclass(frozen=True, slots=True)
class ParamsUnknown:
    """Parameters that cannot be known statically (a function result, an unknown variable ...)."""

    reason: str
    span: Span


ParamSource = Union[ParamFile, ParamDict, ParamsUnknown]


@dataclass(frozen=True, slots=True)
class ComposableNode:
    package: Value | None
    plugin: Value | None
    name: Value | None
    namespace: Value | None
    parameters: tuple[ParamSource, ...]
    remappings: tuple[Remapping, ...]
    # extra_arguments: (name, value, span of the key); typed like a parameter dict's values
    # (launch_ros get_composable_node_load_request runs them through evaluate_parameters)
    extra_arguments: tuple[tuple[str, PValue, Span], ...]
    span: Span
    condition: Condition | None = None  # the one launch_ros is given (condition= / if= / unless=)
    id: str = ""
    # Python: the undecided ``if`` branches the description was made under (it is in the list
    # only when they hold), apart from ``condition``: humble's LoadComposableNodes ignores that one
    branch: Condition | None = None


@dataclass(frozen=True, slots=True)
class NodeAction(ActionBase):
    """``Node``, ``LifecycleNode``, ``ComposableNodeContainer`` (kind "container") / ``<node>``,
    ``<node_container>``. ``field_spans`` maps keyword/attribute names ("package", "executable",
    "name", "namespace", "parameters", "remappings", ...) to where they were written."""

    kind: Literal["node", "lifecycle_node", "container"]
    package: Value | None
    executable: Value | None
    name: Value | None
    namespace: Value | None
    parameters: tuple[ParamSource, ...] = ()
    remappings: tuple[Remapping, ...] = ()
    arguments: tuple[Value, ...] | None = ()
    ros_arguments: tuple[Value, ...] | None = ()
    composable_nodes: tuple[ComposableNode, ...] = ()
    field_spans: tuple[tuple[str, Span], ...] = ()
    exec_name: Value | None = None
    # Other values launch substitutes when the node runs (output, respawn, prefix, cwd,
    # environment): no rule looks at them, but the launch configurations they read are read.
    other: tuple[Value, ...] = ()
    # ``LifecycleNode(autostart=...)`` (launch_ros since jazzy: ``if self.node_autostart`` it
    # configures and activates the node itself): False when not given or false, None when its
    # value is not known.
    autostart: bool | None = False
    # ``respawn=`` given as text or substitutions (a bool literal is not kept): launch types what it
    # substitutes with ``perform_typed_substitution(context, respawn, bool)`` when the action runs.
    respawn: Value | None = None

    def span_of(self, field_name: str) -> Span:
        for key, span in self.field_spans:
            if key == field_name:
                return span
        return self.span


@dataclass(frozen=True, slots=True)
class LoadComposableNodes(ActionBase):
    """``target_id`` when the target is a container action object; ``target`` when it is a name."""

    target: Value | None
    target_id: str | None
    nodes: tuple[ComposableNode, ...]


@dataclass(frozen=True, slots=True)
class ExecuteProcess(ActionBase):
    cmd: tuple[Value, ...] | None
    name: Value | None = None
    other: tuple[Value, ...] = ()  # as NodeAction.other
    respawn: Value | None = None  # as NodeAction.respawn
    respawn_span: Span | None = None  # where ``respawn=`` is written


@dataclass(frozen=True, slots=True)
class Timer(ActionBase):
    """``TimerAction`` / ``<timer>``; ``ros`` is ``RosTimer`` / ``<ros_timer>``."""

    period: Value
    actions: tuple["Action", ...]
    ros: bool = False


EventKind = Literal[
    "on_process_start", "on_process_exit", "on_execution_complete", "on_shutdown",
    "on_state_transition", "on_process_io", "on_include_launch_description", "other",
]


@dataclass(frozen=True, slots=True)
class EventHandler(ActionBase):
    """``RegisterEventHandler(OnProcessExit(target_action=x, on_exit=[...]))``.

    ``target_id`` is the id of the target action when known; ``None`` for handlers that listen to
    every process or whose target cannot be resolved (``target_known`` False). For
    ``OnStateTransition``, ``goal_state``/``start_state`` carry the states when given."""

    event: EventKind
    target_id: str | None
    target_known: bool
    actions: tuple["Action", ...]
    goal_state: str | None = None
    start_state: str | None = None
    actions_span: Span | None = None  # where its actions are given (on_exit=[...])


@dataclass(frozen=True, slots=True)
class EmitEvent(ActionBase):
    """``EmitEvent(event=...)``. For a lifecycle ``ChangeState``: ``target_id`` is the action
    ``matches_action(x)`` names, ``target_name`` the literal name ``matches_node_name('...')``
    compares with, and ``matcher_span`` where the matcher is written."""
    event: str
    target_id: str | None = None
    target_name: str | None = None
    matcher_span: Span | None = None


@dataclass(frozen=True, slots=True)
class SetEnvironment(ActionBase):
    op: Literal["set", "unset", "append", "reset"]
    name: Value | None
    value: Value | None


@dataclass(frozen=True, slots=True)
class Log(ActionBase):
    message: Value


@dataclass(frozen=True, slots=True)
class Shutdown(ActionBase):
    reason: Value | None = None


@dataclass(frozen=True, slots=True)
class OpaqueAction(ActionBase):
    """Actions that cannot be known statically (an unknown call returning actions, an
    ``OpaqueFunction`` whose body could not be evaluated). ``reason`` says why. When an
    ``OpaqueFunction`` body was evaluated, its actions are in ``actions`` and ``reason`` is ''."""

    reason: str
    actions: tuple["Action", ...] = ()
    # What the OpaqueFunction's body substituted itself (``lc.perform(context)``): the launch
    # configurations it reads when it runs.
    other: tuple[Value, ...] = ()
    # For a body evaluated (``reason`` '') with values lost to ``if``s or conditional expressions
    # that a launch configuration it substitutes or looks up may decide: those (``other`` and the
    # looked-up ones). The resolver evaluates the body again with their strings (as for ``reason``).
    again: tuple[Value, ...] = ()


Action = Union[
    DeclareArgument, SetLaunchConfiguration, Include, Group, ResetLaunchConfigurations,
    PushNamespace, SetRemap, SetParameter, SetParametersFromFile, SetUseSimTime, NodeAction,
    LoadComposableNodes, ExecuteProcess, Timer, EventHandler, EmitEvent, SetEnvironment, Log,
    Shutdown, OpaqueAction,
]


# ---- facts the Python frontend records for the syntax-level rules ------------------------------


@dataclass(frozen=True, slots=True)
class CallFact:
    """A call of a known launch/launch_ros API: its qualified name (``launch_ros.actions.Node``),
    the keyword arguments given (name, span of the keyword) and the number of positional ones.
    ``value_kinds`` maps keyword name to a coarse kind of its value: "list", "dict", "tuple", "str",
    "number", "bool", "none", "call", "name", "other". ``splat`` is True when the call unpacks
    ``*args`` or ``**kwargs``: which arguments it passes is then unknown."""

    qualname: str
    span: Span
    kwargs: tuple[tuple[str, Span], ...]
    positional: int
    value_kinds: tuple[tuple[str, str], ...] = ()
    splat: bool = False


@dataclass(frozen=True, slots=True)
class NameFact:
    """A name used but never imported or defined (``undefined-name``)."""

    name: str
    span: Span
    function: str = ""  # the function whose body uses it ("": the module's code)
    visible: tuple[str, ...] = ()  # the names defined where it is used


@dataclass(frozen=True, slots=True)
class TypeFact:
    """A value of a Python type that launch rejects where the launch file gives it
    (``wrong-argument-type``). ``kind``: "text", a bool or number where launch wants a string or
    substitutions; "pairs", a dict where launch iterates (name, value) pairs (``launch_arguments``);
    "remap", a remap rule that is not a tuple (a list, or a dict's key); "plain-bool" and
    "plain-number", a string or substitution where launch uses the value as is (``shell``,
    ``respawn_delay``); "entities", a string, number or substitution where launch wants actions
    (``on_exit``); "path-string", one string where PathJoinSubstitution iterates components. ``call`` names the
    argument as written (``DeclareLaunchArgument(default_value=...)``), ``value`` is the Python
    value's repr (shortened) and ``type`` its type's name."""

    kind: Literal["text", "pairs", "remap", "remap-bare", "plain-bool", "plain-number", "entities", "period",
                  "event", "part", "path-string"]
    call: str
    value: str
    type: str
    span: Span


@dataclass(frozen=True, slots=True)
class ConcatFact:
    """A substitution joined at description time: ``'a' + LaunchConfiguration('x')``,
    ``os.path.join(FindPackageShare('p'), 'x')``, f-string of a substitution (``how``)."""

    how: Literal["plus", "os.path.join", "path", "f-string", "format", "percent", "str", "join",
                 "truth", "equals", "not-equals", "call", "condition", "get_package_share",
                 "get_package_prefix"]
    span: Span
    detail: str


@dataclass(frozen=True, slots=True)
class LateFact:
    """A function launch calls later (``caller``: "OpaqueFunction", or the event handler's class)
    whose body reads ``name``, a variable of an enclosing function that was rebound after the
    function was made (a loop moved on): the body sees ``now``, not ``made`` (reprs, or "" when not
    a plain value). ``span``: the ``lambda`` or ``def``."""

    caller: str
    name: str
    made: str
    now: str
    span: Span


# In ``PythonFacts.escaped``: the whole ``context.launch_configurations`` mapping was read
# (iterated, copied, handed on, indexed by an unknown name), so every configuration may be.
EVERY_CONFIGURATION = "*"


@dataclass(frozen=True, slots=True)
class PythonFacts:
    calls: tuple[CallFact, ...] = ()
    undefined_names: tuple[NameFact, ...] = ()
    concatenations: tuple[ConcatFact, ...] = ()
    has_generate_launch_description: bool = True
    # A launch test, not run by `ros2 launch`: a launch_testing file (defines
    # generate_test_description(), run by `launch_test`) or a launch_pytest module (run by pytest).
    is_launch_test: bool = False
    wrong_types: tuple[TypeFact, ...] = ()
    # Launch configurations (by name) handed to code the linter cannot follow (MoveItConfigsBuilder,
    # an unknown helper): it may read them, so they are never reported unused. EVERY_CONFIGURATION
    # when the code read the whole mapping.
    escaped: tuple[str, ...] = ()
    # A substitution tested as a Python value while the description is built: ``if lc:`` (always
    # true), ``lc == 'true'`` (always false). ``how`` is "truth", "equals" or "not-equals".
    tested: tuple[ConcatFact, ...] = ()
    # A call of a function the file defines with arguments its signature refuses (how "call";
    # detail: Python's TypeError message).
    call_errors: tuple[ConcatFact, ...] = ()
    # Package lookups (``FindPackage`` values, ``eager``) that building the description surely
    # makes (``get_package_share_directory('p')``, ``FindPackageShare('p').find('p')``): launch
    # fails there when the package does not exist, whether or not the path is used. Not those in a
    # ``try`` with handlers, in an undecided branch, or in a function launch calls later.
    lookups: tuple[Value, ...] = ()
    # ``from launch_ros.actions import Name`` of the launch packages' public modules, each with the
    # span of the imported name; not those in a ``try`` body with handlers (a compatibility
    # fallback) or in code the evaluation never ran.
    imports: tuple[tuple[str, str, Span], ...] = ()
    # Files opened for reading while the description is built (``open(path)``,
    # ``Path(path).read_text()``) whose path is known only symbolically (a package's share
    # directory), with the call's span; guarded as ``lookups`` are. A missing one raises
    # FileNotFoundError there.
    opens: tuple[tuple[Value, Span], ...] = ()
    # Functions launch calls later that read a variable rebound since they were made (LateFact).
    late_bound: tuple[LateFact, ...] = ()


@dataclass(frozen=True, slots=True)
class MarkupFacts:
    """XML/YAML: tags and attributes as written, for the unknown-attribute rule.
    Each element: (tag, parent tag, attribute names with spans, tag span)."""

    elements: tuple[tuple[str, str | None, tuple[tuple[str, Span], ...], Span], ...] = ()


@dataclass(frozen=True, slots=True)
class LaunchFile:
    path: str
    format: Literal["python", "xml", "yaml"]
    actions: tuple[Action, ...]
    python: PythonFacts | None = None
    markup: MarkupFacts | None = None
    # Workspace files the frontend read statically (yaml.safe_load of a config, sibling modules).
    read_files: tuple[str, ...] = field(default_factory=tuple)


fast_pickle_module(globals())  # tuples instead of dataclasses.fields() per object (model/pickling.py)
