"""The names nodes get from their code when the launch file gives none.

``Node(package='demo', executable='talker')`` starts a node named as ``talker``'s code names it
(``Node("talker")``, ``super().__init__('talker')``): launch adds ``-r __node:=`` only for
``name=`` (launch_ros ``Node._get_node_name`` / ``_perform_substitutions``). A ``ComposableNode``
without ``name`` is loaded with an empty ``node_name``, and rclcpp_components keeps the
constructor's (``ComponentManager::create_node_options``). Parameter files, lifecycle managers,
private topics and duplicate names are all matched against that name, so once the interfaces are
known, each such node takes the name its executable's interface gives (``NodeInterface.node_name``:
the code's one literal name, a bundled schema's, or a declaration's). Nodes whose code's name is
not known stay unnamed, and the rules stay silent on them as before.
"""
from __future__ import annotations

import os
from collections.abc import Iterable
from typing import Any

from physai_lint.resolve.names import join_fqn, make_namespace_absolute

_NAMED_KINDS = frozenset({"node", "lifecycle_node", "composable_node"})


def apply_default_names(launches: Iterable[Any], interfaces: Any) -> None:
    """Name each active node that launch names nothing after its executable's code (in place;
    the same node objects may be listed by several launches, naming them again is a no-op)."""
    if interfaces is None:
        return
    for launch in launches:
        for node in launch.nodes:
            if node.kind not in _NAMED_KINDS or node.active is False or not node.package \
                    or not node.executable or node.name_source is not None:
                continue
            unnamed = node.name is None and not node.name_explicit
            if not unnamed and node.namespace_explicit:
                continue  # launch names it and places it: nothing the code says changes that
            iface = interfaces.get(node.package, node.executable)
            name = getattr(iface, "node_name", None)
            if not name:
                continue
            if not node.namespace_explicit and node.namespace == "/" and iface.node_namespace:
                # launch adds -r __ns:= only for a namespace it is given or has pushed
                # (launch_ros Node._perform_substitutions): the code's own one stands
                node.namespace = make_namespace_absolute(iface.node_namespace)
                if node.name is not None:
                    node.fqn = join_fqn(node.namespace, node.name) if node.namespace else None
            if unnamed:
                node.name = name
                node.fqn = join_fqn(node.namespace, name) if node.namespace else None
                node.name_source = _source(iface)


def _source(iface: Any) -> str:
    span = iface.node_name_span
    if span is None:
        return f"the name its code gives it ({iface.source})"
    try:
        where = os.path.relpath(span.file).replace(os.sep, "/")
    except ValueError:
        where = span.file
    return f"the name its code gives it ({where}:{span.line})"


def default_named(node: Any) -> bool:
    """Whether ``node``'s name is its code's default (``apply_default_names`` gave it)."""
    return node.name is not None and not node.name_explicit and node.name_source is not None


def name_note(nodes: Iterable[Any]) -> str:
    """For a message about ``nodes``: where the name of the first one launch names nothing comes
    from (``; "talker" is the name its code gives it (src/talker.cpp:5): the launch file gives
    none``), or ""."""
    node = next((n for n in nodes if default_named(n)), None)
    if node is None:
        return ""
    return f'; "{node.name}" is {node.name_source}: the launch file gives no name='
