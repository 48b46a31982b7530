"""Launch arguments: L101 undefined-launch-configuration, L102 unused-argument,
L103 argument-not-in-choices, L104 missing-required-argument."""
from __future__ import annotations

from collections.abc import Iterator
from typing import Any

from physai_lint.checks._util import relpath, suggestion
from physai_lint.checks.base import CheckContext, rule
from physai_lint.checks.markup import markup_problems
from physai_lint.model.findings import Diagnostic, Related
from physai_lint.model.launch import EVERY_CONFIGURATION


@rule("L101", "undefined-launch-configuration")
def undefined_configuration(ctx: CheckContext) -> Iterator[Diagnostic]:
    seen: set[object] = set()
    for launch in ctx.launches:
        declared = sorted({a.name for a in launch.declared_args})
        # (a read after an include the linter cannot read, or an action it cannot follow, in
        # the same file counts as defined: that may set any configuration, and includes do not
        # scope them; autoware's agnocast_env sets container_package)
        for read in launch.config_reads:
            if read.defined or read.has_default or read.active is False or read.span in seen:
                continue
            # A read in a file whose includer passed this name is fine; resolution saw it defined.
            seen.add(read.span)
            later = next((a for a in launch.declared_args if a.name == read.name), None)
            hint = (f"it is declared at {relpath(later.span.file)}:{later.span.line}, but that declaration "
                    "does not reach this read (it runs later, or in a scope that does not include it)"
                    if later is not None else suggestion(read.name, declared))
            lead = "is read but never declared or set"
            if read.note == "timer period":
                lead = "is not set when the TimerAction performs its period"
                hint = ("TimerAction._wait_to_fire_event performs it once the whole launch description "
                        "has been visited, with the configurations left at the top level: a group or "
                        "include scope that declared or set it has ended by then")
            # a LaunchConfiguration made elsewhere (a Python variable): reported at the condition
            site = read.site if read.site is not None and read.site.file == read.span.file \
                and read.span.file.endswith(".py") and not _within(read.span, read.site) else None
            yield Diagnostic(
                "L101", site or read.span,
                f'launch configuration "{read.name}" {lead}'
                + (f"; {hint}" if hint else "")
                + f'; launch fails with "launch configuration \'{read.name}\' does not exist"',
                help=f'declare it with DeclareLaunchArgument("{read.name}", default_value=...) / '
                     f'<arg name="{read.name}" default="..."/>, or give LaunchConfiguration a default',
                related=(Related(read.span, "the LaunchConfiguration"),) if site is not None else (),
                key=read.name)


def _within(inner: Any, outer: Any) -> bool:
    """``inner`` lies within ``outer`` (same file)."""
    return (outer.line, outer.col) <= (inner.line, inner.col) and \
        (inner.end_line, inner.end_col) <= (outer.end_line, outer.end_col)


# Configurations launch itself reads for every process it executes: ExecuteLocal's 'emulate_tty'
# override (launch/actions/execute_local.py :: __execute_process) and the Executable's default
# prefix (launch/descriptions/executable.py: LaunchConfiguration('launch-prefix', default=''),
# 'launch-prefix-filter').
_READ_BY_EVERY_PROCESS = frozenset({"emulate_tty", "launch-prefix", "launch-prefix-filter"})


@rule("L102", "unused-argument")
def unused_argument(ctx: CheckContext) -> Iterator[Diagnostic]:
    seen: set[object] = set()
    for launch in ctx.launches:
        opaque_files = {s.file for s, _ in launch.opaque}
        # a file including one that cannot be read (missing: L105) may hand it its arguments
        opaque_files |= {i.file for i in launch.includes if i.status not in ("ok", "cycle") and i.active is not False}
        read_names = {r.name for r in launch.config_reads}
        if any(n.kind != "composable_node" and n.active is not False for n in launch.nodes):
            read_names |= _READ_BY_EVERY_PROCESS
        # a file of this launch that reads the whole context.launch_configurations reads them all
        reads_all = any(EVERY_CONFIGURATION in _escaped(ctx, f) for f in launch.files)
        # a parameter file with allow_substs whose path is unknown may read those of the files
        # that lead to it (what a sibling subtree declares it most likely does not)
        open_files = {f for _, chain in launch.open_reads for f in chain}
        for arg in launch.declared_args:
            # one finding per declaration; a helper (add_launch_arg) declares many at one span
            if not arg.name or arg.name in read_names or arg.file in opaque_files or arg.file in open_files \
                    or (arg.span, arg.name) in seen:  # no name: L009 (XML/YAML) reports it
                continue
            if launch.opaque and any(s.file == arg.file for s, _ in launch.opaque):
                continue
            if reads_all or _read_anywhere(ctx, arg.file, arg.name) or arg.name in _escaped(ctx, arg.file):
                continue
            if markup_problems(ctx, arg.file):
                continue  # launch refuses the file (L002): what it does not read is moot
            seen.add((arg.span, arg.name))
            yield Diagnostic(
                "L102", arg.span,
                f'launch argument "{arg.name}" is declared but never read',
                help=f'read it with LaunchConfiguration("{arg.name}") / $(var {arg.name}), '
                     "or remove the declaration",
                key=arg.name)


def _escaped(ctx: CheckContext, file: str) -> tuple[str, ...]:
    """Configurations the Python file hands to code the linter cannot follow, which may read them."""
    facts = getattr(ctx.launch_files.get(file), "python", None)
    return getattr(facts, "escaped", ())


def _read_anywhere(ctx: CheckContext, file: str, name: str) -> bool:
    """A read that resolution did not reach (e.g. only in an event handler of another launch)."""
    for launch in ctx.launches:
        if file in launch.files and any(r.name == name for r in launch.config_reads):
            return True
    return False


@rule("L103", "argument-not-in-choices")
def not_in_choices(ctx: CheckContext) -> Iterator[Diagnostic]:
    seen: set[object] = set()
    for launch in ctx.launches:
        for arg in launch.declared_args:
            if not arg.choices or arg.value is None or arg.value in arg.choices:
                continue
            span = arg.value_span or arg.span
            if (span, arg.value) in seen:
                continue
            seen.add((span, arg.value))
            options = ", ".join(f'"{c}"' for c in arg.choices)
            yield Diagnostic(
                "L103", span,
                f'launch argument "{arg.name}" is "{arg.value}" (from the {arg.value_origin}), '
                f"which is not one of its choices: {options}",
                help=f"use one of {options}, or add the value to the declaration's choices",
                related=(Related(arg.span, "declared here with its choices"),) if arg.value_span else (),
                key=f"{arg.name}={arg.value}")


@rule("L104", "missing-required-argument")
def missing_required(ctx: CheckContext) -> Iterator[Diagnostic]:
    seen: set[object] = set()
    for launch in ctx.launches:
        for inc in launch.includes:
            for name in inc.required_missing:
                if inc.active is False or (inc.span, name) in seen:
                    continue
                seen.add((inc.span, name))
                given = ", ".join(n for n, _, _ in inc.arguments) or "none"
                target = inc.target_source or inc.target or "the included file"
                yield Diagnostic(
                    "L104", inc.span,
                    f'include of "{_short(target)}" does not pass required argument "{name}" '
                    f"(given: {given}); launch fails with \"Included launch description missing "
                    f"required argument '{name}'\"",
                    help=f'pass "{name}" in launch_arguments / <arg name="{name}" value="..."/>, '
                         "or give the declaration a default_value",
                    key=name)
        yield from _entry_missing(ctx, launch, seen)


def _entry_missing(ctx: CheckContext, launch: Any, seen: set[object]) -> Iterator[Diagnostic]:
    """The entry file's unconditional arguments without a default that the run's NAME:=VALUE
    arguments leave out: ``ros2 launch`` includes the entry with them and fails. Only for a run
    that gives arguments (it describes one invocation); without any, a required argument is the
    file's design, to be given by whoever starts it."""
    from physai_lint.resolve.includes import required_missing

    lf = ctx.launch_files.get(launch.entry)
    if not launch.given or lf is None:
        return
    given = ", ".join(launch.given)
    for decl in required_missing(lf.actions, launch.given):
        if (decl.span, decl.name) in seen:
            continue
        seen.add((decl.span, decl.name))
        yield Diagnostic(
            "L104", decl.span,
            f'required argument "{decl.name}" of the launched file is not among the arguments of '
            f"the run (given: {given}); ros2 launch fails with \"Included launch description "
            f"missing required argument '{decl.name}'\"",
            help=f"add {decl.name}:=VALUE to the command line, or give the declaration a default_value",
            key=decl.name)


def _short(path: str) -> str:
    return path.rsplit("/", 1)[-1]


__all__ = ["Related"]
