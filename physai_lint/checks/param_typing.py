"""P112 ambiguous-parameter-typing: a value the node receives with a different type or value than
it was written with (ECOSYSTEM.md §4, SEMANTICS.md §4a/§4b).

The check looks at the value each node finally gets (the effective parameter, typed the way rcl or
launch_ros types it for that node) and at the text it came from, and reports only the traps:

- a leading-zero number (``017`` is octal 15 for rcl, ``0483`` the double 483.0);
- ``y``/``n`` read as booleans;
- ``1_000`` left a string by rcl; ``~``/``null`` left the string "null" by rcl;
- a number-looking text that stays a string (``1e3``, ``.5`` read by PyYAML for a composable node);
- a Python string in a launch dict that rcl re-types when launch_ros writes it to its temporary
  params file (``'0483'`` -> 483.0, ``'y'`` -> true).

Quoted YAML scalars are what the author asked for and are never reported. When the declared type
says the received type is wrong, P105 reports it instead; when the declaration accepts the value
as received (``0483`` for a double), nothing is reported.
"""
from __future__ import annotations

import math
import re
from collections.abc import Iterator
from typing import Any

from physai_lint.checks._params import (
    declarations,
    effective,
    interface,
    literal_markup_entry,
    nodes_with_params,
)
from physai_lint.checks.base import CheckContext, rule
from physai_lint.model.findings import Diagnostic
from physai_lint.model.span import Span
from physai_lint.params.typing import rcl_type_scalar
from physai_lint.resolve.model import NodeInstance, ResolvedParam, ResolvedParamDict

_LEADING_ZERO = re.compile(r"[+-]?0[0-9]+")
_UNDERSCORE_NUMBER = re.compile(r"[+-]?[0-9][0-9_]*_[0-9_]*(\.[0-9_]*)?")
_LETTER_BOOLS = frozenset({"y", "Y", "n", "N"})
_NULLS = frozenset({"~", "null", "Null", "NULL"})


def _fmt(value: Any) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, str):
        return f'the string "{value}"'
    return repr(value)


def _kind_name(kind: str | None) -> str:
    return {"integer": "an integer", "double": "a double", "bool": "a bool",
            "string": "a string"}.get(kind or "", kind or "?")


def _written(node: NodeInstance) -> dict[tuple[Span, str], tuple[str, bool, str]]:
    """(value span, parameter name) -> (text as written, quoted/string literal, where) for the
    node's launch parameters; they take precedence over the parameter files' values
    (``_file_written``). The name is part of the key: the entries of a dict comprehension share
    one span."""
    out: dict[tuple[Span, str], tuple[str, bool, str]] = {}
    for src in node.param_sources:
        if isinstance(src, ResolvedParamDict):
            for prm in src.params:
                _add_launch_param(out, prm)
    return out


def _file_written(ctx: CheckContext) -> dict[Span, tuple[str, bool, str]]:
    """value span -> written form of every parameter file value (the same for every node: built
    once per run, since rebuilding it per node made this rule quadratic)."""
    out: dict[Span, tuple[str, bool, str]] = {}
    for model in ctx.param_files.values():
        for block in model.blocks:
            for fp in block.params:
                if not isinstance(fp.value, list):
                    out.setdefault(fp.value_span, (fp.raw, fp.quoted, "file"))
    return out


def _add_launch_param(out: dict[tuple[Span, str], tuple[str, bool, str]], prm: ResolvedParam) -> None:
    if prm.typed_by in ("yaml", "rcl") and prm.raw is not None:
        out[(prm.span, prm.name)] = (prm.raw.strip(), False, "launch")
    elif prm.typed_by == "python" and isinstance(prm.value, str):
        out[(prm.span, prm.name)] = (prm.value, True, "python")


def _problem(text: str, quoted: bool, origin: str, kind: str | None, value: Any,
             decl_type: str | None) -> tuple[str, str] | None:
    """(what happened, what to write instead) when the received value is a trap. A declared type
    that the received value does not have is P105's; only an octal integer for a declared integer
    is reported here, because the type is right and the number is not."""
    if quoted and origin != "python":
        return None
    if _LEADING_ZERO.fullmatch(text) and decl_type in (None, "integer") and kind == "integer":
        decimal = int(text, 10)
        if value == decimal:
            return None
        return (f'rcl reads "{text}" as an octal integer: the node gets {value}, not {decimal}',
                f'write {decimal} for the number, or "{text}" (quoted) for a string')
    if decl_type is not None or kind is None:
        return None
    if origin == "python":
        # the author wrote a Python str; rcl re-typed the text launch_ros dumped for it
        if kind == "string":
            return None
        return ((f"the Python string '{text}' reaches the node as {_fmt(value)}: launch_ros "
                 f"writes it unquoted to its temporary params file and rcl reads it as "
                 f"{_kind_name(kind)}"),
                ("give the value the type you mean: a number for the number; for the text, a "
                 f'declared string parameter or a params file with "{text}" quoted'))
    return _plain_problem(text, kind, value)


def _plain_problem(text: str, kind: str, value: Any) -> tuple[str, str] | None:
    if _LEADING_ZERO.fullmatch(text):
        decimal = int(text, 10)
        if kind == "double":
            return ((f'rcl reads "{text}" as the double {value} (an 8 or 9 makes it no valid '
                     "octal integer)"),
                    f'write "{text}" (quoted) for a string such as a serial number, or {decimal}')
        if kind == "string":
            return ((f'"{text}" stays a string here but is a number for rcl '
                     f"({_kind_name(rcl_type_scalar(text)[0])})"),
                    f'quote it ("{text}") if it is a string, or write {decimal}')
        return None
    if text in _LETTER_BOOLS and kind == "bool":
        return (f'rcl reads "{text}" as the bool {_fmt(value)} (YAML 1.1 boolean), not as a letter',
                f'quote it ("{text}") for the letter, or write {"true" if value else "false"}')
    if kind != "string":
        return None
    if text in _NULLS:
        return ((f'"{text}" is YAML null, which parameters do not have: rcl hands the node the '
                 f'string "{text}"'),
                'remove the parameter to keep its default, or give a value ("" for an empty string)')
    if _UNDERSCORE_NUMBER.fullmatch(text):
        return (f'rcl reads "{text}" as a string: digit separators are YAML 1.1 only',
                f"write {text.replace('_', '')}")
    if rcl_type_scalar(text)[0] == "double":
        return ((f'"{text}" reaches the node as a string: PyYAML (YAML 1.1) does not read it as a '
                 "number, although rcl would"),
                f"write a plain decimal float such as {_decimal_hint(text)}")
    return None


def _decimal_hint(text: str) -> str:
    kind, value = rcl_type_scalar(text)
    if kind == "double" and math.isfinite(value):
        return f"{value!r}" if "e" not in f"{value!r}" else f"{value:.1f}"
    return "1000.0"


@rule("P112", "ambiguous-parameter-typing")
def ambiguous_typing(ctx: CheckContext) -> Iterator[Diagnostic]:
    seen: set[object] = set()
    file_written: dict[Span, tuple[str, bool, str]] | None = None
    for _, node in nodes_with_params(ctx):
        params = effective(ctx, node)
        if not params:
            continue
        if file_written is None:  # only runs that launch a node with parameters need it
            file_written = _file_written(ctx)
        written = _written(node)
        declared = declarations(ctx, node, interface(ctx, node), params)
        yield from _launch_nulls(node, seen)
        for name, ep in sorted(params.items()):
            how = None if ep.origin is None else written.get((ep.origin, name)) or file_written.get(ep.origin)
            if how is None or (ep.origin, name) in seen:
                continue
            text, quoted, origin = how
            decl = declared(name)
            decl_type = None if decl is None or decl.dynamic_type else decl.type
            found = _problem(text, quoted, origin, ep.kind, ep.value, decl_type)
            if found is None:
                continue
            seen.add((ep.origin, name))
            what, instead = found
            yield Diagnostic(
                "P112", ep.origin,
                f'parameter "{name}" of {node.fqn or node.executable}: {what}',
                help=instead, key=f"{node.fqn}:{name}")


def _launch_nulls(node: NodeInstance, seen: set[object]) -> Iterator[Diagnostic]:
    """``<param value="null">``/``~``: PyYAML makes it None, a type no parameter has."""
    for src in node.param_sources:
        if not isinstance(src, ResolvedParamDict):
            continue
        for prm in src.params:
            if prm.typed_by != "yaml" or prm.raw is None or prm.raw.strip() not in _NULLS:
                continue
            if (prm.span, prm.name) in seen:
                continue
            seen.add((prm.span, prm.name))
            yield Diagnostic(
                "P112", prm.span,
                f'parameter "{prm.name}" of {node.fqn or node.executable}: value "{prm.raw}" is YAML '
                "null for launch (PyYAML), a type no parameter has; launch refuses to start the node",
                help='remove the parameter to keep its default, or quote the text ("\'null\'")',
                key=f"{node.fqn}:{prm.name}")


# ---- P113: a substituted value launch cannot type ----------------------------------------------

def _yaml_outcome(text: str) -> tuple[str, str] | None:
    """("error", the YAML problem) or ("mapping", "") when ``yaml.safe_load`` cannot make a
    parameter value of ``text``; None when it can (lists are P106's, null P112's) or it is not
    worked out (an alias, a text too long)."""
    from physai_lint.params.typing import pyyaml_type, yaml_syntax_error

    problem = yaml_syntax_error(text)
    if problem == "an alias":
        return None
    if problem is not None:
        return "error", problem
    return ("mapping", "") if isinstance(pyyaml_type(text), dict) else None


def _failure(ctx: CheckContext, prm: ResolvedParam, outcome: tuple[str, str]) -> tuple[str, str] | None:
    """(how launch reads the value, how it then fails) by the frontend ``prm`` comes from; None when
    that frontend keeps the text as it is."""
    file = prm.span.file or ""
    dict_type = outcome[0] == "mapping"
    if not file.endswith((".xml", ".yaml", ".yml")) and not prm.wrapped:
        return "a substituted parameter value is read with YAML rules", (
            "launch_ros fails evaluating it (TypeError \"" +
            ("Allowed value types are bytes, bool, int, float, str, Sequence[...]. Got <class 'dict'>"
             if dict_type else f"Unable to parse the value of parameter {prm.name} as yaml") + '")')
    if not prm.wrapped and literal_markup_entry(ctx, prm) is not None:
        if not dict_type or not file.endswith(".xml"):
            return None  # launch_xml keeps a text YAML cannot read; launch_yaml's values are typed
        return "an XML value without substitutions is typed with YAML rules when the file is read", (
            "launch_xml cannot read the attribute and the launch file fails to load (TypeError "
            f"\"Attribute 'value' of Entity 'param' expected to be of type 'None'.'{prm.raw}' can not be "
            "converted to one of those types\")")
    how = "ParameterValue without a value_type reads its text" if prm.wrapped else \
        "a substituted parameter value is read"
    return f"{how} with YAML rules", (
        f"launch fails evaluating it (ValueError \"Failed to convert '{prm.raw}' using yaml rules: " +
        ("output type is not allowed, got <class 'dict'>" if dict_type else "yaml.safe_load() failed") + '")')


@rule("P113", "invalid-parameter-value")
def invalid_parameter_value(ctx: CheckContext) -> Iterator[Diagnostic]:
    seen: set[object] = set()
    for _, node in nodes_with_params(ctx):
        for src in node.param_sources:
            if not isinstance(src, ResolvedParamDict):
                continue
            for prm in src.params:
                if prm.command is not None and prm.typed_by == "yaml" and (prm.span, prm.name) not in seen:
                    found_cmd = _printed_description(ctx, node, prm)
                    if found_cmd is not None:
                        seen.add((prm.span, prm.name))
                        yield found_cmd
                    continue
                if prm.typed_by != "yaml" or prm.value is not None or not prm.raw or \
                        prm.raw.lstrip().startswith("[") or (prm.span, prm.name) in seen:
                    continue
                outcome = _yaml_outcome(prm.raw)
                found = None if outcome is None else _failure(ctx, prm, outcome)
                if outcome is None or found is None:
                    continue
                seen.add((prm.span, prm.name))
                what = f"is not valid YAML ({outcome[1]})" if outcome[0] == "error" else \
                    "is a YAML mapping (\"key: value\"), which no parameter holds"
                yield Diagnostic(
                    "P113", prm.span,
                    f'parameter "{prm.name}" of {node.fqn or node.executable}: value "{prm.raw}" {what}; '
                    f"{found[0]}, and {found[1]}",
                    help="pass the text as a string: ParameterValue(..., value_type=str) in Python, "
                         "type=\"str\" in XML, type: str in YAML; or quote it inside the value (\"'map: odom'\")",
                    key=f"{node.fqn}:{prm.name}")


def _description_fix(prm: ResolvedParam) -> tuple[str, str]:
    """(what the value lacks, the help) for a command's output launch reads with YAML rules, in
    the words of the frontend it is written in."""
    file = prm.span.file or ""
    if file.endswith(".xml"):
        return 'given without type="str"', 'add type="str" to the <param>: the description is then passed as it is'
    if file.endswith((".yaml", ".yml")):
        return "given without type: str", 'add "type: str" to the param: the description is then passed as it is'
    wrap = f"{{'{prm.name}': ParameterValue(Command([...]), value_type=str)}}"
    if prm.wrapped:
        return "given as ParameterValue without value_type=str", f"add value_type=str: {wrap}"
    return ("not wrapped in ParameterValue(..., value_type=str)",
            f"wrap the command: {wrap} (from launch_ros.parameter_descriptions import ParameterValue)")


def _printed_description(ctx: CheckContext, node: NodeInstance, prm: ResolvedParam) -> Diagnostic | None:
    """P113 for ``{'robot_description': Command(['xacro ', file])}``: the file the command prints
    (a workspace file) holds a line that its output keeps and YAML cannot read as text."""
    from physai_lint.model.findings import Related
    from physai_lint.params.description_yaml import description_breakage, printed_file

    printed = printed_file(prm.command or "")
    locate = getattr(ctx.packages, "locate", None)
    read = getattr(ctx.packages, "read_text", None)
    if printed is None or locate is None or read is None:
        return None
    program, path = printed
    loc = locate(path)
    if loc.status != "ok" or not loc.source:
        return None
    memo = ctx.options.setdefault("_printed_descriptions", {})
    key = (program, loc.source)
    if key not in memo:  # several nodes are given one description: its file is scanned once
        text = read(loc.source)
        memo[key] = None if text is None else description_breakage(program, loc.source, text)
    broken = memo[key]
    if broken is None:
        return None
    kept = "keeps" if program == "xacro" else "prints"
    name = broken.path.rsplit("/", 1)[-1]
    fails = "passes a description cut there, or fails evaluating it" if "comment" in broken.what \
        else "fails evaluating it"
    error = ("ValueError \"Failed to convert '...' using yaml rules: yaml.safe_load() failed\""
             if prm.wrapped or (prm.span.file or "").endswith((".xml", ".yaml", ".yml")) else
             f'TypeError "Unable to parse the value of parameter {prm.name} as yaml"')
    how, instead = _description_fix(prm)
    return Diagnostic(
        "P113", prm.span,
        f'parameter "{prm.name}" of {node.fqn or node.executable} is the output of "{program} {name}", '
        f"{how}, which launch reads with YAML rules; "
        f'{program} {kept} line {broken.line} of {name} ("{broken.snippet}"), where '
        f"{broken.what}: launch {fails} ({error})",
        help=instead,
        related=(Related(Span.point(broken.path, broken.line), f"the line {program} {kept}"),),
        key=f"{node.fqn}:{prm.name}")
