"""What a node's code declares: topics, services, actions and parameters."""
from __future__ import annotations

import re
from collections.abc import Iterable
from dataclasses import dataclass, field
from typing import Any, Literal

from physai_lint.model.pickling import fast_init, fast_pickle_module
from physai_lint.model.span import Span

ParamType = Literal[
    "bool", "integer", "double", "string",
    "bool_array", "integer_array", "double_array", "string_array", "byte_array",
]
PARAM_TYPES: frozenset[str] = frozenset(
    ("bool", "integer", "double", "string", "bool_array", "integer_array", "double_array",
     "string_array", "byte_array"))


@fast_init
@dataclass(frozen=True, slots=True)
class Endpoint:
    """A topic/service/action name exactly as written in the code (relative, absolute or ``~/``);
    ``type`` as ``pkg/msg/Name`` when known."""

    name: str
    type: str | None = None
    span: Span | None = None
    # the node has the endpoint only when each of these parameters has this value (its
    # effective value, else its declared default): imu_filter_madgwick subscribes to imu/mag
    # only with use_mag true
    when: tuple[tuple[str, Any], ...] = ()


# ``Endpoint.when`` of an endpoint the code makes only under a condition it tests at run time
# (``if (subscribe_scan_) { ... }``): a parameter no node has, so whether the node has the
# endpoint cannot be told. T201/T202 do not report it; it still counts as a topic's other end.
CODE_CONDITION: tuple[tuple[str, Any], ...] = (("(a condition in the code)", True),)


@dataclass
class ParamDecl:
    name: str
    type: str | None = None  # one of PARAM_TYPES, None when unknown
    default: Any = None
    min: float | None = None
    max: float | None = None
    choices: list[Any] | None = None
    read_only: bool = False
    validators: list[tuple[str, list[Any]]] = field(default_factory=list)
    description: str | None = None
    span: Span | None = None
    source: str = ""
    has_default: bool = False
    dynamic_type: bool = False  # declared with dynamic typing (any type accepted)


@dataclass
class NodeInterface:
    publishers: list[Endpoint] | None = None
    subscribers: list[Endpoint] | None = None
    services: list[Endpoint] | None = None
    clients: list[Endpoint] | None = None
    action_servers: list[Endpoint] | None = None
    action_clients: list[Endpoint] | None = None
    parameters: dict[str, ParamDecl] | None = None
    parameters_complete: bool = False
    source: str = ""
    # dotted-name prefixes of generate_parameter_library ``__map_`` subtrees: any parameter below
    # them is declared at run time
    parameter_patterns: list[str] = field(default_factory=list)
    # the code makes a lifecycle node: it has LIFECYCLE_ENDPOINTS too (the graph adds them)
    lifecycle: bool = False
    # (kind, type) of each endpoint the code makes under a name not known statically (a
    # parameter's value, a computed string): it may be the other end of any topic of that type
    unnamed: list[tuple[str, str | None]] = field(default_factory=list)
    # The name the code gives its node when the launch file gives none (``Node("talker")``,
    # ``super().__init__('talker')``), and where: ``node_name_decided`` says this layer has the
    # word on it; decided with ``node_name`` None, the name cannot be told (computed, or the
    # executable makes several nodes).
    node_name: str | None = None
    node_name_span: Span | None = None
    node_name_decided: bool = False
    # the namespace the code gives that node (``Node("driver", "robot1")``, rclpy
    # ``namespace='robot1'``), which stands when launch gives none: "" when it gives none
    node_namespace: str = ""

    def endpoints(self, kind: str) -> list[Endpoint]:
        return list(getattr(self, kind) or [])

    def is_declared(self, name: str) -> bool | None:
        """True/False when known; None when the declarations are incomplete."""
        if self.parameters is not None and name in self.parameters:
            return True
        if any(name.startswith(p) for p in self.parameter_patterns):
            return True
        if not self.parameters_complete:
            return None
        return False


ENDPOINT_KINDS = ("publishers", "subscribers", "services", "clients", "action_servers",
                  "action_clients")

# What every lifecycle node has besides its own endpoints (rcl_lifecycle's com_interface.c, which
# rclcpp_lifecycle and rclpy.lifecycle use): (kind, name, type).
LIFECYCLE_ENDPOINTS: tuple[tuple[str, str, str], ...] = (
    ("publishers", "~/transition_event", "lifecycle_msgs/msg/TransitionEvent"),
    ("services", "~/change_state", "lifecycle_msgs/srv/ChangeState"),
    ("services", "~/get_state", "lifecycle_msgs/srv/GetState"),
    ("services", "~/get_available_states", "lifecycle_msgs/srv/GetAvailableStates"),
    ("services", "~/get_available_transitions", "lifecycle_msgs/srv/GetAvailableTransitions"),
    ("services", "~/get_transition_graph", "lifecycle_msgs/srv/GetAvailableTransitions"),
)


# A node's own arguments renaming it (``NodeOptions().arguments({"--ros-args", "-r",
# "__node:=x"})``, rclpy ``cli_args``): rcl applies them before the command line's (launch's).
CODE_REMAP = re.compile(r"__(?:node|name|ns):=")

# A place the code makes a node: (its name, or None when not known statically; when that argument
# only passes on the name a constructor was given, that constructor's class ("" outside a class),
# else None; where; the namespace the code gives it: "" none, None not known statically)
NodeSite = tuple[str | None, str | None, Span | None, str | None]


def decide_node_name(iface: NodeInterface, sites: list[NodeSite],
                     makes: Iterable[tuple[str, str | None, Span | None]] = ()) -> None:
    """Set ``iface``'s node name (and the namespace its code gives the node) from the places its
    code makes a node. No place: no word on it. A name a constructor passes on
    (``Node(node_name)``) is the literal the code constructs that class with (``makes``: class,
    name or None when not a literal, where; ``make_shared<LifecycleTalker>("lc_talker")``).
    Then one literal name, wherever it is written, with one namespace: that name. Several names, a
    computed one or namespace, a name the code remaps itself (``-r __node:=`` in its own
    arguments, which rcl applies before launch's), or only names passed on from a caller not seen:
    decided, not known. A name passed on is left aside when a literal one is written elsewhere
    (the subclass's ``super().__init__('planner')`` names the node its base class makes)."""
    if not sites:
        return
    iface.node_name_decided = True
    given: dict[str, list[tuple[str | None, Span | None]]] = {}
    for cls, name, span in makes:
        given.setdefault(cls, []).append((name, span))
    resolved: list[NodeSite] = []
    for name, passed, span, ns in sites:
        if passed and passed in given:
            resolved.extend((n, None, s, ns) for n, s in given[passed])
        else:
            resolved.append((name, passed, span, ns))
    named = {n for n, _, _, _ in resolved if n is not None}
    if len(named) != 1 or any(n is None and passed is None for n, passed, _, _ in resolved):
        return
    name = named.pop()
    namespaces = {ns for n, _, _, ns in resolved if n == name}
    if len(namespaces) != 1 or None in namespaces:
        return
    iface.node_name, iface.node_namespace = name, namespaces.pop()
    iface.node_name_span = next(s for n, _, s, _ in resolved if n == name)


def with_lifecycle_endpoints(iface: Any) -> Any:
    """A copy of ``iface`` that also lists the endpoints of a lifecycle node (those it lists
    already are not added twice); ``iface`` itself is not changed."""
    import copy

    out = copy.copy(iface)
    for kind in {k for k, _, _ in LIFECYCLE_ENDPOINTS}:
        setattr(out, kind, list(getattr(iface, kind, None) or ()))
    for kind, name, type_ in LIFECYCLE_ENDPOINTS:
        have = getattr(out, kind)
        if not any(e.name == name for e in have):
            have.append(Endpoint(name, type_, None))
    return out


fast_pickle_module(globals())  # tuples instead of dataclasses.fields() per object (model/pickling.py)
