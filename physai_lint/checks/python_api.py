"""Python launch API misuse found in the file's syntax: L003 parameters-not-a-list,
L004 substitution-concatenation, L005 undefined-name, L006 missing-generate-launch-description,
L008 wrong-argument-type."""
from __future__ import annotations

from typing import Iterator

from physai_lint.checks.base import CheckContext, rule
from physai_lint.model.findings import Diagnostic

NODE_CLASSES = ("launch_ros.actions.Node", "launch_ros.actions.LifecycleNode",
                "launch_ros.actions.ComposableNodeContainer", "launch_ros.descriptions.ComposableNode",
                "launch_ros.actions.node.Node", "launch_ros.actions.lifecycle_node.LifecycleNode")


@rule("L003", "parameters-not-a-list")
def parameters_not_a_list(ctx: CheckContext) -> Iterator[Diagnostic]:
    for path in sorted(ctx.launch_files):
        facts = ctx.launch_files[path].python
        if facts is None:
            continue
        for call in facts.calls:
            kinds = dict(call.value_kinds)
            kind = kinds.get("parameters")
            if kind not in ("dict", "str", "set") or not any(call.qualname.endswith(c.rsplit(".", 1)[-1])
                                                            for c in NODE_CLASSES):
                continue
            span = dict(call.kwargs).get("parameters", call.span)
            cls = call.qualname.rsplit(".", 1)[-1]
            yield Diagnostic(
                "L003", span,
                f"{cls}(parameters=...) is given a {kind}, not a list; launch_ros raises "
                f"\"TypeError: '{cls}' expected 'parameters' to be one of [<class 'list'>]\"",
                help="wrap it in a list: parameters=[{...}] (dicts and parameter file paths go in the list)",
                key=f"{cls}:parameters")


@rule("L005", "undefined-name")
def undefined_name(ctx: CheckContext) -> Iterator[Diagnostic]:
    for path in sorted(ctx.launch_files):
        facts = ctx.launch_files[path].python
        if facts is None:
            continue
        for fact in facts.undefined_names:
            yield Diagnostic(
                "L005", fact.span,
                f'name "{fact.name}" is used but never imported or defined; loading the file raises NameError',
                help=f'import it (e.g. "from launch_ros.actions import {fact.name}") or define it',
                key=fact.name)


@rule("L006", "missing-generate-launch-description")
def missing_gld(ctx: CheckContext) -> Iterator[Diagnostic]:
    from physai_lint.model.span import Span

    for path in sorted(ctx.launch_files):
        facts = ctx.launch_files[path].python
        if facts is None or facts.has_generate_launch_description or facts.is_launch_test:
            continue
        yield Diagnostic(
            "L006", Span.point(path, 1),
            "the launch file defines no generate_launch_description() function; ros2 launch cannot load it",
            help="define def generate_launch_description(): return LaunchDescription([...])",
            key="generate_launch_description")


@rule("L004", "substitution-concatenation")
def concatenation(ctx: CheckContext) -> Iterator[Diagnostic]:
    how_text = {
        "plus": "joined with + at description time",
        "os.path.join": "passed to os.path.join at description time",
        "f-string": "put into an f-string at description time",
        "format": "formatted with str.format at description time",
        "percent": "formatted with % at description time",
        "str": "converted with str() at description time",
    }
    for path in sorted(ctx.launch_files):
        facts = ctx.launch_files[path].python
        if facts is None:
            continue
        for fact in facts.concatenations:
            yield Diagnostic(
                "L004", fact.span,
                f"substitution {fact.detail} is {how_text.get(fact.how, fact.how)}: it is an object, not "
                "a string, so this raises TypeError or produces its repr",
                help="build the value as a list of parts ([LaunchConfiguration('x'), '.yaml']) or with "
                     "PathJoinSubstitution([...])",
                key=f"{fact.how}:{fact.detail}")


_TEXT_HINT = {"bool": "a string such as 'true' or 'false'", "int": "a string such as '{v}'",
              "float": "a string such as '{v}'"}


@rule("L008", "wrong-argument-type")
def wrong_argument_type(ctx: CheckContext) -> Iterator[Diagnostic]:
    for path in sorted(ctx.launch_files):
        facts = ctx.launch_files[path].python
        if facts is None:
            continue
        for f in facts.wrong_types:
            if f.kind == "text":
                lower = f.value.lower() if f.type == "bool" else f.value
                message = (f"{f.call} is given the {f.type} {f.value}, where launch accepts only a string or "
                           f"substitutions; it raises \"TypeError: '{f.type}' object is not iterable\"")
                help_ = f"write it as {_TEXT_HINT[f.type].format(v=lower)}" if f.type in _TEXT_HINT else \
                    "give a string or a substitution"
            elif f.kind == "pairs":
                message = (f"{f.call} is given a dict ({f.value}): launch iterates it as (name, value) pairs "
                           "and gets only its keys, so the include fails with \"ValueError: too many values "
                           "to unpack (expected 2)\" (a two-letter key silently sets another argument)")
                help_ = "pass launch_arguments={...}.items(), or a list of (name, value) tuples"
            else:
                what = f"a dict ({f.value}), whose keys launch_ros takes as the rules" if f.type == "dict" \
                    else f"the rule {f.value} as a {f.type}"
                message = (f"{f.call} is given {what}; launch_ros accepts only (from, to) tuples and raises "
                           f"\"TypeError: Expected 'remap_rule' to be one of [<class 'tuple'>]\"")
                help_ = ("pass a list of (from, to) tuples, e.g. remappings=[('/in', '/out')] or {...}.items()"
                         if f.type == "dict" else "write the rule as a tuple: ('from', 'to')")
            yield Diagnostic("L008", f.span, message, help=help_, key=f"{f.call}:{f.value}")
