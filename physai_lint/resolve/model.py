"""The resolved model: what ROS 2 would launch from one entry file under given arguments.

``None`` in a resolved string field means "cannot be known statically"; rules stay silent on it.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Literal, Union

from physai_lint.model.findings import Diagnostic
from physai_lint.model.launch import ComposableNode, NodeAction
from physai_lint.model.pickling import fast_init, fast_pickle_module
from physai_lint.model.span import Span

Activity = Union[bool, None]  # True, False, or None for unknown
# nav2's lifecycle manager, as a process and as a component: (package, executable or plugin)
LIFECYCLE_MANAGERS = frozenset({("nav2_lifecycle_manager", "lifecycle_manager"),
                                ("nav2_lifecycle_manager", "nav2_lifecycle_manager::LifecycleManager")})
NodeKind = Literal["node", "lifecycle_node", "container", "composable_node", "process"]

# A parameter value as launch hands it over: bool, int, float, str, or a homogeneous list of those.
# ``None`` means unknown.
ParamScalar = Union[bool, int, float, str]
ParamValue = Union[ParamScalar, list[ParamScalar], None]


@fast_init
@dataclass(frozen=True, slots=True)
class EffRemap:
    """One remapping rule as handed to the node, in rcl order. ``origin`` "global" = ``SetRemap`` in
    scope; "node" = the node's own ``remappings``. ``node_prefix`` for ``node:from:=to`` rules."""

    src: str | None
    dst: str | None
    span: Span
    origin: Literal["global", "node"]
    node_prefix: str | None = None


@dataclass(frozen=True, slots=True)
class ResolvedParamFile:
    """A parameter file a node loads. ``path`` is the path launch would open (for a workspace
    package: under the virtual install prefix); ``source`` is the file in the workspace it comes
    from when known. ``status``: "ok" (exists after install), "missing" (exists nowhere),
    "not_installed" (in the source tree but no install rule covers it), "unknown"."""

    path: str | None
    source: str | None
    status: Literal["ok", "missing", "not_installed", "unknown"]
    span: Span
    # command_line: --params-file in arguments; forwarded: the container's, which a component
    # loaded with forward_global_arguments reads through rcl like its container
    origin: Literal["global", "node", "command_line", "forwarded"]
    allow_substs: bool = False
    # A temporary file a substitution writes (nav2_common RewrittenYaml/ReplaceString): the model
    # rcl reads from it, positions mapped back to the source YAML; ``derived_from`` is that source.
    model: Any = field(default=None, compare=False, repr=False)
    derived_from: str | None = None
    # The substitution that opens ``path`` while launch runs ("RewrittenYaml", "ReplaceString"):
    # a file it cannot open fails the launch (FileNotFoundError), not only the node.
    opened_by: str | None = None


@fast_init
@dataclass(frozen=True, slots=True)
class ResolvedParam:
    """One parameter from a launch dict / ``<param>`` / ``SetParameter``: typed as launch types it
    (SEMANTICS §4a). ``value`` is ``None`` when unknown; ``raw`` is the string before YAML typing
    when it came from substitutions or markup."""

    name: str
    value: ParamValue
    span: Span
    raw: str | None = None
    typed_by: Literal["python", "yaml", "forced", "rcl"] = "python"  # rcl: -p on the command line
    item_spans: tuple[Span, ...] | None = None  # per list item, when written as a literal list
    # The command line of a value that is one Command([...]) typed by YAML, when known: its output
    # (never run) is what launch reads with YAML rules (P113 looks at the file it prints)
    command: str | None = None
    wrapped: bool = False  # PSubst.wrapped: a Python ParameterValue without a type


@fast_init
@dataclass(frozen=True, slots=True)
class ResolvedParamDict:
    """A dict source. ``key`` is the node key launch writes the temporary file under: the node's fqn
    when name and namespace are both known, else ``/**`` (``Node._create_params_file_from_dict``)."""

    params: tuple[ResolvedParam, ...]
    span: Span
    origin: Literal["global", "node", "forwarded"]
    key: str = "/**"


@dataclass(frozen=True, slots=True)
class UnknownParams:
    reason: str
    span: Span


ParamSourceR = Union[ResolvedParamFile, ResolvedParamDict, UnknownParams]


@dataclass
class NodeInstance:
    """One process or component ROS 2 would start. ``id`` is stable within one resolution."""

    id: str
    kind: NodeKind
    package: str | None
    executable: str | None  # for composable nodes: the plugin class
    name: str | None
    namespace: str | None  # absolute, "/" for root; None when unknown
    fqn: str | None
    active: Activity
    remaps: list[EffRemap]
    param_sources: list[ParamSourceR]  # command-line order: global first, then the node's own
    span: Span
    file: str
    action: NodeAction | ComposableNode | None
    action_id: str  # "<file>#<action id>" of the IR action it came from
    include_chain: tuple[str, ...] = ()
    name_explicit: bool = False  # name given in the launch file (not the executable's default)
    namespace_explicit: bool = False
    container: str | None = None  # fqn of the container, for composable nodes
    container_id: str | None = None
    arguments: tuple[str | None, ...] = ()
    in_timer: bool = False  # launched from a TimerAction (lost the group's namespace/remaps)
    timer_lost: tuple[str, ...] = ()  # what the timer made it lose ("namespace /r1", "remap a:=b")
    spans: dict[str, Span] = field(default_factory=dict)  # "package", "executable", "name", ...
    name_source: str | None = None  # set when the name is the one its code gives it (interfaces/naming.py)
    namespace_source: str | None = None
    package_from_config: bool = False  # the package name came from a launch configuration
    # A name given as "$(anon ID)" / AnonName(ID): "ID#k", equal for the nodes that get the same
    # generated name (AnonName caches it per ID in launch_configurations['anon']); else None.
    anon: str | None = None
    # A component's extra_arguments, typed as launch_ros sends them in the load request
    extra_args: tuple[ResolvedParam, ...] = ()


@fast_init
@dataclass(frozen=True, slots=True)
class ConfigRead:
    """A launch configuration read (``LaunchConfiguration``, ``$(var)``). ``defined`` False means
    nothing set it at that point (real launch raises). ``has_default`` when the read has its own."""

    name: str
    span: Span
    defined: bool
    has_default: bool
    active: Activity = True
    note: str = ""  # "timer period": read when a TimerAction performs its period, after the pass
    # the condition whose evaluation made the read: where a LaunchConfiguration made elsewhere
    # (a Python variable) is used
    site: Span | None = None


@dataclass
class DeclaredArg:
    name: str
    span: Span
    file: str
    default: str | None  # resolved default (None: no default, or unknown when default_known False)
    default_known: bool
    has_default: bool
    choices: tuple[str, ...] | None
    value: str | None  # the value it ends up with in this launch, None when unknown/unset
    value_origin: Literal["default", "include", "command-line", "none"]
    value_span: Span | None = None
    reads: int = 0


@dataclass
class IncludeRecord:
    span: Span
    file: str  # the including file
    target: str | None  # path launch would load (install space), None when unknown
    target_source: str | None  # the workspace file behind it
    status: Literal["ok", "missing", "not_installed", "unknown", "cycle", "unparsed"]
    arguments: list[tuple[str, str | None, Span]]  # name, resolved value, where it was passed
    declared: tuple[str, ...] | None  # args the included file declares (None: unknown)
    required_missing: tuple[str, ...] = ()
    active: Activity = True
    cycle: tuple[str, ...] = ()


@dataclass(frozen=True, slots=True)
class StartEdge:
    """An ordering edge for the startup plan: ``after`` starts after ``before`` (ids of nodes or of
    processes), for ``reason`` ("on_process_start", "on_process_exit", "timer 3.0 s", "container",
    "lifecycle", "topic /x"). ``soft`` edges (topic needs) do not make cycles errors."""

    before: str
    after: str
    reason: str
    span: Span
    delay: float | None = None
    soft: bool = False


@dataclass
class LaunchResult:
    entry: str
    arguments: dict[str, str | None]  # given on the command line plus declared defaults
    given: tuple[str, ...] = ()  # the names given on the command line (NAME:=VALUE)
    nodes: list[NodeInstance] = field(default_factory=list)
    config_reads: list[ConfigRead] = field(default_factory=list)
    declared_args: list[DeclaredArg] = field(default_factory=list)
    includes: list[IncludeRecord] = field(default_factory=list)
    edges: list[StartEdge] = field(default_factory=list)
    diagnostics: list[Diagnostic] = field(default_factory=list)  # found while resolving
    files: list[str] = field(default_factory=list)  # launch files visited, in order
    # SetRemap actions and the node ids they reached: (span, src, dst, node ids)
    set_remaps: list[tuple[Span, str | None, str | None, list[str]]] = field(default_factory=list)
    # Actions waiting on an event that can never come: (span, description)
    never_started: list[tuple[Span, str]] = field(default_factory=list)
    # LoadComposableNodes(target_container=<container action>) run before that action has: (its
    # span, the container action's line when known, why the container has not run then)
    early_loads: list[tuple[Span, int | None, str]] = field(default_factory=list)
    # Event handlers waiting on each other through an action that is no node (a TimerAction, a
    # GroupAction...), which the plan's node cycles cannot show: (the first handler's span, the
    # cycle as text, its steps as text, the other handlers' spans)
    # (span, path, steps, other spans, through a lifecycle node's transitions)
    trigger_cycles: list[tuple[Span, str, str, tuple[Span, ...], bool]] = field(default_factory=list)
    # Nodes that never start: every event handler that starts them waits, in the end, for one of
    # those trigger cycles (or for an action that never starts); their ids.
    blocked: list[str] = field(default_factory=list)
    # Timers: (span, period seconds or None when unknown, raw period text)
    timers: list[tuple[Span, float | None, str]] = field(default_factory=list)
    # A process action object run again (ExecuteLocal.execute raises "executed more than once"):
    # (the first run's node id, the later run's, the span of the event handler or timer that
    # runs it again, or None when the description lists it twice)
    repeated: list[tuple[str, str, Span | None]] = field(default_factory=list)
    # Processes an OnShutdown handler starts: (node id, where the handler's actions are given).
    # launch marks itself shut down before those handlers run when it ends on Ctrl-C or idle, and
    # ExecuteLocal.execute then starts nothing
    at_shutdown: list[tuple[str, Span | None]] = field(default_factory=list)
    # Nodes an event handler starts whose target action is never added to the description: the
    # handler never fires (there is no start edge to show it); their ids
    unstartable: list[str] = field(default_factory=list)
    # Packages referenced by FindPackageShare/$(find-pkg-share)/get_package_share_directory/...:
    # (name, span, file, whether the name came from a launch configuration, e.g. $(var model)_description)
    # (name, where, file, whether a launch configuration gave it: its name when it alone did)
    package_refs: list[tuple[str, Span | None, str, bool | str]] = field(default_factory=list)
    # Every PushRosNamespace: (span, the namespace as written, the resulting namespace or None)
    pushed_namespaces: list[tuple[Span, str | None, str | None]] = field(default_factory=list)
    # SetRemap/SetParameter inside a scoped group that reach nodes after it: (span, what, the outer
    # action that created the list, the nodes reached: node id -> the node's action)
    scope_leaks: list[tuple[Span, str, Span, dict[str, Span]]] = field(default_factory=list)
    use_sim_time_actions: list[Span] = field(default_factory=list)
    # Lifecycle transitions the launch itself requests (EmitEvent(ChangeState(...))): the target
    # node's action id ("<file>#<action id>"), None when the matcher may name any node
    lifecycle_changes: list[tuple[str | None, Span]] = field(default_factory=list)
    # The matchers of those transitions the linter can follow: ("action", the matched action's id,
    # where the matcher is written) for matches_action(x), ("name", the name compared with, where)
    # for matches_node_name('...')
    change_matchers: list[tuple[str, str, Span]] = field(default_factory=list)
    # Opaque parts whose effects are unknown: (span, reason)
    opaque: list[tuple[Span, str]] = field(default_factory=list)
    # The parts of ``opaque`` disabled by a condition false for this run's arguments: they start
    # nothing now (the plan leaves them out), though with other arguments they might (the rules,
    # which judge the launch file for every run, still treat them as unknown).
    inactive_opaque: list[tuple[Span, str]] = field(default_factory=list)
    # Condition values that are not true/false/1/0, and boolean substitution operands that are
    # not YAML booleans: (span, value, "condition" or the operator: "not", "and", ...)
    invalid_conditions: list[tuple[Span, str, str]] = field(default_factory=list)
    # PythonExpression / $(eval) texts that raise when evaluated: (span, text, the error)
    expression_errors: list[tuple[Span, str, str]] = field(default_factory=list)
    # Command / $(command) lines whose parts run two words together: (span, left word, right
    # word, the command line)
    glued_commands: list[tuple[Span, str, str, str]] = field(default_factory=list)
    # RewrittenYaml param_rewrites keys that rewrite nothing: (the key's span, the key, source file)
    unused_rewrites: list[tuple[Span, str, str]] = field(default_factory=list)
    # $(dirname)/ThisLaunchFileDir evaluated after an include: (span, got, the file's own dir)
    dirname_traps: list[tuple[Span, str, str]] = field(default_factory=list)
    # Start delay of nodes started by timers (node id -> seconds, None when unknown)
    delays: dict[str, float | None] = field(default_factory=dict)
    # Conditions of components that humble's LoadComposableNodes never evaluates (the component is
    # loaded anyway): (the condition's span, how it is written, the component's name or None)
    ignored_conditions: list[tuple[Span, str, str | None]] = field(default_factory=list)
    # Conditions that can never be true (or never false): (span, explanation)
    dead_conditions: list[tuple[Span, str]] = field(default_factory=list)
    # Parts that may read any launch configuration (a parameter file with allow_substs whose
    # path is unknown): (span, the launch files from the entry down to the one holding it)
    open_reads: list[tuple[Span, tuple[str, ...]]] = field(default_factory=list)
    # Files a Python launch file opens while its description is built (``PythonFacts.opens``),
    # as evaluated here: (path, span of the call).
    opened_files: list[tuple[str, Span]] = field(default_factory=list)


fast_pickle_module(globals())  # tuples instead of dataclasses.fields() per object (model/pickling.py)
