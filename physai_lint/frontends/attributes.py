"""Required attributes (L009) and attribute value types (L010) of XML/YAML launch markup.

Mirrors what the ``parse`` classmethods of the launch actions read (SEMANTICS §5) and how each
frontend's ``Entity.get_attr`` treats a value:

- ``launch_xml`` coerces the attribute text to the requested type with ``can_be_str=True``: text
  that does not convert (a word, a substitution) is *kept as a string*;
- ``launch_yaml`` does not coerce: it checks ``isinstance(value, (str, data_type))`` and raises
  ``TypeError`` otherwise, so ``default: 10`` (an int where a string is read) or ``period: 2``
  (an int where a float is read) abort the launch;
- a missing attribute that is not optional raises ``AttributeError`` in both.
"""
from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

from physai_lint.frontends.tags import ACCEPTED_BY_SCHEMA, ALIASES, suggest
from physai_lint.model.findings import Diagnostic

if TYPE_CHECKING:
    from physai_lint.frontends.markup import Attr, Element

# What each tag's parse() reads without optional=True. ("arg" under "include" is its own schema.)
REQUIRED: dict[str, tuple[str, ...]] = {
    "arg": ("name",), "choice": ("value",), "let": ("name", "value"), "include": ("file",),
    "include/arg": ("name", "value"), "keep": ("name", "value"), "executable": ("cmd",),
    "env": ("name", "value"), "node": ("exec",), "node_container": ("exec", "name", "namespace"),
    "composable_node": ("pkg", "plugin", "name"), "extra_arg": ("name", "value"),
    "remap": ("from", "to"), "load_composable_node": ("target",),
    "push-ros-namespace": ("namespace",), "push_ros_namespace": ("namespace",),
    "set_remap": ("from", "to"), "set_parameter": ("name", "value"),
    "set_parameters_from_file": ("filename",), "set_use_sim_time": ("value",),
    "set_ros_log_dir": ("new_log_dir",), "timer": ("period",), "ros_timer": ("period",),
    "set_env": ("name", "value"), "unset_env": ("name",), "append_env": ("name", "value"),
    "log": ("message",),
}
# Read by the action's constructor rather than by parse(): a TypeError instead of AttributeError.
_CONSTRUCTOR = {("node_container", "name"), ("node_container", "namespace")}

_PROCESS_FLOAT = ("respawn_delay", "sigterm_timeout", "sigkill_timeout")
_PROCESS_TAGS = ("executable", "node", "node_container")
# Attributes read with data_type=float/int/bool; everything else is read as a string.
_FLOAT: dict[str, frozenset[str]] = {t: frozenset(_PROCESS_FLOAT) for t in _PROCESS_TAGS}
_FLOAT["timer"] = _FLOAT["ros_timer"] = frozenset({"period"})
_INT: dict[str, frozenset[str]] = {t: frozenset({"respawn_max_retries"}) for t in _PROCESS_TAGS}
# Plain bools in the action (used by truthiness): a string stays a string, and is true.
_BOOL: dict[str, frozenset[str]] = {t: frozenset({"shell", "emulate_tty"}) for t in _PROCESS_TAGS}
_BOOL["group"] = frozenset({"scoped", "forwarding"})
# Bools the action also accepts as substitutions.
_BOOL_OR_SUBST: dict[str, frozenset[str]] = {
    "param": frozenset({"allow_substs"}), "append_env": frozenset({"prepend"}),
    "timer": frozenset({"cancel_on_shutdown"})}
_ANY = {("param", "value"), ("param", "type")}
# Keys whose YAML value must be a list of mappings (get_attr(data_type=List[Entity])).
_LIST_KEYS = frozenset({"param", "remap", "env", "arg", "choice", "keep", "composable_node",
                        "extra_arg"})
# Tags whose YAML mapping must hold "children" (launch_yaml Entity.children).
_YAML_CHILDREN = frozenset({"group", "timer", "ros_timer"})

_YAML_KIND = {bool: "a boolean", int: "an integer", float: "a float", type(None): "null"}
_PY_TYPE = {bool: "bool", int: "int", float: "float", type(None): "NoneType", tuple: "list"}


def _schema(el: Element) -> str:
    return "include/arg" if el.tag == "arg" and el.parent == "include" else el.tag


def attribute_problems(root: Element, fmt: str) -> list[Diagnostic]:
    """L009/L010 diagnostics (and the L002 ``param`` attribute conflicts) of a ``<launch>`` tree.
    Attributes unknown to the tag are left to L002."""
    out: list[Diagnostic] = []
    stack = [root]
    while stack:
        el = stack.pop()
        stack.extend(reversed(el.children))
        accepted = ACCEPTED_BY_SCHEMA.get(_schema(el))
        if accepted is None:
            continue
        out.extend(_yaml_types(el, accepted) if fmt == "yaml" else _xml_types(el))
        out.extend(_missing(el, fmt, accepted))
    return out


def _stands_for(el: Element, accepted: frozenset[str]) -> set[str]:
    """The accepted attributes that the element's unknown ones are misspellings of (L002 says so
    and suggests them, so a missing one is not reported again)."""
    meant: set[str] = set()
    for name in el.attrs:
        if name not in accepted:
            close = ALIASES.get((el.tag, name)) or suggest(name, accepted)
            if close:
                meant.add(close)
    return meant


def _missing(el: Element, fmt: str, accepted: frozenset[str]) -> Iterator[Diagnostic]:
    what = "key" if fmt == "yaml" else "attribute"
    need = list(REQUIRED.get(_schema(el), ()))
    kids = {c.tag for c in el.children}
    if el.tag == "param" and el.parent != "param" and "from" not in el.attrs \
            and "name" not in el.attrs:
        yield _diag("L009", el, '"param" has neither "name" nor "from"; launch fails with '
                    '"param Entity should have name or from attribute"',
                    "add name: and value: for one parameter, or from: for a file" if fmt == "yaml"
                    else 'add name="..." value="..." for one parameter, or from="..." for a file',
                    "param:name|from")
    elif el.tag == "param" and el.parent == "param" and "name" not in el.attrs:
        yield _diag("L009", el, 'nested "param" has no "name"; launch fails with "Attribute '
                    "'name' not found in Entity 'param'\"",
                    "add name: ..." if fmt == "yaml" else 'add name="..."', "param:name")
    elif el.tag == "param" and "name" in el.attrs and "value" not in el.attrs \
            and "from" not in el.attrs and "param" not in kids and "value" not in kids:
        name = el.attrs["name"].text
        yield _diag("L009", el, f'parameter "{name}" has no "value" and no nested "param"; '
                    'launch fails with "either a value attribute or nested params are needed"',
                    "add value: ..." if fmt == "yaml" else 'add value="..."', "param:value")
    if el.tag == "param":
        yield from _param_conflicts(el, kids)
    if el.tag == "load_composable_node" and "composable_node" not in kids:
        yield _diag("L009", el, '"load_composable_node" has no "composable_node"; launch fails '
                    "with AttributeError: Attribute 'composable_node' not found",
                    "list the components to load inside it", "load:composable_node")
    if fmt == "yaml" and el.tag in _YAML_CHILDREN and "children" not in el.attrs and \
            not el.children:
        yield _diag("L009", el, f'"{el.tag}" has no "children"; launch fails with "Expected '
                    f'entity `{el.tag}` to have children entities."',
                    "put its actions in a children: list", f"{el.tag}:children")
    missing = [n for n in need if n not in el.attrs and n not in kids]
    if not missing:
        return
    meant = _stands_for(el, accepted)
    for name in missing:
        if name in meant:
            continue  # L002 already reports the misspelling and suggests this name
        if (el.tag, name) in _CONSTRUCTOR:
            why = (f"launch fails with TypeError: ComposableNodeContainer.__init__() missing "
                   f"required keyword-only argument '{name}'")
        elif fmt == "yaml":
            why = f"launch fails with \"Can not find attribute '{name}' in Entity '{el.tag}'\""
        else:
            why = (f"launch fails with \"Attribute '{name}' of type '<class 'str'>' not found "
                   f"in Entity '{el.tag}'\"")
        example = f'{name}: ...' if fmt == "yaml" else f'{name}="..."'
        yield _diag("L009", el, f'"{el.tag}" has no "{name}" {what}, which launch requires; '
                    f"{why}", f"add {example}", f"{_schema(el)}:{name}")


def _param_conflicts(el: Element, kids: set[str]) -> Iterator[Diagnostic]:
    """Attribute combinations ``Node.parse_nested_parameters`` rejects (reported as L002, like
    ``if`` with ``unless``)."""
    attrs = el.attrs
    if el.parent != "param" and "from" in attrs and "name" in attrs:
        yield Diagnostic("L002", attrs["from"].name_span, '"param" has both "name" and "from"; '
                         'launch fails with "name and from attributes are mutually exclusive"',
                         'keep "from" to load a file, or "name" with "value" for one parameter',
                         key="param:name+from")
    elif el.parent != "param" and "allow_substs" in attrs and "from" not in attrs:
        yield Diagnostic("L002", attrs["allow_substs"].name_span,
                         '"allow_substs" on a "param" without "from"; launch fails with '
                         "\"'allow_substs' can only be used together with 'from' attribute\"",
                         'remove it, or use it on a <param from="..."/>',
                         key="param:allow_substs")
    elif "name" in attrs and "param" in kids:
        for other, what in (("value", "value"), ("type", "type")):
            if other in attrs:
                yield Diagnostic(
                    "L002", attrs[other].name_span, f'parameter "{attrs["name"].text}" has both '
                    f'"{other}" and nested "param"; launch fails with "nested parameters and '
                    f'{what} attributes are mutually exclusive"',
                    f'remove "{other}", or the nested parameters', key=f"param:{other}+param")


def _diag(code: str, el: Element, message: str, help_: str, key: str) -> Diagnostic:
    return Diagnostic(code, el.span, message, help_, key=key)


def _yaml_kind(attr: Attr) -> type:
    if attr.items or isinstance(attr.typed, tuple):
        return tuple
    if attr.is_str:
        return str
    return type(attr.typed) if type(attr.typed) in _YAML_KIND else str


def _yaml_types(el: Element, accepted: frozenset[str]) -> Iterator[Diagnostic]:
    tag = el.tag
    for name, attr in el.attrs.items():
        if (tag, name) == ("param", "value"):
            typed = list(_yaml_param_typed(el, attr))
            yield from typed or _yaml_param_list(el, attr)  # one finding for one TypeError
        if name not in accepted or (tag, name) in _ANY or name == "children":
            continue
        kind = _yaml_kind(attr)
        shown = _shown(attr, kind)
        if name == "on_exit" and kind is str:
            yield from _on_exit(attr, tag, "yaml")
            continue
        if name in _FLOAT.get(tag, ()):
            if kind is float or (kind is str and name == "period"):
                continue
            if kind is str:  # respawn_delay: "2.0" is kept as text and compared with 0.0
                yield _attr_diag(
                    attr, f'key "{name}" of "{tag}" is the string {shown}: launch keeps it as '
                    "text and fails with TypeError: '<' not supported between instances of "
                    "'str' and 'float'", f"write a number: {name}: {_as_float(attr.text)}",
                    f"{tag}:{name}:str")
                continue
            yield _type_error(attr, tag, name, kind, float,
                              f"write it as a float: {name}: {_as_float(attr.text)}")
        elif name in _INT.get(tag, ()):
            if kind is int or kind is bool:
                continue
            if kind is str:
                yield _attr_diag(
                    attr, f'key "{name}" of "{tag}" is the string {shown}: launch keeps it as '
                    "text and fails with TypeError when the process exits and is respawned",
                    f"write an integer: {name}: 3", f"{tag}:{name}:str")
                continue
            yield _type_error(attr, tag, name, kind, int, f"write an integer: {name}: 3")
        elif name in _BOOL.get(tag, ()):
            if kind is bool:
                continue
            if kind is str:
                yield _truthy(attr, tag, name, _yaml_boolean_help(attr.text, name))
                continue
            yield _type_error(attr, tag, name, kind, bool, f"write {name}: true or {name}: false")
        elif name in _BOOL_OR_SUBST.get(tag, ()):
            if kind not in (bool, str):
                yield _type_error(attr, tag, name, kind, bool,
                                  f"write {name}: true or {name}: false")
        elif kind is not str:
            text = attr.text if kind is not tuple else "[...]"
            yield _type_error(attr, tag, name, kind, str, f'quote it: {name}: "{text}"'
                              if kind is not tuple else
                              f'write it as one string: {name}: "a b c"')
    for child in el.children:
        if child.tag in accepted and child.single:  # "value: {p: 1}": a mapping, not a scalar
            want = "float" if child.tag in _FLOAT.get(tag, ()) else "scalar or list of scalars" \
                if (tag, child.tag) in _ANY else "str"
            yield Diagnostic(
                "L010", child.span, f'key "{child.tag}" of "{tag}" is a mapping but launch reads '
                f"a {want} here; it fails with TypeError \"Attribute '{child.tag}' of Entity "
                f"'{tag}' expected to be of type ..., got '<class 'dict'>'\"",
                "write nested parameters as a param: list of name/value entries"
                if tag == "param" else f"give {child.tag} a single value",
                key=f"{tag}:{child.tag}:dict")
        elif child.tag in _LIST_KEYS and child.single:
            yield Diagnostic(
                "L010", child.span, f'key "{child.tag}" of "{tag}" is a mapping; launch wants a '
                f"list of mappings and fails with TypeError \"Attribute '{child.tag}' of Entity "
                f"'{tag}' expected to be a list of dictionaries.\"",
                'make it a list: put "- " before its first key', key=f"{tag}:{child.tag}:map")


def get_attr_rejects(kinds: list[type]) -> bool:
    """Whether a frontend's ``Entity.get_attr`` rejects a list with items of these Python types
    (launch ``is_instance_of_valid_type`` with strings allowed): it wants scalars whose non-string
    items are all of the first non-string one's type."""
    first = next((k for k in kinds if k is not str), str)
    return first not in (str, bool, int, float) or \
        any(k is not str and not issubclass(k, first) for k in kinds)


def _yaml_param_list(el: Element, attr: Attr) -> Iterator[Diagnostic]:
    """A YAML list parameter value launch rejects (P106): ``get_attr`` (``is_instance_of_valid_type``
    with strings allowed) wants scalars whose non-string items share the first one's type, and
    ``parse_if_substitutions`` then wants one type among the values and plain texts."""
    if not attr.items:
        return
    kinds = [_yaml_kind(item) for item in attr.items]
    name = el.attrs["name"].text if "name" in el.attrs else "?"
    shown = "[" + ", ".join(i.text if i.is_str or not i.items else "[...]"
                            for i in attr.items) + "]"
    if get_attr_rejects(kinds):
        why = ("TypeError \"Attribute 'value' of Entity 'param' expected to be of type 'None', "
               "got '<class 'list'>'\"")
    elif len({k for k in kinds if k is not str} |
             {str for i in attr.items if i.is_str and "$(" not in i.text}) > 1:
        why = "ValueError \"The result is a non-uniform list\""
    else:
        return
    what = "items of different types" if all(k in (str, bool, int, float) for k in kinds) \
        else "items that are not scalars (a list or null)"
    yield Diagnostic(
        "P106", attr.value_span, f'parameter "{name}" value {shown} is a list with {what}; '
        f"launch fails with {why}",
        "make every item the same type (e.g. all floats: 1.0, 2.5; all strings in quotes)",
        key=name)


_TYPE_IDS: dict[str, type] = {"str": str, "bool": bool, "int": int, "float": float}


def _yaml_param_typed(el: Element, attr: Attr) -> Iterator[Diagnostic]:
    """A YAML parameter value that is not of the Python type its ``type:`` names (L010).

    ``Node.parse_nested_parameters`` reads ``value`` with ``get_attr(data_type=<type>)``, which
    in launch_yaml converts nothing (``is_instance_of`` with strings allowed, so ``int`` is not a
    ``float``); a string without substitutions then stays a str (``parse_if_substitutions``) and
    ``ParameterValue`` -> ``normalize_typed_substitution`` raises TypeError unless the type is str.
    A string with substitutions is converted when it is evaluated and is left alone here."""
    type_attr = el.attrs.get("type")
    if type_attr is None or not type_attr.is_str:
        return
    ident = type_attr.text.strip()
    listed = ident.startswith("list_of_")
    want = _TYPE_IDS.get(ident[len("list_of_"):] if listed else ident)
    if want is None:
        return
    name = el.attrs["name"].text if "name" in el.attrs else "?"
    kind = _yaml_kind(attr)
    shown = f"the list {_list_text(attr)}" if kind is tuple else _shown(attr, kind)
    if listed:
        if kind is not tuple:
            why = (f"TypeError \"Attribute 'value' of Entity 'param' expected to be of type "
                   f"'typing.List[{want.__name__}]', got '<class '{_PY_TYPE.get(kind, 'str')}'>'\"")
            help_ = f"write a YAML list: value: [...], or drop type: {ident}"
        else:
            kinds = [_yaml_kind(i) for i in attr.items]
            if any(k is not str and not issubclass(k, want) for k in kinds):
                bad = next(k for k in kinds if k is not str and not issubclass(k, want))
                why = (f"TypeError \"Attribute 'value' of Entity 'param' expected to be of type "
                       f"'typing.List[{want.__name__}]', got '<class 'list'>'\" (an item is "
                       f"{_YAML_KIND.get(bad, 'a list')})")
                help_ = (f"write every item as a {want.__name__}"
                         + (" (1.0, not 1)" if want is float else ""))
            elif want is not str and not kinds:
                # normalize_typed_substitution: no item type is a subset of {str, Substitution}
                why = (f"TypeError \"Got a list of '<class 'str'>', expected a list of "
                       f"'<class '{want.__name__}'>'\": launch takes an empty list for a list of strings")
                help_ = f"give at least one item, or drop type: {ident}"
            elif want is not str and kinds and all(k is str for k in kinds) and \
                    not all("$(" in i.text for i in attr.items):
                why = (f"TypeError \"Got a list of '<class 'str'>', expected a list of "
                       f"'<class '{want.__name__}'>'\": launch_yaml does not convert quoted items")
                help_ = "write the items without quotes"
            else:
                return
    elif kind is str:
        if want is str or "$(" in attr.text:
            return
        why = (f"TypeError \"value='{attr.text}' is not an instance of <class "
               f"'{want.__name__}'>\": launch_yaml does not convert a quoted value")
        help_ = f"write it without quotes: value: {attr.text}, or drop type: {ident}"
    elif kind is tuple or not issubclass(kind, want):
        why = (f"TypeError \"Attribute 'value' of Entity 'param' expected to be of type "
               f"'<class '{want.__name__}'>', got '<class '{_PY_TYPE.get(kind, 'str')}'>'\"")
        help_ = (f'quote it: value: "{attr.text}"' if want is str else
                 f"write it as a float: value: {_as_float(attr.text)}" if want is float and
                 kind is int else f"write a {want.__name__}, or drop type: {ident}")
    else:
        return
    yield Diagnostic(
        "L010", attr.value_span, f'parameter "{name}" is given {shown} with type: {ident}; '
        f"launch fails with {why}", help_, key=f"param:{name}:type:{ident}")


def _list_text(attr: Attr) -> str:
    return "[" + ", ".join(f'"{i.text}"' if i.is_str else "[...]" if i.items else i.text
                           for i in attr.items) + "]"


def _shown(attr: Attr, kind: type) -> str:
    if kind is tuple:
        return "a list"
    if kind is type(None):
        return "null"
    return f'"{attr.text}"' if kind is str else f"{_YAML_KIND[kind]} ({attr.text})"


def _as_float(text: str) -> str:
    try:
        return repr(float(text))
    except ValueError:
        return "2.0"


def _type_error(attr: Attr, tag: str, name: str, kind: type, want: type, help_: str
                ) -> Diagnostic:
    got = _PY_TYPE.get(kind, "str")
    return _attr_diag(
        attr, f'key "{name}" of "{tag}" is {_shown(attr, kind)} but launch reads a '
        f"{want.__name__} here; it fails with TypeError \"Attribute '{name}' of Entity '{tag}' "
        f"expected to be of type '<class '{want.__name__}'>', got '<class '{got}'>'\"",
        help_, f"{tag}:{name}:{got}")


def _yaml_boolean_help(text: str, name: str) -> str:
    """The YAML boolean a string given to a boolean key means (``scoped: "true"`` ->
    ``scoped: true``): the help must not turn the key off when the text meant on."""
    meant = text.strip().lower()
    if "$(" not in text and meant in ("true", "yes", "on", "1"):
        return f'write a YAML boolean: {name}: true (the same here, but a quoted "false" is on too)'
    return f"write a YAML boolean: {name}: false" if meant in ("false", "no", "off", "0") \
        else f"write a YAML boolean: {name}: true or {name}: false"


def _truthy(attr: Attr, tag: str, name: str, help_: str) -> Diagnostic:
    subst = "$(" in attr.text
    why = ("substitutions are not evaluated here and the text is used as is"
           if subst else "launch uses the text as is")
    return _attr_diag(
        attr, f'"{name}" of "{tag}" is the string "{attr.text}": {why}, and any non-empty '
        f"string is true, so {name} is always on", help_, f"{tag}:{name}:truthy")


def _attr_diag(attr: Attr, message: str, help_: str, key: str) -> Diagnostic:
    return Diagnostic("L010", attr.value_span, message, help_, key=key)


def _xml_number(text: str, want: type) -> bool:
    try:
        want(text)
    except ValueError:
        return False
    return True


def _on_exit(attr: Attr, tag: str, fmt: str) -> Iterator[Diagnostic]:
    """``on_exit`` of a process: ``ExecuteProcess.parse`` compares the raw text with "shutdown"
    (no substitution) and raises for anything else."""
    if attr.text != "shutdown":
        example = "on_exit: shutdown" if fmt == "yaml" else 'on_exit="shutdown"'
        yield _attr_diag(
            attr, f'"on_exit" of "{tag}" is "{attr.text}"; launch accepts only "shutdown" there and '
            f"fails with ValueError \"Attribute on_exit of Entity node expected to be shutdown but "
            f"got `{attr.text}`\"",
            f"write {example}, or start what should follow the process from a Python launch "
            "file (OnProcessExit)", f"{tag}:on_exit")


def _xml_types(el: Element) -> Iterator[Diagnostic]:
    tag = el.tag
    for name, attr in el.attrs.items():
        text = attr.text
        if name == "on_exit":
            yield from _on_exit(attr, tag, "xml")
        elif name in _FLOAT.get(tag, ()) and name != "period":
            if not _xml_number(text, float):
                what = "a substitution" if "$(" in text else "not a number"
                yield _attr_diag(
                    attr, f'attribute "{name}" of "{tag}" is "{text}", {what}: launch does not '
                    f"substitute it and fails with TypeError: '<' not supported between "
                    "instances of 'str' and 'float'",
                    f'write a literal number, e.g. {name}="2.0"', f"{tag}:{name}:str")
            elif float(text) < 0.0:
                yield _attr_diag(
                    attr, f'attribute "{name}" of "{tag}" is {text}; launch fails with '
                    f"ValueError: expected to be a non-negative value",
                    'use 0.0 or more', f"{tag}:{name}:negative")
        elif name in _INT.get(tag, ()) and not _xml_number(text, int):
            yield _attr_diag(
                attr, f'attribute "{name}" of "{tag}" is "{text}", not an integer: launch keeps '
                "the text and fails with TypeError when the process exits and is respawned",
                f'write a literal integer, e.g. {name}="3"', f"{tag}:{name}:str")
        elif name in _BOOL.get(tag, ()):
            value = _xml_bool(text)
            if value == "str":
                yield _truthy(attr, tag, name, f'write {name}="true" or {name}="false"')
            elif value == "other":
                yield _attr_diag(
                    attr, f'attribute "{name}" of "{tag}" is "{text}", not a boolean; launch '
                    f"fails with TypeError \"Attribute '{name}' of Entity '{tag}' expected to be "
                    "of type '<class 'bool'>'\"", f'write {name}="true" or {name}="false"',
                    f"{tag}:{name}:other")


def _xml_bool(text: str) -> str:
    """How ``coerce_to_type(text, bool, can_be_str=True)`` ends: "bool", "str" (kept as text) or
    "other" (a number or list: ValueError). "0"/"1" are left alone: newer launch reads them as
    booleans, humble rejects them."""
    if text.strip() in ("0", "1", ""):
        return "bool"
    from physai_lint.params.typing import pyyaml_type

    value = pyyaml_type(text)
    if isinstance(value, bool):
        return "bool"
    if isinstance(value, str):
        return "str"
    return "other"
