"""Accepted XML tags / YAML keys, their attributes, children and parents (SEMANTICS §5).

``unknown_markup`` is a pure function over ``MarkupFacts`` for the unknown-attribute rule (L002):
real launch rejects unknown attributes, keys and nested tags (``assert_entity_completely_parsed``).
"""
from __future__ import annotations

import difflib
from collections.abc import Callable
from dataclasses import dataclass

from physai_lint.model.launch import MarkupFacts
from physai_lint.model.pickling import fast_pickle_module
from physai_lint.model.span import Span


@dataclass(frozen=True, slots=True)
class TagSpec:
    attributes: frozenset[str]
    children: frozenset[str]
    parents: frozenset[str] | None = None  # None: anywhere an action may appear
    action: bool = True


_COND = frozenset({"if", "unless"})
_PROCESS = frozenset({
    "cwd", "name", "launch-prefix", "output", "shell", "emulate_tty", "sigterm_timeout",
    "sigkill_timeout", "respawn", "respawn_delay", "respawn_max_retries", "on_exit",
})
_NODE_ATTRS = (_PROCESS - {"name"}) | {"pkg", "exec", "name", "namespace", "exec_name", "args",
                                       "ros_args", "node-name"}
ACTION_TAGS = frozenset({
    "arg", "let", "group", "include", "executable", "node", "node_container",
    "load_composable_node", "push-ros-namespace", "push_ros_namespace", "set_remap",
    "set_parameter", "set_parameters_from_file", "set_use_sim_time", "set_ros_log_dir", "timer",
    "ros_timer", "set_env", "unset_env", "append_env", "reset_env", "reset", "log", "shutdown",
})
_ACTION_PARENTS = frozenset({"launch", "group", "timer", "ros_timer"})


def _spec(attrs: set[str] | frozenset[str], children: set[str] | frozenset[str] = frozenset(),
          parents: set[str] | None = None, action: bool = True) -> TagSpec:
    full = frozenset(attrs) | (_COND if action else frozenset())
    return TagSpec(full, frozenset(children), frozenset(parents) if parents else None, action)


ACCEPTED: dict[str, TagSpec] = {
    # Parser.parse_description reads "deprecated" and never asks the root whether all was read:
    # any other attribute of the root is ignored, not refused (see unknown_markup)
    "launch": _spec({"version", "deprecated"}, ACTION_TAGS, action=False),
    "arg": _spec({"name", "default", "description"}, {"choice"}),
    "choice": _spec({"value"}, parents={"arg"}, action=False),
    "let": _spec({"name", "value"}),
    "group": _spec({"scoped", "forwarding"}, ACTION_TAGS | {"keep"}),
    "keep": _spec({"name", "value"}, parents={"group", "reset"}, action=False),
    "include": _spec({"file"}, {"arg"}),
    "executable": _spec(_PROCESS | {"cmd"}, {"env"}),
    "env": _spec({"name", "value"}, parents={"executable", "node", "node_container"},
                 action=False),
    "node": _spec(_NODE_ATTRS, {"param", "remap", "env"}),
    "node_container": _spec(_NODE_ATTRS, {"param", "remap", "env", "composable_node"}),
    "param": _spec({"name", "value", "type", "value-sep", "from", "allow_substs"}, {"param"},
                   parents={"node", "node_container", "composable_node", "param"}, action=False),
    "remap": _spec({"from", "to"}, parents={"node", "node_container", "composable_node"},
                   action=False),
    "composable_node": TagSpec(frozenset({"pkg", "plugin", "name", "namespace", "if", "unless"}),
                               frozenset({"param", "remap", "extra_arg"}),
                               frozenset({"node_container", "load_composable_node"}), False),
    "extra_arg": _spec({"name", "value"}, parents={"composable_node"}, action=False),
    "load_composable_node": _spec({"target"}, {"composable_node"}),
    "push-ros-namespace": _spec({"namespace"}),
    "push_ros_namespace": _spec({"namespace"}),
    "set_remap": _spec({"from", "to"}),
    "set_parameter": _spec({"name", "value"}),
    "set_parameters_from_file": _spec({"filename"}),
    "set_use_sim_time": _spec({"value"}),
    "set_ros_log_dir": _spec({"new_log_dir"}),
    "timer": _spec({"period", "cancel_on_shutdown"}, ACTION_TAGS),
    "ros_timer": _spec({"period"}, ACTION_TAGS),
    "set_env": _spec({"name", "value"}),
    "unset_env": _spec({"name"}),
    "append_env": _spec({"name", "value", "prepend", "separator"}),
    "reset_env": _spec(set()),
    "reset": _spec(set(), {"keep"}),
    "log": _spec({"message"}),
    "shutdown": _spec({"reason"}),
}
# include's <arg> children are (name, value), not DeclareLaunchArgument attributes
_INCLUDE_ARG = _spec({"name", "value"}, action=False)
# Accepted attributes by schema name ("include/arg" for an include's <arg>), for L009/L010.
ACCEPTED_BY_SCHEMA: dict[str, frozenset[str]] = {
    **{tag: spec.attributes for tag, spec in ACCEPTED.items()},
    "include/arg": _INCLUDE_ARG.attributes}

# Unknown attributes that stand for an accepted one: the Python keyword or the ROS 1 spelling.
_PY_KEYWORDS = {"executable": "exec", "package": "pkg", "node_executable": "exec",
                "node_name": "name", "node_namespace": "namespace", "arguments": "args"}
ALIASES: dict[tuple[str, str], str] = {
    **{(t, k): v for t in ("node", "node_container") for k, v in _PY_KEYWORDS.items()},
    ("node", "type"): "exec", ("node", "ns"): "namespace", ("node_container", "ns"): "namespace",
    ("composable_node", "package"): "pkg", ("arg", "default_value"): "default",
    ("include", "filename"): "file", ("executable", "command"): "cmd",
}
# Attributes accepted by the parser but rejected right after (SEMANTICS §5, e19) or ROS 1 habits.
_HINTS: dict[tuple[str, str], str] = {
    **{k: f'use "{v}" ("{k[1]}" is the keyword of the Python action)'
       for k, v in ALIASES.items() if k[1] not in ("type", "ns")},
    ("node", "node-name"): 'use "name"; "node-name" is accepted by the parser but fails later',
    ("node", "ns"): 'ROS 2 uses "namespace" (ROS 1 "ns")',
    ("node", "type"): 'ROS 2 uses "exec" (ROS 1 "type")',
    ("group", "ns"): 'ROS 2 groups take no namespace: put <push-ros-namespace namespace="..."/> '
                     'first inside the group',
    ("include", "ns"): "wrap the include in a <group> with a <push-ros-namespace>",
}


# Process attributes (executable, node, node_container) that ``ExecuteProcess.parse`` reads only
# from a later distro on: launch iron added sigterm_timeout/sigkill_timeout (#667), emulate_tty
# (#669) and on_exit (#751, backported as #764), jazzy respawn_max_retries; humble's parse reads
# none of them, so its ``assert_entity_completely_parsed`` rejects them.
NEWER_PROCESS_ATTRIBUTES: dict[str, str] = {
    "sigterm_timeout": "jazzy", "sigkill_timeout": "jazzy", "emulate_tty": "jazzy",
    "on_exit": "jazzy", "respawn_max_retries": "jazzy",
}
_PROCESS_TAGS = frozenset({"executable", "node", "node_container"})


def suggest(word: str, options: frozenset[str]) -> str | None:
    close = difflib.get_close_matches(word, sorted(options), n=1, cutoff=0.6)
    return close[0] if close else None


def unknown_markup(facts: MarkupFacts, fmt: str = "xml", extension_tags: Callable[[], frozenset[str]] | None = None,
                   distro: str = "rolling") -> list[tuple[Span, str, str | None]]:
    """Unknown tags, attributes/keys and misplaced tags: (span, message, suggestion or help).
    In YAML a key of its parent's given a mapping (``value: {a: 1}``) is wrong-attribute-type's.
    ``extension_tags``: the tags launch extensions of the workspace register (asked for only when
    a tag is unknown); such a tag and what it holds are theirs to judge. ``distro``: process
    attributes newer than it (``NEWER_PROCESS_ATTRIBUTES``) are unknown."""
    from physai_lint.workspace.distro import DISTROS

    rank = DISTROS.index(distro) if distro in DISTROS else len(DISTROS)
    newer = {name: since for name, since in NEWER_PROCESS_ATTRIBUTES.items() if rank < DISTROS.index(since)}
    out: list[tuple[Span, str, str | None]] = []
    extensions: set[str] = set()  # extension tags met: what they hold is theirs to judge
    for tag, parent, attrs, span in facts.elements:
        if parent is not None and parent in extensions:
            continue
        if fmt == "yaml" and parent is not None and parent in ACCEPTED_BY_SCHEMA \
                and tag in ACCEPTED_BY_SCHEMA[parent]:
            continue
        spec = _INCLUDE_ARG if tag == "arg" and parent == "include" else ACCEPTED.get(tag)
        if spec is None and extension_tags is not None and tag in extension_tags():
            extensions.add(tag)
            continue
        if spec is None:
            allowed = ACCEPTED[parent].children if parent in ACCEPTED else ACTION_TAGS
            out.append((span, f'unknown tag "{tag}"', suggest(tag, allowed or ACTION_TAGS)))
            continue
        if parent is not None and parent in ACCEPTED and tag not in ACCEPTED[parent].children \
                and not (tag == "arg" and parent == "include"):
            out.append((span, f'tag "{tag}" is not allowed inside "{parent}"', None))
        elif parent is None and tag != "launch":
            out.append((span, f'unexpected root tag "{tag}"', "launch"))
        if parent is None and tag == "launch":
            continue  # the root's attributes: launch reads "deprecated" and ignores the rest
        for name, name_span in attrs:
            if name in newer and tag in _PROCESS_TAGS:
                out.append((name_span, f'attribute "{name}" on "{tag}" does not exist in {distro} '
                            f"(launch reads it from {newer[name]} on)",
                            f'remove "{name}", or target a newer distro with --distro'))
                continue
            # "<attr>-sep" is launch_xml's (Entity.get_attr of a list); launch_yaml reads no such
            # key, and rejects it as an unexpected key
            sep = name.endswith("-sep") and name[:-4] in spec.attributes
            if sep and fmt == "xml" or name in spec.attributes and not sep and (tag, name) not in _HINTS:
                continue
            names = spec.attributes if fmt == "xml" else frozenset(a for a in spec.attributes if not a.endswith("-sep"))
            hint = (f"give {name[:-4]} as a YAML list instead" if sep else None) or \
                _HINTS.get((tag, name)) or suggest(name, names)
            out.append((name_span, f'unknown attribute "{name}" on "{tag}"', hint))
    return out


fast_pickle_module(globals())  # tuples instead of dataclasses.fields() per object (model/pickling.py)
