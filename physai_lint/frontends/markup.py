"""Shared tag -> IR building for the XML and YAML frontends, so both formats give the same IR.

The readers (``xml_launch``, ``yaml_launch``) turn their documents into ``Element`` trees with
positions; ``build_launch_file`` maps tags to actions following SEMANTICS §5.
"""
from __future__ import annotations

import re
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from typing import Literal

from physai_lint.frontends.attributes import attribute_problems
from physai_lint.frontends.substitutions import parse_substitutions
from physai_lint.model.findings import Diagnostic
from physai_lint.model.launch import (
    Action,
    ComposableNode,
    Condition,
    DeclareArgument,
    EventHandler,
    ExecuteProcess,
    Group,
    Include,
    IncludeArgument,
    LaunchFile,
    LoadComposableNodes,
    Log,
    MarkupFacts,
    NodeAction,
    OpaqueAction,
    ParamDict,
    ParamEntry,
    ParamFile,
    ParamSource,
    PushNamespace,
    Remapping,
    ResetLaunchConfigurations,
    SetEnvironment,
    SetLaunchConfiguration,
    SetParameter,
    SetParametersFromFile,
    SetRemap,
    SetUseSimTime,
    Shutdown,
    Timer,
)
from physai_lint.model.span import Span
from physai_lint.model.values import (
    PList,
    PLit,
    PSubst,
    PValue,
    PyScalar,
    Text,
    Unknown,
    Value,
    literal_of,
)

Scalar = PyScalar | None


@dataclass
class Attr:
    """An attribute (XML) or scalar/list key (YAML) as written.

    ``text`` is the string form (for YAML, the scalar as written); ``typed`` is the YAML-constructed
    value for non-string scalars and lists (``None`` for XML and YAML strings)."""

    name: str
    text: str
    name_span: Span
    value_span: Span
    positions: Sequence[tuple[int, int]] | None = None
    is_str: bool = True
    typed: Scalar | tuple[object, ...] = None
    items: tuple[Attr, ...] = ()


@dataclass
class Element:
    tag: str
    span: Span
    attrs: dict[str, Attr] = field(default_factory=dict)
    children: list[Element] = field(default_factory=list)
    parent: str | None = None
    single: bool = False  # YAML: one mapping where launch reads a list of mappings


class _Builder:
    def __init__(self, path: str, fmt: str = "xml") -> None:
        self.path = path
        self.fmt = fmt
        self.diags: list[Diagnostic] = []
        self.facts: list[tuple[str, str | None, tuple[tuple[str, Span], ...], Span]] = []

    # ---- values ---------------------------------------------------------------------------
    def value_of(self, attr: Attr) -> Value:
        if not attr.is_str:
            return (Text(attr.text, attr.value_span),)
        value, diags = parse_substitutions(attr.text, attr.value_span, attr.positions)
        self.diags.extend(diags)
        return value

    def val(self, el: Element, name: str) -> Value | None:
        attr = el.attrs.get(name)
        return None if attr is None else self.value_of(attr)

    def req(self, el: Element, name: str) -> Value:
        """A required attribute; when it is missing (L009 reports it) the value is unknown, so
        no later rule reports on a made-up empty string."""
        v = self.val(el, name)
        return v if v is not None else (Unknown(f'missing "{name}"', el.span),)

    def lit(self, el: Element, name: str) -> str | None:
        attr = el.attrs.get(name)
        return None if attr is None else literal_of(self.value_of(attr))

    def flag(self, el: Element, name: str, default: bool) -> bool:
        raw = self.lit(el, name)
        if raw is None:
            return default
        low = raw.strip().lower()
        return True if low in ("true", "1") else False if low in ("false", "0") else default

    def truth(self, el: Element, name: str, default: bool) -> bool:
        """A plain-bool attribute (group ``scoped``/``forwarding``) as the action sees it: XML text
        goes through ``coerce_to_type(bool, can_be_str=True)`` and YAML is taken as is, so text
        that is not a boolean (a substitution, YAML ``"false"``) stays a non-empty string: true.
        L010 reports those."""
        attr = el.attrs.get(name)
        if attr is None:
            return default
        if not attr.is_str:
            return bool(attr.typed) if isinstance(attr.typed, (bool, int, float)) else default
        if self.fmt == "yaml":
            return bool(attr.text)
        from physai_lint.params.typing import pyyaml_type

        value = pyyaml_type(attr.text)
        return bool(value) if isinstance(value, (bool, int, float, str)) else default

    def condition(self, el: Element) -> Condition | None:
        given = [n for n in ("if", "unless") if n in el.attrs]
        if not given:
            return None
        if len(given) == 2:
            self.diags.append(Diagnostic(
                "L002", el.attrs["unless"].name_span, 'both "if" and "unless" given',
                'launch rejects an action with both; keep one condition', key="if+unless"))
        attr = el.attrs[given[0]]
        return Condition(given[0], self.value_of(attr), attr.value_span, f'{given[0]}="{attr.text}"')  # type: ignore[arg-type]

    @staticmethod
    def ident(el: Element) -> str:
        return f"{el.span.line}:{el.span.col}"

    def kids(self, el: Element, *tags: str) -> list[Element]:
        return [c for c in el.children if c.tag in tags]

    # ---- tree walk --------------------------------------------------------------------------
    def record(self, el: Element) -> None:
        names = tuple((a.name, a.name_span) for a in el.attrs.values())
        self.facts.append((el.tag, el.parent, names, el.span))
        for child in el.children:
            self.record(child)

    def actions(self, elements: list[Element]) -> tuple[Action, ...]:
        out: list[Action] = []
        for el in elements:
            maker = _ACTIONS.get(el.tag)
            if maker is not None:
                out.append(maker(self, el))
                if el.tag in _PROCESS_TAGS:
                    out.extend(self.on_exit(el, out[-1]))
            elif el.tag not in _NON_ACTIONS:
                out.append(OpaqueAction(self.ident(el), el.span, self.condition(el),
                                        f'unknown tag "{el.tag}"'))
        return tuple(out)

    # ---- actions ----------------------------------------------------------------------------
    def arg(self, el: Element) -> Action:
        name_attr = el.attrs.get("name")
        choices = tuple(c for c in (self.lit(ch, "value") for ch in self.kids(el, "choice"))
                        if c is not None)
        return DeclareArgument(
            self.ident(el), el.span, self.condition(el), name=self.lit(el, "name") or "",
            default=self.val(el, "default"), description=self.lit(el, "description"),
            choices=choices or None, name_span=name_attr.value_span if name_attr else None)

    def let(self, el: Element) -> Action:
        return SetLaunchConfiguration(self.ident(el), el.span, self.condition(el),
                                      self.req(el, "name"), self.req(el, "value"))

    def include(self, el: Element) -> Action:
        args = tuple(IncludeArgument(self.lit(a, "name") or "", self.req(a, "value"), a.span)
                     for a in self.kids(el, "arg"))
        return Include(self.ident(el), el.span, self.condition(el), self.req(el, "file"), args,
                       "any")

    def keep(self, el: Element) -> tuple[tuple[Value, Value], ...]:
        return tuple((self.req(k, "name"), self.req(k, "value")) for k in self.kids(el, "keep"))

    def group(self, el: Element) -> Action:
        return Group(self.ident(el), el.span, self.condition(el), self.actions(el.children),
                     scoped=self.truth(el, "scoped", True),
                     forwarding=self.truth(el, "forwarding", True),
                     launch_configurations=self.keep(el))

    def reset(self, el: Element) -> Action:
        keep = self.keep(el)
        return ResetLaunchConfigurations(self.ident(el), el.span, self.condition(el),
                                         keep if keep else None)

    def simple(self, el: Element) -> Action:
        i, s, c = self.ident(el), el.span, self.condition(el)
        tag = el.tag
        if tag in ("push-ros-namespace", "push_ros_namespace"):
            return PushNamespace(i, s, c, self.req(el, "namespace"))
        if tag == "set_remap":
            return SetRemap(i, s, c, self.req(el, "from"), self.req(el, "to"))
        if tag == "set_parameter":
            attr = el.attrs.get("value")
            pv = self.pvalue(attr, None, None) if attr else PSubst((Text("", s),), span=s)
            return SetParameter(i, s, c, self.req(el, "name"), pv)
        if tag == "set_parameters_from_file":
            return SetParametersFromFile(i, s, c, self.req(el, "filename"))
        if tag == "set_use_sim_time":
            return SetUseSimTime(i, s, c, self.req(el, "value"))
        if tag == "log":
            return Log(i, s, c, self.req(el, "message"))
        if tag == "shutdown":
            return Shutdown(i, s, c, self.val(el, "reason"))
        op: Literal["set", "unset", "append", "reset"] = _ENV_OPS[tag]
        return SetEnvironment(i, s, c, op, self.val(el, "name"), self.val(el, "value"))

    def timer(self, el: Element) -> Action:
        return Timer(self.ident(el), el.span, self.condition(el), self.req(el, "period"),
                     self.actions(el.children), ros=el.tag == "ros_timer")

    def executable(self, el: Element) -> Action:
        cmd = self.val(el, "cmd")
        return ExecuteProcess(self.ident(el), el.span, self.condition(el),
                              split_cmdline(cmd) if cmd is not None else None, self.val(el, "name"),
                              self.other(el), self.val(el, "respawn"))

    def on_exit(self, el: Element, action: Action) -> list[Action]:
        """``on_exit="shutdown"``: ``ExecuteProcess.parse`` gives the process ``on_exit=[Shutdown()]``,
        which launch registers as an ``OnProcessExit`` handler when the process starts (jazzy+;
        humble rejects the attribute, L002; any other text fails, L010)."""
        attr = el.attrs.get("on_exit")
        if attr is None or attr.text != "shutdown":
            return []
        return [EventHandler(f"{action.id}/on_exit", attr.value_span, action.condition,
                             "on_process_exit", action.id, True,
                             (Shutdown(f"{action.id}/on_exit/shutdown", attr.value_span, None),))]

    def other(self, el: Element) -> tuple[Value, ...]:
        """The process attributes launch substitutes that no rule models, and ``<env>`` values."""
        out = [v for v in (self.val(el, n) for n in _OTHER_ATTRS) if v is not None]
        for env in self.kids(el, "env"):
            out.extend(v for v in (self.val(env, "name"), self.val(env, "value")) if v is not None)
        return tuple(out)

    def node(self, el: Element) -> Action:
        spans: list[tuple[str, Span]] = []
        for attr_name, key in _NODE_FIELDS:
            if attr_name in el.attrs:
                spans.append((key, el.attrs[attr_name].value_span))
        for tag, key in (("param", "parameters"), ("remap", "remappings")):
            first = self.kids(el, tag)
            if first:
                spans.append((key, first[0].span))
        args, ros_args = self.val(el, "args"), self.val(el, "ros_args")
        kind: Literal["node", "container"] = "container" if el.tag == "node_container" else "node"
        return NodeAction(
            self.ident(el), el.span, self.condition(el), kind, self.val(el, "pkg"),
            self.val(el, "exec"), self.val(el, "name"), self.val(el, "namespace"),
            parameters=self.params(el), remappings=self.remaps(el),
            arguments=split_cmdline(args) if args is not None else (),
            ros_arguments=split_cmdline(ros_args) if ros_args is not None else (),
            composable_nodes=tuple(self.composable(c) for c in self.kids(el, "composable_node")),
            field_spans=tuple(spans), exec_name=self.val(el, "exec_name"), other=self.other(el),
            respawn=self.val(el, "respawn"))

    def load(self, el: Element) -> Action:
        return LoadComposableNodes(
            self.ident(el), el.span, self.condition(el), self.val(el, "target"), None,
            tuple(self.composable(c) for c in self.kids(el, "composable_node")))

    def composable(self, el: Element) -> ComposableNode:
        # launch_ros parses each value as substitutions, typed by YAML when the node is loaded
        extra = tuple((self.lit(x, "name") or "", PSubst(self.req(x, "value"), None, x.span), x.span)
                      for x in self.kids(el, "extra_arg"))
        return ComposableNode(
            self.val(el, "pkg"), self.val(el, "plugin"), self.val(el, "name"),
            self.val(el, "namespace"), self.params(el), self.remaps(el), extra, el.span,
            self.condition(el), self.ident(el))

    def remaps(self, el: Element) -> tuple[Remapping, ...]:
        return tuple(Remapping(self.req(r, "from"), self.req(r, "to"), r.span)
                     for r in self.kids(el, "remap"))

    # ---- parameters -------------------------------------------------------------------------
    def params(self, el: Element) -> tuple[ParamSource, ...]:
        out: list[ParamSource] = []
        for p in self.kids(el, "param"):
            if "from" in p.attrs:
                out.append(ParamFile(self.req(p, "from"), p.span,
                                     self.flag(p, "allow_substs", False)))
            else:
                out.append(ParamDict(tuple(self.entries(p, "")), p.span))
        return tuple(out)

    def entries(self, p: Element, prefix: str) -> list[ParamEntry]:
        attr = p.attrs.get("name")
        name = prefix + (self.name_text(attr) if attr else "")
        nested = self.kids(p, "param")
        if nested:
            return [e for n in nested for e in self.entries(n, name + ".")]
        value = p.attrs.get("value")
        sep_attr = p.attrs.get("value-sep") or p.attrs.get("value_sep")
        pv = self.pvalue(value, self.lit(p, "type"), sep_attr.text if sep_attr else None) \
            if value is not None else PSubst((Text("", p.span),), span=p.span)
        return [ParamEntry(name, pv, p.span)]

    def name_text(self, attr: Attr) -> str:
        value = self.value_of(attr)
        lit = literal_of(value)
        return lit if lit is not None else attr.text

    def pvalue(self, attr: Attr, vtype: str | None, sep: str | None) -> PValue:
        if attr.items or isinstance(attr.typed, tuple):
            items = [self.pvalue(i, vtype, None) for i in attr.items]
            if all(isinstance(i, PLit) for i in items):
                return PLit(tuple(i.value for i in items if isinstance(i, PLit)  # type: ignore[misc]
                                  ), attr.value_span)
            return PList(tuple(items), attr.value_span)
        if not attr.is_str and attr.typed is not None:
            return PLit(attr.typed, attr.value_span)  # type: ignore[arg-type]
        value = self.value_of(attr)
        if self.fmt == "yaml" and attr.is_str and sep is None and vtype in (None, "str", "yaml") \
                and all(isinstance(p, Text) for p in value):
            # launch_yaml's get_attr does not convert, and parse_if_substitutions keeps a string
            # without substitutions as the str it is: value: "10" reaches the node as "10"
            return PLit("".join(p.text for p in value if isinstance(p, Text)), attr.value_span)
        if vtype is None and sep is None and all(isinstance(p, Text) for p in value):
            from physai_lint.params.typing import yaml_syntax_error

            text = "".join(p.text for p in value if isinstance(p, Text))
            if text and yaml_syntax_error(text) is not None:
                # launch's get_attr(data_type=None) keeps a literal that YAML cannot read as the
                # string it is (launch_xml/launch_yaml Entity.get_attr -> coerce_to_type with
                # can_be_str): value="[*]" is "[*]", not a malformed list
                return PLit(text, attr.value_span)
        return PSubst(value, vtype, attr.value_span, sep)


_WS = re.compile(r"\s+")


def split_cmdline(value: Value) -> tuple[Value, ...]:
    """Split a value on whitespace in its text parts, like ``Action._parse_cmdline``."""
    out: list[Value] = []
    cur: list[object] = []
    for part in value:
        if not isinstance(part, Text):
            cur.append(part)
            continue
        pieces = [(m.start(), m.end()) for m in re.finditer(r"\S+", part.text)]
        starts_ws = bool(part.text) and part.text[0].isspace()
        ends_ws = bool(part.text) and part.text[-1].isspace()
        if not pieces:
            if part.text and cur:
                out.append(tuple(cur))  # type: ignore[arg-type]
                cur = []
            continue
        for k, (a, b) in enumerate(pieces):
            if (k > 0 or starts_ws) and cur:
                out.append(tuple(cur))  # type: ignore[arg-type]
                cur = []
            cur.append(Text(part.text[a:b], _sub_span(part.span, a, b)))
        if ends_ws:
            out.append(tuple(cur))  # type: ignore[arg-type]
            cur = []
    if cur:
        out.append(tuple(cur))  # type: ignore[arg-type]
    return tuple(out)


def _sub_span(span: Span | None, a: int, b: int) -> Span | None:
    if span is None or span.line != span.end_line:
        return span
    return Span(span.file, span.line, span.col + a, span.line, span.col + b)


# ExecuteProcess.parse: read with parse_substitution (the numbers and bools are literals).
_OTHER_ATTRS = ("output", "launch-prefix", "cwd")
_NODE_FIELDS = (("pkg", "package"), ("exec", "executable"), ("name", "name"),
                ("namespace", "namespace"), ("exec_name", "exec_name"), ("args", "arguments"),
                ("ros_args", "ros_arguments"))
_ENV_OPS: dict[str, Literal["set", "unset", "append", "reset"]] = {
    "set_env": "set", "unset_env": "unset", "append_env": "append", "reset_env": "reset"}
_PROCESS_TAGS = frozenset({"executable", "node", "node_container"})
_NON_ACTIONS = frozenset({"param", "remap", "env", "choice", "keep", "extra_arg",
                          "composable_node", "set_ros_log_dir"})
_ACTIONS: dict[str, Callable[[_Builder, Element], Action]] = {
    "arg": _Builder.arg, "let": _Builder.let, "include": _Builder.include,
    "group": _Builder.group, "reset": _Builder.reset, "timer": _Builder.timer,
    "ros_timer": _Builder.timer, "executable": _Builder.executable, "node": _Builder.node,
    "node_container": _Builder.node, "load_composable_node": _Builder.load,
    **{t: _Builder.simple for t in (
        "push-ros-namespace", "push_ros_namespace", "set_remap", "set_parameter",
        "set_parameters_from_file", "set_use_sim_time", "log", "shutdown", "set_env",
        "unset_env", "append_env", "reset_env")},
}


def build_launch_file(path: str, fmt: Literal["xml", "yaml"], root: Element,
                      ) -> tuple[LaunchFile, list[Diagnostic]]:
    """The IR of a ``<launch>`` element tree, plus substitution/condition diagnostics."""
    b = _Builder(path, fmt)
    b.record(root)
    actions = b.actions(root.children)
    facts = MarkupFacts(tuple(b.facts))
    diags = b.diags + attribute_problems(root, fmt)
    return LaunchFile(path, fmt, actions, markup=facts), diags
