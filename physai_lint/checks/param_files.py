"""Parameter files: P101 parameter-file-missing, P102 parameter-file-not-installed,
P103 parameter-file-no-match, P104 parameter-file-structure, P106 mixed-type-array, P115 param-rewrite-no-effect."""
from __future__ import annotations

import os
from collections.abc import Iterator
from dataclasses import replace
from typing import Any

from physai_lint.checks._util import RELATIVE_PATH, all_nodes, once, switched_off_by, where
from physai_lint.checks._util import relpath as _rel
from physai_lint.checks.base import CheckContext, rule
from physai_lint.interfaces.naming import name_note
from physai_lint.model.findings import Diagnostic, Related
from physai_lint.params.typing import yaml_syntax_error
from physai_lint.resolve.model import ResolvedParamFile
from physai_lint.resolve.names import name_rejected

RELATIVE = f"{RELATIVE_PATH}, so it is missing wherever else the launch is started"


@rule("P101", "parameter-file-missing")
def missing(ctx: CheckContext) -> Iterator[Diagnostic]:
    seen: set[object] = set()
    for _, node in all_nodes(ctx):
        for src in node.param_sources:
            if isinstance(src, ResolvedParamFile) and src.status == "missing" and src.span not in seen:
                if switched_off_by(node, src.path):
                    continue
                seen.add(src.span)
                what = ("is empty" if not (src.path or "").strip()
                        else "is a directory" if src.source and os.path.isdir(src.source)
                        else RELATIVE if not (src.path or "").startswith("/") else "does not exist")
                shown = f'parameter file path "{src.path}"' if what != "does not exist" else f'parameter file "{src.path}"'
                yield Diagnostic(
                    "P101", src.span, f"{shown} {what}; {_consequence(src, node)}",
                    help="give the installed path: PathJoinSubstitution([FindPackageShare('<package>'), "
                         "'config', 'x.yaml']) / $(find-pkg-share <package>)/config/x.yaml"
                    if what == RELATIVE else "fix the path (package, folder or file name) or create the file",
                    key=src.path or "")


def _consequence(src: ResolvedParamFile, node: Any) -> str:
    """What launch does with a parameter file that is not there (launch_ros ``Node``)."""
    who = node.fqn or node.executable
    if src.opened_by:
        return f"{src.opened_by} opens it while launch runs and the launch fails with FileNotFoundError"
    if src.origin == "command_line":
        return (f"rcl cannot open it and {who} exits at start-up with \"Couldn't parse params file: "
                f"'--params-file {src.path}'\"")
    if src.origin == "global" and node.kind != "composable_node":
        return (f"SetParametersFromFile hands it to every node after it, and launch fails when it "
                f"starts {who} (AssertionError: Node._perform_substitutions asserts the file exists)")
    return f'launch only warns "Parameter file path is not a file" and starts {who} without it'


@rule("P102", "parameter-file-not-installed")
def not_installed(ctx: CheckContext) -> Iterator[Diagnostic]:
    seen: set[object] = set()
    for _, node in all_nodes(ctx):
        for src in node.param_sources:
            if isinstance(src, ResolvedParamFile) and src.status == "not_installed" and src.span not in seen:
                seen.add(src.span)
                hint = ctx.packages.locate(src.path).install_hint if src.path else None
                yield Diagnostic(
                    "P102", src.span,
                    f'parameter file "{_rel(src.source)}" is in the source tree but is not installed, '
                    f'so "{src.path}" will not exist at run time; {_consequence(src, node)}',
                    help=hint or "install it (CMake install(DIRECTORY ...) or setup.py data_files)",
                    key=src.path or "")


@rule("P103", "parameter-file-no-match")
def no_match(ctx: CheckContext) -> Iterator[Diagnostic]:
    from physai_lint.params.effective import matching_keys
    from physai_lint.params.match import unnamed_component

    loaders: dict[str, list[tuple[Any, Any]]] = {}
    # every node that reads the file, also through a file a substitution derives from it
    # (RewrittenYaml) or under a condition that is false with the default arguments
    readers: dict[str, list[Any]] = {}
    unnamed: list[tuple[Any, Any, str]] = []
    for _, node in all_nodes(ctx):
        for src in node.param_sources:
            if not isinstance(src, ResolvedParamFile) or src.status != "ok":
                continue
            path = src.source if src.source in ctx.param_files else src.derived_from
            if path not in ctx.param_files:
                continue
            if _by_launch_ros(node, src) and unnamed_component(node):
                if node.active is not False:
                    unnamed.append((node, src, path))
                continue  # gets the "/**" entries only, whatever the other keys say
            readers.setdefault(path, []).append((node, src))
            if node.active is not False and src.source == path and not name_rejected(node.name, node.namespace):
                loaders.setdefault(path, []).append((node, src))
    yield from _unnamed_components(ctx, unnamed)
    for path, users in sorted(loaders.items()):
        model = ctx.param_files[path]
        if not model.ok or not model.blocks:
            continue
        if any(_file_name(n, s) is None for n, s in users):
            continue
        keys = {id(n): matching_keys(_file_name(n, s), model, _by_launch_ros(n, s)) for n, s in users}
        if not any(keys.values()):
            yield _whole_file(path, model, users)
        elif all(n.fqn is not None for n, _ in readers[path]):
            yield from _stray_keys(path, model, users, keys, readers[path])
    yield from _rewritten_no_match(ctx, readers)


def _unnamed_components(ctx: CheckContext, unnamed: list[tuple[Any, Any, str]]) -> Iterator[Diagnostic]:
    """A component loaded with no name given a parameter file with no "/**" entry: launch_ros
    sends no node name and ``to_parameters_list`` keeps only the file's "**" entries (with no
    namespace it warns "node name not provided to launch; parameter files will not apply"), so
    it gets nothing from the file, whatever key names it."""
    seen: set[tuple[Any, str]] = set()
    for node, src, path in unnamed:
        model = src.model if src.source != path and src.model is not None else ctx.param_files[path]
        if not model.ok or not model.blocks or model.flat is not None or (src.span, path) in seen:
            continue
        if any(b.key.lstrip("/") == "**" and not b.nested for b in model.blocks):
            continue
        seen.add((src.span, path))
        what = f'"{_rel(path)}"' if model is ctx.param_files[path] else f'the file written from "{_rel(path)}"'
        keys = ", ".join(f'"{k}"' for k in dict.fromkeys(b.key for b in model.blocks))
        default = f' (name="{node.name}")' if node.name else ""
        span = node.spans.get("executable", src.span)
        yield Diagnostic(
            "P103", span,
            f'component "{node.executable}" is loaded without a name, so launch_ros applies only the "/**" '
            f"entries of its parameter files, and {what} has none (its keys: {keys}): the component gets "
            "none of its parameters from it and runs on its defaults",
            help=f"give the ComposableNode a name{default} so that launch_ros applies the entry keyed by it, "
                 'or key the entries "/**:"',
            related=(Related(src.span, "the file is given here"),) if src.span != span else (),
            key=f"{_rel(path)}:unnamed:{node.executable}")


def _rewritten_no_match(ctx: CheckContext, readers: dict[str, list[Any]]) -> Iterator[Diagnostic]:
    """A workspace file that active nodes read only through files a substitution writes from it
    (nav2_common RewrittenYaml: its ``root_key`` nests every key under it), when no written key
    matches any of them: each gets none of its parameters (rcl matches the written keys). A
    file some node reads as it is is the plain check's (``no_match``)."""
    from physai_lint.params.effective import matching_keys

    for path, users in sorted(readers.items()):
        active = [(n, s) for n, s in users if n.active is not False]
        if not active or any(s.source == path or s.model is None or _file_name(n, s) is None for n, s in active):
            continue
        if any(matching_keys(_file_name(n, s), s.model, _by_launch_ros(n, s)) for n, s in active):
            continue
        model = active[0][1].model
        mine = [(n, s) for n, s in active if s.model is model]
        if not model.blocks:
            continue
        roots = {b.key.split("/", 1)[0] for b in model.blocks}
        if len(roots) == 1 and all(b.nested and "/" in b.key for b in model.blocks):
            yield _under_root(path, model, mine, roots.pop())
        else:
            yield _whole_file(path, model, mine, written=True)


def _under_root(path: str, model: Any, users: list[tuple[Any, Any]], root: str) -> Diagnostic:
    """``_whole_file`` for a written file whose keys all sit under one root key (RewrittenYaml's
    ``root_key``) that the loading nodes' namespace does not have."""
    block, (_, src) = _closest_pair(_in_source_order(model.blocks), users)
    fqns = ", ".join(sorted({f'"{n.fqn}"' for n, _ in users}))
    spaces = ", ".join(sorted({f'"{n.namespace}"' for n, _ in users}))
    return Diagnostic(
        "P103", block.key_span,
        f'no node key of the file written from "{_rel(path)}" matches the node(s) that load it ({fqns}): '
        f'its writer (RewrittenYaml\'s root_key "{root}") nests every key under "{root}" ("{block.key}" '
        f"matches /{block.key} only), and the nodes run in {spaces}; the whole file is silently ignored",
        help=(f'give root_key only where the nodes run in namespace "/{root}" (nav2 gives it with '
              "use_namespace:=true), or push that namespace for them"),
        related=(Related(src.span, "loaded here"),),
        key=f"{_rel(path)}:{block.key}")


def _in_source_order(blocks: list[Any]) -> list[Any]:
    """A written file's keys in the order of its source's (the writer may sort them)."""
    return sorted(blocks, key=lambda b: (b.key_span.file, b.key_span.line, b.key_span.col))


def _by_launch_ros(node: Any, src: Any) -> bool:
    """Whether launch_ros reads the file for the node (a component's own parameters: only "/**" and
    its exact name match) rather than rcl (wildcard keys; a container's file a component gets
    through forward_global_arguments)."""
    return bool(node.kind == "composable_node" and src.origin != "forwarded")


def _file_name(node: Any, src: Any) -> str | None:
    """The name the file's keys are matched against for the node (``file_key_name``)."""
    from physai_lint.params.match import file_key_name

    return file_key_name(node, _by_launch_ros(node, src))


def _whole_file(path: str, model: Any, users: list[tuple[Any, Any]], written: bool = False) -> Diagnostic:
    """No key of the file matches any node that loads it (``written``: of the file a substitution
    writes from it, whose keys are shown as written)."""
    from physai_lint.params.match import explain_for, key_help

    block, (node, src) = _closest_pair(_in_source_order(model.blocks) if written else model.blocks, users)
    fqns = ", ".join(sorted({f'"{n.fqn}"' for n, _ in users}))
    what = f'the file written from "{_rel(path)}" (as "{block.key}")' if written else f'"{_rel(path)}"'
    return Diagnostic(
        "P103", block.key_span,
        f'no node key of {what} matches the node(s) that load it ({fqns}): '
        f"{explain_for(block.key, node)}; the whole file is silently ignored"
        f"{name_note(n for n, _ in users)}",
        help=key_help(node, whole=True),
        related=(Related(src.span, "loaded here"),),
        key=f"{_rel(path)}:{block.key}")


def _own(key: str) -> str:
    """The last segment of a node key: the node name it names."""
    return key.rstrip("/").rsplit("/", 1)[-1]


def _closest_pair(blocks: list[Any], users: list[tuple[Any, Any]]) -> tuple[Any, tuple[Any, Any]]:
    """The key and the loading node the message of a whole-file P103 explains: a key named like a
    node (else close to one), else the first of each."""
    from physai_lint.closematch import close_matches

    names = {n.name: (n, s) for n, s in reversed(users) if n.name}
    for block in blocks:
        if _own(block.key) in names:
            return block, names[_own(block.key)]
    for block in blocks:
        hit = next(iter(close_matches(_own(block.key), tuple(sorted(names)), 1, 0.8)), None)
        if hit is not None:
            return block, names[hit]
    return blocks[0], users[0]


def _stray_keys(path: str, model: Any, users: list[tuple[Any, Any]], keys: dict[int, list[Any]],
                readers: list[tuple[Any, Any]]) -> Iterator[Diagnostic]:
    """Keys meant for a node that loads the file but gets none of its own parameters from it: the
    key names it with a typo, or without (or with another) namespace. A key for a node of another
    name is left alone: the file may be shared with nodes that launch files not checked here start.
    ``keys``: the blocks that match each loading node (by ``id``)."""
    from physai_lint.closematch import close_matches
    from physai_lint.params.effective import matching_keys
    from physai_lint.params.match import explain_for, key_help

    matched = {id(b) for n, src in readers
               for b in keys.get(id(n)) or matching_keys(_file_name(n, src), model, _by_launch_ros(n, src))}
    yield from _wildcards_for_components(path, model, users, matched)
    # nodes that load the file and get no key of their own from it (wildcard keys aside)
    unserved: dict[str, tuple[Any, Any]] = {}
    for node, src in users:
        if node.name and not any("*" not in _own(b.key) for b in keys[id(node)]):
            unserved.setdefault(node.name, (node, src))
    if not unserved:
        return
    names = tuple(sorted(unserved))
    for block in model.blocks:
        name = _own(block.key)
        if id(block) in matched or "*" in name or not name:
            continue
        hit = name if name in unserved else next(iter(close_matches(name, names, 1, 0.8)), None)
        if hit is None:
            continue
        node, src = unserved[hit]
        yield Diagnostic(
            "P103", block.key_span,
            f'node key "{block.key}" of "{_rel(path)}" matches none of the nodes that load the file: '
            f"{explain_for(block.key, node)}; the parameters under it are silently ignored"
            f"{name_note((node,))}",
            help=key_help(node, whole=False),
            related=(Related(src.span, f"{where(node)} loads it here"),),
            key=f"{_rel(path)}:{block.key}")


def _wildcards_for_components(path: str, model: Any, users: list[tuple[Any, Any]],
                              matched: set[int]) -> Iterator[Diagnostic]:
    """A wildcard key (other than "/**") that rcl would match to a component loading the file, but
    that no reader matches: launch_ros honours only "/**" and the exact name for a component's own
    parameters (to_parameters_list), so the parameters under it never reach it."""
    from physai_lint.params.match import explain_composable_no_match, key_help, key_matches

    for block in model.blocks:
        if id(block) in matched or "*" not in block.key or block.key.strip("/") == "**":
            continue
        hit = next(((n, src) for n, src in users if _by_launch_ros(n, src)
                    and key_matches(block.key, n.fqn)), None)
        if hit is None:
            continue
        node, src = hit
        yield Diagnostic(
            "P103", block.key_span,
            f'node key "{block.key}" of "{_rel(path)}" matches none of the nodes that load the file: '
            f"{explain_composable_no_match(block.key, node.fqn)}; the parameters under it are "
            "silently ignored",
            help=key_help(node, whole=False),
            related=(Related(src.span, f"{where(node)} loads it here"),),
            key=f"{_rel(path)}:{block.key}")


@rule("P104", "parameter-file-structure")
def structure(ctx: CheckContext) -> Iterator[Diagnostic]:
    components_only = _read_by_components_only(ctx)
    loaded: dict[str, set[bool]] | None = None  # file -> loaded with allow_substs (True), without
    for path in sorted(ctx.param_files):
        if path in components_only:
            continue
        for d in ctx.param_files[path].diagnostics:
            if d.code != "P104":
                continue
            if loaded is None and ("${" in d.message or _templated(d)):
                loaded = {}
                for _, node in all_nodes(ctx):
                    for src in node.param_sources:
                        if isinstance(src, ResolvedParamFile) and src.source:
                            loaded.setdefault(src.source, set()).add(src.allow_substs)
            if _templated(d):
                if loaded is None or False not in loaded.get(path, ()):
                    continue  # loaded with allow_substs only, or by no node: substituted, or a template
                yield replace(d, message=f"{d.message}; a node loads the file without "
                              "ParameterFile(..., allow_substs=True), so rcl reads the substitution as "
                              "written and rejects the whole file for it",
                              help="load it with ParameterFile(path, allow_substs=True) (XML/YAML: "
                                   "<param from=... allow_substs=\"true\"/>), or write the key out")
                continue
            if "${" in d.message and loaded is not None and path not in loaded:
                continue  # "${name}_controller:" in a file no node loads: a generator's template
            yield d


def _read_by_components_only(ctx: CheckContext, flat_only: bool = True) -> set[str]:
    """Files that only composable nodes load (with ``flat_only``, only those with no
    ros__parameters key, ``ParamFileModel.flat``): launch_ros reads them with PyYAML and sends the
    values in the load request (to_parameters_list), so what rcl's parser would reject never
    reaches rcl."""
    wanted = {p for p, m in ctx.param_files.items() if m.flat is not None or not flat_only}
    if not wanted:
        return set()
    kinds: dict[str, set[bool]] = {}
    for _, node in all_nodes(ctx):
        for src in node.param_sources:
            if isinstance(src, ResolvedParamFile) and src.source in wanted:
                kinds.setdefault(src.source, set()).add(_by_launch_ros(node, src))
    return {p for p, k in kinds.items() if k == {True}}


def _launch_array_mix(model: Any, span: Any) -> set[str] | None:
    """The PyYAML types of the array an rcl P106 points into (its item at ``span``)."""
    for block in model.blocks:
        for prm in block.params:
            if prm.item_spans and span in prm.item_spans and isinstance(prm.launch_value, list):
                return {type(x).__name__ for x in prm.launch_value}
    return None


def _templated(d: Diagnostic) -> bool:
    """A problem of a file's raw text at a ``$(...)`` substitution (``/$(var robot)/driver:``): such a
    file is loaded with ``ParameterFile(..., allow_substs=True)``, which substitutes before rcl
    reads it; what the nodes get is checked where they load it."""
    return "$(" in d.message


def _frontend_rejects(ctx: CheckContext, prm: Any) -> bool:
    """Whether an XML launch file's literal list value is one launch_xml's ``Entity.get_attr``
    rejects (``coerce_to_type`` with no type: ``is_instance_of_valid_type`` wants scalars, the
    non-string ones of the first one's type). A substituted value passes ``get_attr`` as text and
    fails later; launch_yaml reads typed YAML instead (``frontends/attributes.py``)."""
    import yaml

    from physai_lint.checks._params import literal_markup_entry
    from physai_lint.frontends.attributes import get_attr_rejects

    if not (getattr(prm.span, "file", "") or "").endswith(".xml"):
        return False
    entry = literal_markup_entry(ctx, prm)
    if entry is None or entry.value.sep is not None:
        return False
    try:
        items = yaml.safe_load(prm.raw)
    except (yaml.YAMLError, RecursionError, ValueError):
        return False
    return isinstance(items, list) and bool(items) and get_attr_rejects([type(x) for x in items])


@rule("P106", "mixed-type-array")
def mixed_array(ctx: CheckContext) -> Iterator[Diagnostic]:
    components_only = None
    for path in sorted(ctx.param_files):
        for d in ctx.param_files[path].diagnostics:
            if d.code != "P106" or _templated(d):
                continue
            if components_only is None:
                components_only = _read_by_components_only(ctx, flat_only=False)
            if path not in components_only:
                yield d
                continue
            # launch_ros normalizes a component's arrays itself (normalize_parameter_dict ->
            # _normalize_parameter_array_value): ints with floats become a double array; any
            # other mix fails evaluate_parameter_dict's uniform-type check
            mix = _launch_array_mix(ctx.param_files[path], d.span)
            if mix is None or mix <= {"int", "float"}:
                continue
            yield Diagnostic(
                "P106", d.span, d.message.split(" (rcl:")[0] + " (only composable nodes load this "
                "file: launch_ros fails loading them with TypeError \"Expected a non-empty sequence, "
                "with items of uniform type. Allowed sequence item types are bool, int, float, "
                'str.")', help="make every element the same type (quote every element of a "
                "string array)", key=d.key)
    seen: set[object] = set()
    for _, node in all_nodes(ctx):
        for src in node.param_sources:
            for prm in getattr(src, "params", ()):
                if prm.typed_by == "yaml" and prm.value is None and prm.raw and prm.raw.strip().startswith("[") \
                        and prm.span not in seen:
                    seen.add(prm.span)
                    problem = yaml_syntax_error(prm.raw)
                    if problem is not None:
                        yield Diagnostic(
                            "P106", prm.span,
                            f'parameter "{prm.name}" value "{prm.raw}" is not valid YAML ({problem}); launch '
                            "reads a substituted parameter value with YAML rules and fails to convert it",
                            help="quote it to pass the text as a string (e.g. \"'[*]'\"), or write a valid YAML list",
                            key=prm.name)
                        continue
                    empty = prm.raw.strip()[1:].strip() == "]"
                    if _frontend_rejects(ctx, prm):
                        yield Diagnostic(
                            "P106", prm.span,
                            f'parameter "{prm.name}" value "{prm.raw}" is a list with items that are not '
                            "scalars of one type; launch fails reading the attribute with TypeError "
                            "\"Attribute 'value' of Entity 'param' expected to be of type 'None'.'...' "
                            "can not be converted to one of those types\"",
                            help="a parameter holds a scalar or a list of scalars of one type: give each "
                                 "mapping's fields as parameters of their own (name.field), or pass the "
                                 "whole text as a string",
                            key=prm.name)
                        continue
                    yield Diagnostic(
                        "P106", prm.span,
                        f'parameter "{prm.name}" value "{prm.raw}" is '
                        + ("an empty list" if empty else "a list with items of different types")
                        + '; launch raises "Expected a non-empty sequence, with items of uniform type"',
                        help=("an empty list has no type for launch to give it: leave the parameter out, "
                              "or give it a value of its type (e.g. [\"\"], [0])" if empty else
                              "make every item the same type (e.g. all floats: 1.0, 2.5)"), key=prm.name)


@rule("P115", "param-rewrite-no-effect")
def rewrite_no_effect(ctx: CheckContext) -> Iterator[Diagnostic]:
    given: set[str] | None = None
    for span, key, source in once(ctx, "unused_rewrites", lambda e: (e[0], e[1])):
        if given is None:
            given = _given_by_launch(ctx)
        if key.rpartition(".")[2] in given:
            continue  # given to a node another way as well (nav2: autostart to the lifecycle manager)
        yield Diagnostic(
            "P115", span,
            f'param_rewrites key "{key}" matches no key of "{_rel(source)}": RewrittenYaml replaces only '
            "keys the file has (and adds dotted paths through ros__parameters), so it writes this value "
            "nowhere and no node gets it",
            help=f'add "{key}:" (any value) under the ros__parameters of the node that needs it in '
                 f'"{_rel(source)}", or give the full path ("<node>.ros__parameters.{key}")',
            key=key)


def _given_by_launch(ctx: CheckContext) -> set[str]:
    """Names of the parameters launch files give some node directly (a dict, ``<param>``,
    ``SetParameter``): a rewrite of such a name that writes nothing repeats a value given anyway."""
    from physai_lint.resolve.model import ResolvedParamDict

    return {rp.name.rpartition(".")[2] for _, node in all_nodes(ctx) for src in node.param_sources
            if isinstance(src, ResolvedParamDict) for rp in src.params}
