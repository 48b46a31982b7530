"""Node-key validation of params files (``_validate_name`` in rcl_yaml_param_parser ``parse.c``),
built on the rmw namespace and node-name validators (ECOSYSTEM.md §3)."""
from __future__ import annotations

from physai_lint.resolve.names import validate_namespace, validate_node_name

# rcl validates node keys with the same rmw validators the launch side mirrors.
rmw_node_name_problem = validate_node_name
rmw_namespace_problem = validate_namespace


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
