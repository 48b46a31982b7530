"""Effective parameters per node, computed once per run and shared by the parameter rules."""
from __future__ import annotations

import os
from typing import Any

from physai_lint.checks._util import all_nodes
from physai_lint.checks.base import CheckContext
from physai_lint.resolve.model import NodeInstance


def effective(ctx: CheckContext, node: NodeInstance) -> dict[str, Any]:
    cache = ctx.options.setdefault("_effective", {})
    key = id(node)
    if key not in cache:
        from physai_lint.params.effective import node_parameters

        cache[key] = node_parameters(node, ctx.param_files, ctx.distro)
    return cache[key]  # type: ignore[no-any-return]


def declarations(ctx: CheckContext, node: Any, iface: Any, params: dict[str, Any]) -> Any:
    """A lookup ``name -> declaration`` for one node whose effective parameters are ``params``: the
    interface's own, or the generate_parameter_library ``__map_`` template the name is an instance
    of (the mapped array's value for this node names the instances; its declared default does only
    when every parameter source of the node is known)."""
    decls = (iface.parameters or {}) if iface is not None else {}
    if iface is None or not iface.parameter_patterns:
        return decls.get
    from physai_lint.interfaces.gpl import is_template, mapped_declaration

    templates = {n: d for n, d in decls.items() if is_template(n)}
    complete: list[bool] = []

    def keys_of(array: str) -> list[Any] | None:
        ep = params.get(array)
        if ep is not None:
            return ep.value if ep.certain and isinstance(ep.value, list) else None
        own = decls.get(array)
        if own is None or not isinstance(own.default, list):
            return None
        if not complete:
            complete.append(fully_known(ctx, node, params))
        return own.default if complete[0] else None

    def lookup(name: str) -> Any:
        decl = decls.get(name)
        return decl if decl is not None else mapped_declaration(templates, name, keys_of)

    return lookup


def fully_known(ctx: CheckContext, node: Any, params: dict[str, Any], values: bool = True) -> bool:
    """Every parameter source of the node is statically known, so "unset" really is unset.
    ``values`` False: the names are enough (a parameter whose value is not known still names
    itself)."""
    from physai_lint.resolve.model import ResolvedParamFile, UnknownParams

    if node.fqn is None or (values and any(not ep.certain for ep in params.values())):
        return False
    for src in node.param_sources:
        if isinstance(src, UnknownParams):
            return False
        if isinstance(src, ResolvedParamFile) and src.status != "missing":
            model = src.model if src.model is not None else (
                ctx.param_files.get(src.source or "") or ctx.param_files.get(src.path or ""))
            if model is None or not model.ok:
                return False
        if values and any(getattr(p, "value", 0) is None for p in getattr(src, "params", ())):
            return False
    return True


def interface(ctx: CheckContext, node: NodeInstance) -> Any:
    if ctx.interfaces is None:
        return None
    return ctx.interfaces.get(node.package, node.executable)


def nodes_with_params(ctx: CheckContext) -> Any:
    for launch, node in all_nodes(ctx, include_inactive=False):
        if node.kind != "process":
            yield launch, node


def decl_source(source: str) -> str:
    """A declaration's source for messages: workspace paths relative to the working directory."""
    out = []
    for part in source.split(" + "):
        head, sep, tail = part.rpartition(" ")
        path = tail if tail.startswith("/") else part
        if path.startswith("/"):
            try:
                rel = os.path.relpath(path).replace(os.sep, "/")
            except ValueError:
                rel = path
            part = (head + sep if tail.startswith("/") else "") + rel
        out.append(part)
    return " + ".join(out)


def literal_markup_entry(ctx: CheckContext, prm: Any) -> Any:
    """The ``<param value=...>`` of an XML/YAML launch file that launch parameter ``prm`` comes
    from, when that value has no substitution (launch_xml's ``get_attr`` types it itself, when the
    file is read); else None."""
    from physai_lint.checks._util import ir_objects
    from physai_lint.model.launch import ParamEntry
    from physai_lint.model.values import PSubst, literal_of

    file = getattr(prm.span, "file", "") or ""
    if file not in ctx.launch_files:
        return None
    return next((o for o in ir_objects(ctx, file) if type(o) is ParamEntry and o.span == prm.span
                 and type(o.value) is PSubst and isinstance(literal_of(o.value.value), str)), None)
