"""ROS 2 names: launch_ros namespace helpers and the rmw/rcl validators, mirrored exactly.

Sources: launch_ros ``utilities/namespace_utils.py`` (prefix_namespace, make_namespace_absolute);
rmw ``validate_node_name.c``, ``validate_namespace.c``, ``validate_full_topic_name.c``; rcl
``validate_topic_name.c`` and ``expand_topic_name.c`` (ECOSYSTEM.md §3).
"""
from __future__ import annotations

import re

NODE_NAME_MAX = 255
NAMESPACE_MAX = 245
TOPIC_MAX = 247


def prefix_namespace(base_ns: str | None, ns: str | None) -> str | None:
    """launch_ros ``prefix_namespace``: ``ns`` prefixed with ``base_ns`` when relative."""
    if base_ns is None and ns is None:
        return None
    if ns is None:
        combined = base_ns
    elif not base_ns or ns.startswith("/"):
        combined = ns
    else:
        combined = ("" if base_ns == "/" else base_ns) + "/" + ns
    assert combined is not None
    if combined != "/":
        combined = combined.rstrip("/")
    return combined


def make_namespace_absolute(ns: str | None) -> str | None:
    if ns is None:
        return None
    return ns if ns.startswith("/") else "/" + ns


def join_fqn(namespace: str, name: str) -> str:
    return ("" if namespace == "/" else namespace.rstrip("/")) + "/" + name


def _isalnum(ch: str) -> bool:
    return ch.isascii() and (ch.isalnum() or ch == "_")


# The first character ``_isalnum`` rejects (for ASCII, ``str.isalnum`` is exactly [A-Za-z0-9]): one
# regex search instead of a call per character (a million calls on a large workspace).
_NOT_NAME = re.compile(r"[^A-Za-z0-9_]")
_NOT_FULL_TOPIC = re.compile(r"[^A-Za-z0-9_/]")


def validate_node_name(name: str) -> str | None:
    """rmw_validate_node_name: the reason it is invalid, or None."""
    if not name:
        return "node name must not be empty"
    bad = _NOT_NAME.search(name)
    if bad is not None:
        return f'node name contains "{bad.group()}" at index {bad.start()} (only alphanumerics and "_" are allowed)'
    if name[0].isdigit():
        return "node name must not start with a digit"
    if len(name) > NODE_NAME_MAX:
        return f"node name is {len(name)} characters long (at most {NODE_NAME_MAX})"
    return None


def validate_full_topic_name(name: str, what: str = "topic name") -> str | None:
    """rmw_validate_full_topic_name (without the length check, see callers)."""
    if not name:
        return f"{what} must not be empty"
    if not name.startswith("/"):
        return f"{what} must be absolute (start with \"/\")"
    if name.endswith("/"):
        return f"{what} must not end with \"/\""
    bad = _NOT_FULL_TOPIC.search(name)
    if bad is not None:
        return f'{what} contains "{bad.group()}" at index {bad.start()} (only alphanumerics, "_" and "/" are allowed)'
    if "//" in name:
        return f'{what} must not contain "//"'
    for token in name.split("/"):
        if token and token[0].isdigit():
            return f'{what} token "{token}" must not start with a digit'
    return None


def validate_namespace(ns: str) -> str | None:
    """rmw_validate_namespace."""
    if ns == "/":
        return None
    reason = validate_full_topic_name(ns, "namespace")
    if reason:
        return reason
    if len(ns) > NAMESPACE_MAX:
        return f"namespace is {len(ns)} characters long (at most {NAMESPACE_MAX})"
    return None


# One name part as rcl's remap-rule lexer reads it (rcl/src/rcl/lexer.c, states S9/S10 from a
# letter, S3/S10 from "_"): a "_" must be followed by a letter or digit to go on, so a repeated "_"
# ends the part ("a__b" lexes as "a_" and "_b"; test_lexer.cpp: "a_" from "a__bcd"). "{" and "}"
# are no lexeme at all.
_RULE_TOKEN = re.compile(r"[A-Za-z][A-Za-z0-9]*(?:_[A-Za-z0-9]+)*_?|_[A-Za-z0-9]+(?:_[A-Za-z0-9]+)*_?|_")


def rule_lex_problem(name: str) -> str | None:
    """Why rcl cannot parse ``name`` inside a ``-r`` remap rule (``_rcl_parse_remap_rule``: each part
    between "/" must be one lexer token), for a name that is otherwise valid; None when it can. Names
    launch passes this way: remap rules, and node names and namespaces (``-r __node:=``, ``-r
    __ns:=``, also in a component's load request)."""
    body = name[2:] if name.startswith("~/") else name.lstrip("/") if name.startswith("/") else name
    for part in body.split("/"):
        if not part or _RULE_TOKEN.fullmatch(part):
            continue
        if "__" in part:
            return (f'"{part}" has a repeated "_", where rcl\'s remap-rule lexer ends a name part, so the '
                    "rule does not parse")
        if "{" in part or "}" in part:
            return f'"{part}" holds a substitution ("{{...}}"), which remap rules do not take'
        return f'rcl\'s remap-rule lexer cannot read "{part}"'
    return None


def validate_topic_name(name: str) -> str | None:
    """rcl_validate_topic_name: a name as users write it (relative, ``~``, ``{node}``)."""
    if not name:
        return "topic name must not be empty"
    if name[0].isdigit():
        return "topic name must not start with a digit"
    if name.endswith("/"):
        return 'topic name must not end with "/"'
    depth = 0
    sub_start = -1
    # Only "~", "{", "}" and characters outside [A-Za-z0-9_/] stop the scan below: without them it
    # finds nothing (most names), so skip it.
    for i, ch in enumerate(name if _NOT_FULL_TOPIC.search(name) else ()):
        if ch == "~":
            if i != 0:
                return '"~" is only allowed at the start of a topic name'
            if len(name) > 1 and name[1] != "/":
                return '"~" must be followed by "/"'
            continue
        if ch == "{":
            if depth:
                return "nested \"{\" in topic name"
            depth, sub_start = 1, i
            continue
        if ch == "}":
            if not depth:
                return 'unbalanced "}" in topic name'
            content = name[sub_start + 1 : i]
            if content and content[0].isdigit():
                return f'substitution "{{{content}}}" must not start with a digit'
            depth = 0
            continue
        if ch != "/" and not _isalnum(ch):
            return f'topic name contains "{ch}" at index {i} (only alphanumerics, "_", "/", "~", "{{}}" are allowed)'
        if depth and ch == "/":
            return 'substitution in topic name must not contain "/"'
    if depth:
        return 'unbalanced "{" in topic name'
    for token in name.split("/"):
        if token and token[0].isdigit():
            return f'topic name token "{token}" must not start with a digit'
    return None


_SUBST = re.compile(r"\{([^{}]*)\}")


def expand_topic_name(name: str, node_name: str | None, namespace: str | None) -> str | None:
    """rcl_expand_topic_name: the absolute name, or None when it depends on something unknown."""
    if namespace is None:
        return None
    if "{" in name:
        if node_name is None:
            return None

        def sub(m: re.Match[str]) -> str:
            key = m.group(1)
            if key == "node":
                return node_name or ""
            if key in ("ns", "namespace"):
                return namespace
            raise KeyError(key)

        try:
            name = _SUBST.sub(sub, name)
        except KeyError:
            return None
    if name.startswith("/"):
        return name
    if name.startswith("~"):
        if node_name is None:
            return None
        base = join_fqn(namespace, node_name)
        return base if name == "~" else base + name[1:]
    return join_fqn(namespace, name)


def name_rejected(name: str | None, namespace: str | None) -> bool:
    """Whether launch_ros refuses a node with this known name or absolute namespace before starting
    it (``Node._perform_substitutions``: validate_node_name / validate_namespace raise, and the
    launch ends): the node never exists, so its topics, services and parameter files are moot."""
    return (name is not None and validate_node_name(name) is not None) or \
        (namespace is not None and validate_namespace(namespace) is not None)
