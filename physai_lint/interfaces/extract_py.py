"""Interfaces from rclpy sources, read with ``ast`` (never imported or run).

Recognised: ``create_publisher(T, 'n', qos)`` (and rclpy.lifecycle's ``create_lifecycle_publisher``),
``create_subscription(T, 'n', cb, qos)``, ``create_service(T, 'n', cb)``, ``create_client(T, 'n')``,
``ActionServer(node, T, 'n', ...)``, ``ActionClient(node, T, 'n')``, ``declare_parameter('n',
default)`` and ``declare_parameters(namespace, [('n', default), ...])``; a class derived from
``rclpy.lifecycle.Node`` makes the node a lifecycle node; ``super().__init__('talker')`` (and the
other ways to make a node) names the node when launch does not. Names come from string literals
or module-level string constants; message types from the file's imports.
"""
from __future__ import annotations

import ast
import posixpath
from collections.abc import Callable
from functools import lru_cache
from typing import Any

from physai_lint.model.span import Span
from physai_lint.pyast import ast_children, ast_nodes

from .model import (
    CODE_CONDITION,
    CODE_REMAP,
    Endpoint,
    NodeInterface,
    NodeSite,
    ParamDecl,
    decide_node_name,
)

MAX_SOURCE = 2_000_000
Reader = Callable[[str], "str | None"]

_CALLS = {
    "create_publisher": ("publishers", 0, 1, "msg_type", "topic"),
    "create_lifecycle_publisher": ("publishers", 0, 1, "msg_type", "topic"),  # rclpy.lifecycle.Node
    "create_subscription": ("subscribers", 0, 1, "msg_type", "topic"),
    "create_service": ("services", 0, 1, "srv_type", "srv_name"),
    "create_client": ("clients", 0, 1, "srv_type", "srv_name"),
    "ActionServer": ("action_servers", 1, 2, "action_type", "action_name"),
    "ActionClient": ("action_clients", 1, 2, "action_type", "action_name"),
    # message_filters.Subscriber(node, msg_type, topic, qos_profile=...) subscribes right away
    "Subscriber": ("subscribers", 1, 2, "msg_type", "topic"),
}

_PARAM_TYPE_NAMES = {
    "BOOL": "bool", "INTEGER": "integer", "DOUBLE": "double", "STRING": "string",
    "BOOL_ARRAY": "bool_array", "INTEGER_ARRAY": "integer_array",
    "DOUBLE_ARRAY": "double_array", "STRING_ARRAY": "string_array", "BYTE_ARRAY": "byte_array",
}


def _from_message_filters(fn: ast.expr, imports: dict[str, str]) -> bool:
    """``message_filters.Subscriber`` / ``mf.Subscriber`` / ``Subscriber`` imported from it."""
    if isinstance(fn, ast.Name):
        return imports.get(fn.id, "").startswith("message_filters.")
    return isinstance(fn, ast.Attribute) and isinstance(fn.value, ast.Name) \
        and imports.get(fn.value.id, fn.value.id).split(".")[0] == "message_filters"


def _imports(nodes: list[ast.AST]) -> dict[str, str]:
    """local name -> dotted origin (``String`` -> ``std_msgs.msg.String``)."""
    out: dict[str, str] = {}
    for node in nodes:
        if isinstance(node, ast.ImportFrom) and node.module:
            for a in node.names:
                out[a.asname or a.name] = f"{node.module}.{a.name}"
        elif isinstance(node, ast.Import):
            for a in node.names:
                out[a.asname or a.name.split(".")[0]] = a.name if a.asname else a.name.split(".")[0]
    return out


def _dotted(node: ast.AST) -> str | None:
    if isinstance(node, ast.Name):
        return node.id
    if isinstance(node, ast.Attribute):
        base = _dotted(node.value)
        return f"{base}.{node.attr}" if base else None
    return None


def _qualified(node: ast.AST | None, imports: dict[str, str]) -> str | None:
    """The dotted name ``node`` spells, its first part through the file's imports."""
    d = _dotted(node) if node is not None else None
    if not d:
        return None
    head, _, rest = d.partition(".")
    return imports.get(head, head) + ("." + rest if rest else "")


def _ros_type(node: ast.AST | None, imports: dict[str, str]) -> str | None:
    full = _qualified(node, imports)
    if full is None:
        return None
    parts = full.split(".")
    if len(parts) >= 3 and parts[-2] in ("msg", "srv", "action"):
        return f"{parts[-3]}/{parts[-2]}/{parts[-1]}"
    return None


def _is_lifecycle_node(base: ast.AST, imports: dict[str, str]) -> bool:
    """Whether a base class is rclpy's lifecycle node (``rclpy.lifecycle.Node``, also exported as
    ``LifecycleNode``; ``rclpy.lifecycle.node.LifecycleNode``)."""
    return _qualified(base, imports) in ("rclpy.lifecycle.Node", "rclpy.lifecycle.LifecycleNode",
                    "rclpy.lifecycle.node.LifecycleNode")


def _const_strings(tree: ast.Module) -> dict[str, str]:
    out: dict[str, str] = {}
    for node in tree.body:
        if isinstance(node, ast.Assign) and isinstance(node.value, ast.Constant) and \
                isinstance(node.value.value, str):
            for t in node.targets:
                if isinstance(t, ast.Name):
                    out[t.id] = node.value.value
        elif isinstance(node, ast.AnnAssign) and isinstance(node.target, ast.Name) and \
                isinstance(node.value, ast.Constant) and isinstance(node.value.value, str):
            out[node.target.id] = node.value.value
    return out


def _str_of(node: ast.AST | None, consts: dict[str, str]) -> str | None:
    if isinstance(node, ast.Constant) and isinstance(node.value, str):
        return node.value
    if isinstance(node, ast.Name) and node.id in consts:
        return consts[node.id]
    return None


def _arg(call: ast.Call, pos: int, kw: str) -> ast.AST | None:
    for k in call.keywords:
        if k.arg == kw:
            return k.value
    if pos < len(call.args) and not any(isinstance(a, ast.Starred) for a in call.args[:pos + 1]):
        return call.args[pos]
    return None


def _span(path: str, node: ast.AST) -> Span:
    line = getattr(node, "lineno", 1)
    col = getattr(node, "col_offset", 0) + 1
    eline = getattr(node, "end_lineno", line) or line
    ecol = (getattr(node, "end_col_offset", col) or col) + 1
    return Span(path, line, col, eline, max(ecol, col + 1) if eline == line else ecol)


def _literal(node: ast.AST | None) -> tuple[bool, Any]:
    if node is None:
        return False, None
    try:
        return True, ast.literal_eval(node)
    except (ValueError, TypeError, SyntaxError, MemoryError, RecursionError):
        return False, None


def _kind_of_value(v: Any) -> str | None:
    from .gpl import value_kind

    return value_kind(v)


def _param_from(name: str, value_node: ast.AST | None, path: str, span: Span) -> ParamDecl:
    ok, value = _literal(value_node)
    ptype = None
    if ok and value is not None:
        ptype = _kind_of_value(value)
        if isinstance(value, list) and value and ptype is None:
            ptype = None
    elif value_node is not None:
        d = _dotted(value_node) or ""
        last = d.rsplit(".", 1)[-1]
        if ".Type." in f".{d}" or d.startswith("Type."):
            ptype = _PARAM_TYPE_NAMES.get(last)
    return ParamDecl(name, ptype, value if ok else None, span=span, source=path,
                     has_default=ok and value is not None)


def extract_py(files: list[tuple[str, str]], read: Reader | None = None) -> NodeInterface:
    """What the sources declare together; ``read`` (path -> text or None) reads the package's
    modules whose classes they construct, for the node those make."""
    iface = NodeInterface(publishers=[], subscribers=[], services=[], clients=[],
                          action_servers=[], action_clients=[], parameters={},
                          parameters_complete=False, source="extracted from Python sources")
    sites: list[NodeSite] = []
    makes: list[tuple[str, str | None, Span | None]] = []
    for path, text in files:
        if len(text) > MAX_SOURCE:
            continue
        try:
            tree = ast.parse(text, filename=path)
        except (SyntaxError, ValueError, RecursionError, MemoryError):
            continue
        try:
            nodes = ast_nodes(tree)
            imports, consts = _extract_one(path, tree, iface, nodes)
            found, made = _node_sites(path, tree, imports, consts, nodes)
            sites.extend(site for site, _ in found)
            makes.extend(made)
            defined = {c.name for c in nodes if isinstance(c, ast.ClassDef)}
            if read is not None:
                sites.extend(_imported_node_sites(path, nodes, {c for c, _, _ in made} - defined, read))
        except RecursionError:
            continue
    decide_node_name(iface, sites, makes)
    return iface


# ---- the node the code makes ----------------------------------------------------------------------
# ``super().__init__('talker')`` in a class derived from a node class, ``Node.__init__(self,
# 'talker')``, ``rclpy.create_node('talker')``, ``Node('talker')``: the name rclpy gives the node
# when the command line does not rename it (``-r __node:=``, which launch adds for ``name=``).

_NODE_CLASSES = frozenset({"rclpy.node.Node", "rclpy.lifecycle.Node", "rclpy.lifecycle.LifecycleNode",
                           "rclpy.lifecycle.node.LifecycleNode"})
_NODE_MAKERS = _NODE_CLASSES | {"rclpy.create_node"}
_NOT_A_SITE = ast.Pass()


def _node_classes(nodes: list[ast.AST], imports: dict[str, str]) -> set[str]:
    """The classes of the file (``nodes``: its syntax tree's) derived from a node class: rclpy's,
    one of the file's own, or an imported one whose name ends in ``Node`` (a package's own base
    class)."""
    classes = [n for n in nodes if isinstance(n, ast.ClassDef)]
    found: set[str] = set()
    grew = True
    while grew:
        grew = False
        for c in classes:
            if c.name not in found and any(_is_node_base(b, imports, found) for b in c.bases):
                found.add(c.name)
                grew = True
    return found


def _is_node_base(base: ast.AST, imports: dict[str, str], own: set[str]) -> bool:
    full = _qualified(base, imports)
    return full is not None and (full in _NODE_CLASSES or full.rsplit(".", 1)[-1] in own
                                 or full.rsplit(".", 1)[-1].endswith("Node"))


def _name_argument(call: ast.Call, in_node_class: bool, imports: dict[str, str],
                   own: set[str]) -> ast.AST | None:
    """The argument naming the node ``call`` makes (None: it names none), or ``_NOT_A_SITE``."""
    fn = call.func
    if isinstance(fn, ast.Attribute) and fn.attr == "__init__":
        if not in_node_class:
            return _NOT_A_SITE
        if isinstance(fn.value, ast.Call) and isinstance(fn.value.func, ast.Name) and fn.value.func.id == "super":
            return _arg(call, 0, "node_name")
        if _is_node_base(fn.value, imports, own):
            return _arg(call, 1, "node_name")
        return _NOT_A_SITE
    if _qualified(fn, imports) in _NODE_MAKERS:
        return _arg(call, 0, "node_name")
    return _NOT_A_SITE


def _node_sites(path: str, tree: ast.Module, imports: dict[str, str], consts: dict[str, str],
                nodes: list[ast.AST]
                ) -> tuple[list[tuple[NodeSite, str | None]], list[tuple[str, str | None, Span | None]]]:
    """The places the file (``nodes``: every node of ``tree``) makes a node, each with the class
    whose code it is in; and each class construction with its first argument's literal (None:
    another argument, or none): ``LifecycleTalker('lc_talker')`` names the node a constructor that
    passes its argument on to ``Node`` makes."""
    own = _node_classes(nodes, imports)
    sites: list[tuple[NodeSite, str | None]] = []
    makes: list[tuple[str, str | None, Span | None]] = []

    # Pre-order, as a recursive walk gives, each node with the node class and the parameters of
    # the function it is in; an explicit stack (recursion through ``ast.iter_child_nodes`` was half
    # of the extraction).
    stack: list[tuple[ast.AST, str | None, frozenset[str]]] = [(tree, None, frozenset())]
    while stack:
        node, cls, params = stack.pop()
        if isinstance(node, ast.ClassDef):
            cls = node.name if node.name in own else None
        elif isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.Lambda)):
            a = node.args
            names = {x.arg for x in (*a.posonlyargs, *a.args, *a.kwonlyargs)}
            names |= {x.arg for x in (a.vararg, a.kwarg) if x is not None}
            params = frozenset(names)
        elif isinstance(node, ast.Call):
            arg = _name_argument(node, cls is not None, imports, own)
            if arg is not _NOT_A_SITE and arg is not None:
                name = _str_of(arg, consts)
                passed = name is None and isinstance(arg, ast.Name) and arg.id in params
                ns = _namespace_of(node, consts)
                if _own_arguments_rename(node):
                    name, passed = None, False  # rcl applies the node's own -r __node:= first
                sites.append(((name, (cls or "") if passed else None, _span(path, arg), ns), cls))
            elif arg is _NOT_A_SITE:
                callee = (_dotted(node.func) or "").rsplit(".", 1)[-1]
                if callee[:1].isupper():
                    makes.append((callee, _str_of(_arg(node, 0, "node_name"), consts), _span(path, node)))
        stack.extend((child, cls, params) for child in reversed(ast_children(node)))
    for node in nodes:  # a remap of the node's own name anywhere (a cli_args list built apart)
        if isinstance(node, ast.Constant) and isinstance(node.value, str) and CODE_REMAP.search(node.value):
            sites.append(((None, None, _span(path, node), ""), None))
    return sites, makes


def _namespace_of(call: ast.Call, consts: dict[str, str]) -> str | None:
    """The namespace a node's construction gives (rclpy's keyword-only ``namespace=``): "" none,
    None when not known statically."""
    value = next((k.value for k in call.keywords if k.arg == "namespace"), None)
    if value is None or isinstance(value, ast.Constant) and value.value is None:
        return ""
    return _str_of(value, consts)


def _own_arguments_rename(call: ast.Call) -> bool:
    """Whether the node's own ``cli_args`` may rename it: not a literal list (computed), or one
    with a ``__node:=``/``__ns:=`` rule."""
    value = next((k.value for k in call.keywords if k.arg == "cli_args"), None)
    if value is None or isinstance(value, ast.Constant) and value.value is None:
        return False
    if not isinstance(value, (ast.List, ast.Tuple)):
        return True
    return any(not isinstance(e, ast.Constant) or isinstance(e.value, str) and CODE_REMAP.search(e.value)
               for e in value.elts)


_MAX_FOLLOWED = 8  # imported classes read per file for the node they make


def _imported_node_sites(path: str, nodes: list[ast.AST], classes: set[str], read: Reader
                         ) -> list[NodeSite]:
    """The places where the imported ``classes`` (those the file constructs) make a node, read
    from the package's own modules they come from (``from my_pkg.talker import Talker``,
    ``from .talker import Talker``): the entry module of a console script often only constructs
    the node class another module defines. A class of another package is not read."""
    out: list[NodeSite] = []
    for cls, module, level in _imports_of(nodes, classes)[:_MAX_FOLLOWED]:
        found = _module_source(path, module, level, read)
        if found is None:
            continue
        bases, sites = _module_sites(*found)
        real = cls[1]
        chain, todo = set(), [real]
        while todo:  # the class and the bases of it the module defines
            c = todo.pop()
            if c in bases and c not in chain:
                chain.add(c)
                todo.extend(bases[c])
        if real not in chain:
            continue
        out.extend(site for site, owner in sites if owner in chain)
    return out


@lru_cache(maxsize=256)
def _module_sites(path: str, text: str) -> tuple[dict[str, list[str]], tuple[tuple[NodeSite, str | None], ...]]:
    """Of a module other entry modules import node classes from: each class's bases (last name),
    and where the module makes a node (``_node_sites``). Read once per process: the executables of
    a package often import from the same module (nav2_simple_commander's examples, 54 KB each)."""
    try:
        tree = ast.parse(text, filename=path)
    except (SyntaxError, ValueError, RecursionError, MemoryError):
        return {}, ()
    try:
        nodes = ast_nodes(tree)
        bases = {c.name: [(_dotted(b) or "").rsplit(".", 1)[-1] for b in c.bases]
                 for c in nodes if isinstance(c, ast.ClassDef)}
        sites, _ = _node_sites(path, tree, _imports(nodes), _const_strings(tree), nodes)
    except RecursionError:
        return {}, ()
    return bases, tuple(sites)


def _imports_of(nodes: list[ast.AST], classes: set[str]) -> list[tuple[tuple[str, str], str, int]]:
    """((local name, name in its module), module, level) of each of ``classes`` imported with
    ``from ... import`` (``nodes``: every node of the file's tree)."""
    out = []
    for node in nodes:
        if isinstance(node, ast.ImportFrom):
            for a in node.names:
                local = a.asname or a.name
                if local in classes:
                    out.append(((local, a.name), node.module or "", node.level))
    return sorted(out)


def _module_source(path: str, module: str, level: int, read: Reader) -> tuple[str, str] | None:
    """The file and text of ``module`` imported from ``path`` (``level`` dots), when it is one of
    the package's own: beside the file, or under one of its three nearest parent folders."""
    parts = [p for p in module.split(".") if p]
    folder = posixpath.dirname(path)
    if level:
        for _ in range(level - 1):
            folder = posixpath.dirname(folder)
        roots = [folder]
    else:
        roots = []
        for _ in range(3):
            folder = posixpath.dirname(folder)
            roots.append(folder)
    for root in roots:
        if not parts:
            candidates = [posixpath.join(root, "__init__.py")]
        else:
            candidates = [posixpath.join(root, *parts) + ".py", posixpath.join(root, *parts, "__init__.py")]
        for candidate in candidates:
            text = read(candidate)
            if text is None or len(text) > MAX_SOURCE:
                continue
            return candidate, text
    return None


def _conditional_ids(nodes: list[ast.AST]) -> set[int]:
    """The ids of the nodes that run only under a condition the code tests: in the branches of an
    ``if`` (statement or expression), a ``match`` case or an ``except`` handler."""
    out: set[int] = set()
    for node in nodes:
        if isinstance(node, (ast.If, ast.IfExp)):
            if isinstance(node.test, ast.Compare) and isinstance(node.test.left, ast.Name) \
                    and node.test.left.id == "__name__":
                continue  # ``if __name__ == '__main__':`` runs: it is the script
            branches: list[Any] = [node.body, node.orelse]
        elif isinstance(node, ast.match_case | ast.ExceptHandler):
            branches = [node.body]
        else:
            continue
        for branch in branches:
            for part in branch if isinstance(branch, list) else [branch]:
                if id(part) not in out:
                    out.update(id(x) for x in ast.walk(part))
    return out


def _is_true(node: ast.AST | None) -> bool:
    return isinstance(node, ast.Constant) and node.value is True


def _read_only_descriptors(nodes: list[ast.AST]) -> set[str]:
    """Names bound to a ``ParameterDescriptor(read_only=True)`` or given ``.read_only = True``."""
    out: set[str] = set()
    for node in nodes:
        if not isinstance(node, ast.Assign):
            continue
        for t in node.targets:
            if isinstance(t, ast.Name) and _descriptor_read_only(node.value, set()):
                out.add(t.id)
            elif isinstance(t, ast.Attribute) and t.attr == "read_only" and _is_true(node.value):
                name = _dotted(t.value)
                if name:
                    out.add(name)
    return out


def _descriptor_read_only(node: ast.AST | None, names: set[str]) -> bool:
    """A descriptor argument that makes the parameter read-only."""
    if isinstance(node, ast.Call) and (_dotted(node.func) or "").endswith("ParameterDescriptor"):
        return any(k.arg == "read_only" and _is_true(k.value) for k in node.keywords)
    name = _dotted(node) if node is not None else None
    return name is not None and name in names


def _extract_one(path: str, tree: ast.Module, iface: NodeInterface, nodes: list[ast.AST]
                 ) -> tuple[dict[str, str], dict[str, str]]:
    """Add what one file (``nodes``: every node of ``tree``) declares to ``iface``; the file's
    imports and string constants."""
    imports = _imports(nodes)
    consts = _const_strings(tree)
    read_only = _read_only_descriptors(nodes)
    conditional = _conditional_ids(nodes)
    params = iface.parameters
    assert params is not None
    for node in nodes:
        if isinstance(node, ast.ClassDef):
            if any(_is_lifecycle_node(b, imports) for b in node.bases):
                iface.lifecycle = True
            continue
        if not isinstance(node, ast.Call):
            continue
        fn = node.func
        fname = fn.attr if isinstance(fn, ast.Attribute) else fn.id if isinstance(fn, ast.Name) \
            else None
        if fname in _CALLS:
            kind, tpos, npos, tkw, nkw = _CALLS[fname]
            if fname == "Subscriber":
                if not _from_message_filters(fn, imports):
                    continue
            elif fname in ("ActionServer", "ActionClient"):
                pass
            elif not isinstance(fn, ast.Attribute):
                continue
            name_node = _arg(node, npos, nkw)
            name = _str_of(name_node, consts)
            if name_node is None:
                continue
            rtype = _ros_type(_arg(node, tpos, tkw), imports)
            if name is None:  # a name, just not one known statically
                iface.unnamed.append((kind, rtype))
                continue
            when = CODE_CONDITION if id(node) in conditional else ()
            getattr(iface, kind).append(Endpoint(name, rtype, _span(path, name_node), when))
        elif fname == "declare_parameter" and isinstance(fn, ast.Attribute):
            name_node = _arg(node, 0, "name")
            name = _str_of(name_node, consts)
            if name is None or name_node is None:
                continue
            decl = params.setdefault(name, _param_from(name, _arg(node, 1, "value"), path,
                                                       _span(path, name_node)))
            if _descriptor_read_only(_arg(node, 2, "descriptor"), read_only):
                decl.read_only = True
        elif fname == "declare_parameters" and isinstance(fn, ast.Attribute):
            ns = _str_of(_arg(node, 0, "namespace"), consts) or ""
            plist = _arg(node, 1, "parameters")
            if not isinstance(plist, (ast.List, ast.Tuple)):
                continue
            for item in plist.elts:
                if not isinstance(item, (ast.Tuple, ast.List)) or not item.elts:
                    continue
                pname = _str_of(item.elts[0], consts)
                if pname is None:
                    continue
                full = f"{ns}.{pname}" if ns else pname
                value_node = item.elts[1] if len(item.elts) > 1 else None
                decl = params.setdefault(full, _param_from(full, value_node, path,
                                                           _span(path, item.elts[0])))
                if len(item.elts) > 2 and _descriptor_read_only(item.elts[2], read_only):
                    decl.read_only = True
    return imports, consts
