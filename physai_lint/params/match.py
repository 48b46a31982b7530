"""Node-key matching.

Regular nodes: rclcpp ``is_node_name_matched`` (rclpy does the same): add a leading ``/`` when
missing, replace every ``/*`` with ``(/\\w+)`` and regex-full-match the node FQN. Composable nodes:
launch_ros reads the file with PyYAML and honours only ``/**`` and the exact ``ns/name`` key
(leading ``/`` stripped); other wildcards are ignored.
"""
from __future__ import annotations

import re
from functools import lru_cache
from typing import Any


@lru_cache(maxsize=4096)
def _key_regex(key: str) -> "re.Pattern[str] | None":
    if not key.startswith("/"):
        key = "/" + key
    pattern = key.replace("/*", r"(/\w+)")
    try:
        return re.compile(pattern, re.ASCII)
    except re.error:
        return None


def key_matches(key: str, fqn: str) -> bool:
    """Does params-file node key ``key`` apply to the node ``fqn`` (after remapping)?"""
    rx = _key_regex(key)
    if rx is None:
        return False
    try:
        return rx.fullmatch(fqn) is not None
    except (RecursionError, re.error):
        return False


def is_universal_key(key: str) -> bool:
    """Keys that match every node (``/**``, ``**``)."""
    k = key if key.startswith("/") else "/" + key
    return k == "/**"


def composable_key_matches(key: str, fqn: str, nested: bool = False) -> bool:
    """launch_ros ``to_parameters_list``: only ``/**`` (stored as ``**``) and the exact key. Nested
    keys (``robot: {talker: {ros__parameters: ...}}``) are joined with "/", each stripped of its
    leading "/" (``__normalize_parameters_dict``), as rcl joins them: ``robot/talker``."""
    if nested:
        return re.sub("/+", "/", key).strip("/") == fqn.strip("/")
    k = key.lstrip("/")
    return k == "**" or k == fqn.lstrip("/")


def unnamed_component(node: Any) -> bool:
    """A composable node loaded with no name: launch_ros sends an empty ``node_name`` and
    ``to_parameters_list`` applies only the "/**" entries of its parameter files (with no
    namespace it warns "node name not provided to launch; parameter files will not apply"); the
    node takes its constructor's name only once loaded."""
    return node.kind == "composable_node" and not node.name_explicit


def file_key_name(node: Any, by_launch_ros: bool = True) -> str | None:
    """The name the keys of a node's own parameter files are matched against: "" for a component
    launch_ros loads with no name (``by_launch_ros``: its files are read by launch_ros, not by rcl
    through forwarded arguments), which only "/**" entries match; else its full name."""
    return "" if by_launch_ros and unnamed_component(node) else node.fqn


def explain_for(key: str, node: Any) -> str:
    """``explain_no_match`` or, for a composable node, ``explain_composable_no_match``."""
    if unnamed_component(node):
        return (f'the component is loaded without a name, so launch_ros applies only the "/**" entries '
                f'of its parameter files, not "{key}"')
    if node.kind == "composable_node":
        return explain_composable_no_match(key, node.fqn)
    return explain_no_match(key, node.fqn)


def key_help(node: Any, whole: bool) -> str:
    """The help of a P103 finding: the keys that would reach ``node``."""
    what = "the file" if whole else "it"
    if unnamed_component(node):
        return (f'give the ComposableNode a name (name="{node.name}") so that launch_ros applies the '
                f'entries keyed by it, or key {what} "/**:"' if node.name else
                f'give the ComposableNode a name, or key {what} "/**:"')
    if node.kind == "composable_node":  # launch_ros honours "/**" and the exact name only
        return f'key {what} by the component\'s full name, "{node.fqn.lstrip("/")}:", or use "/**:"'
    full = node.fqn if whole else node.fqn.lstrip("/")
    return f'key {what} by the node\'s full name, e.g. "{full}:", or use a wildcard such as "/**/{node.name}:"'


def _split(fqn: str) -> tuple[str, str]:
    ns, _, name = fqn.rpartition("/")
    return (ns or "/"), name


def explain_no_match(key: str, fqn: str) -> str:
    """Why ``key`` does not match ``fqn``, with keys that would."""
    ns, name = _split(fqn)
    k = key if key.startswith("/") else "/" + key
    rel = fqn.lstrip("/")
    suggestions = f"\"{rel}\" or \"/**/{name}\"" if ns != "/" else f"\"{name}\" or \"/**/{name}\""
    if "*" not in key:
        return (f"key \"{key}\" matches {k} only; the node is {fqn} "
                f"(use {suggestions})")
    if k == "/*":
        return (f"key \"{key}\" matches only nodes in the root namespace; the node is {fqn} "
                f"(use \"/**\" or {suggestions})")
    if k.endswith("/*"):
        return (f"key \"{key}\" matches nodes exactly one level below {k[:-2] or '/'}; the node "
                f"is {fqn} (use {suggestions})")
    if k.endswith("/**"):
        return f"key \"{key}\" matches {k[:-3] or '/'} and the nodes below it; the node is {fqn}"
    key_name = k.rsplit("/", 1)[-1]
    if key_name != name:
        return (f"key \"{key}\" is for nodes named \"{key_name}\"; the node is {fqn} "
                f"(named \"{name}\")")
    return f"key \"{key}\" does not match the node {fqn} (use {suggestions})"


def explain_composable_no_match(key: str, fqn: str) -> str:
    if "*" in key and key.lstrip("/") != "**":
        return (f"key \"{key}\" is ignored for composable nodes: launch_ros honours only \"/**\" "
                f"and the exact key \"{fqn.lstrip('/')}\"")
    return (f"key \"{key}\" is not the component's exact name: use \"{fqn}\" or "
            f"\"{fqn.lstrip('/')}\" (composable nodes ignore other wildcards)")
