"""Node-key validation of params files (``_validate_name`` in rcl_yaml_param_parser ``parse.c``),
built on the rmw namespace and node-name validators (ECOSYSTEM.md §3)."""
from __future__ import annotations

import string

_ALNUM_ = frozenset(string.ascii_letters + string.digits + "_")
NODE_NAME_MAX = 255
NAMESPACE_MAX = 245


def rmw_node_name_problem(name: str) -> str | None:
    if not name:
        return "node name must not be empty"
    for ch in name:
        if ch not in _ALNUM_:
            return f"node name must not contain characters other than alphanumerics or '_' ({ch!r})"
    if name[0].isdigit():
        return "node name must not start with a number"
    if len(name) > NODE_NAME_MAX:
        return f"node name length should not exceed {NODE_NAME_MAX}"
    return None


def rmw_namespace_problem(ns: str) -> str | None:
    if ns == "/":
        return None
    if not ns:
        return "namespace must not be empty"
    if ns[0] != "/":
        return "namespace must be absolute, it must lead with a '/'"
    if ns.endswith("/"):
        return "namespace must not end with a '/', unless only a '/'"
    for ch in ns:
        if ch != "/" and ch not in _ALNUM_:
            return f"namespace must not contain characters other than alphanumerics, '_', or '/' ({ch!r})"
    if "//" in ns:
        return "namespace must not contain repeated '/'"
    for i, ch in enumerate(ns[:-1]):
        if ch == "/" and ns[i + 1].isdigit():
            return "namespace must not have a token that starts with a number"
    if len(ns) > NAMESPACE_MAX:
        return f"namespace should not exceed {NAMESPACE_MAX} characters"
    return None


def validate_node_key(name: str) -> str | None:
    """``None`` when rcl accepts the node key, else the problem."""
    if name in ("/**", "/*"):
        return None
    sep = name.rfind("/")
    absolute_ns: str | None = None
    if sep < 0:
        node_name = name
    else:
        ns = name[:sep + 1]
        absolute_ns = ns if ns.startswith("/") else "/" + ns
        node_name = name[sep + 1:]
    if absolute_ns is not None:
        i = 0
        nxt = absolute_ns.find("/", i + 1)
        if nxt < 0:
            problem = rmw_namespace_problem(absolute_ns)
            if problem:
                return problem
        else:
            while nxt >= 0:
                piece = absolute_ns[i:nxt]
                if piece == "/":
                    return f"{absolute_ns} contains repeated forward slash"
                if piece not in ("/**", "/*"):
                    problem = rmw_namespace_problem(piece)
                    if problem:
                        return problem
                i = nxt
                nxt = absolute_ns.find("/", i + 1)
    if node_name not in ("*", "**"):
        problem = rmw_node_name_problem(node_name)
        if problem:
            return problem
    return None
