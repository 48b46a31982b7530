"""What a node's code declares: topics, services, actions and parameters."""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Literal

from physai_lint.model.pickling import fast_pickle_module
from physai_lint.model.span import Span

ParamType = Literal[
    "bool", "integer", "double", "string",
    "bool_array", "integer_array", "double_array", "string_array", "byte_array",
]
PARAM_TYPES: frozenset[str] = frozenset(
    ("bool", "integer", "double", "string", "bool_array", "integer_array", "double_array",
     "string_array", "byte_array"))


@dataclass(frozen=True, slots=True)
class Endpoint:
    """A topic/service/action name exactly as written in the code (relative, absolute or ``~/``);
    ``type`` as ``pkg/msg/Name`` when known."""

    name: str
    type: str | None = None
    span: Span | None = None


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


fast_pickle_module(globals())  # tuples instead of dataclasses.fields() per object (model/pickling.py)
