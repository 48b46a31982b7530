"""``IncludeLaunchDescription`` as launch executes it (``actions/include_launch_description.py``):
arguments become launch configurations in the *includer's* scope, the required-argument check is
"best effort" over the names passed, and the locals ``current_launch_file_directory``/``_path`` are
set and never restored."""
from __future__ import annotations

import posixpath
from collections.abc import Collection, Iterator
from dataclasses import replace
from typing import TYPE_CHECKING

from physai_lint.model import launch as ir
from physai_lint.model.launch import EVERY_CONFIGURATION
from physai_lint.model.span import Span
from physai_lint.resolve.evaluate import Scope
from physai_lint.resolve.model import IncludeRecord

if TYPE_CHECKING:
    from physai_lint.resolve.instantiate import Instantiator

MAX_INCLUDE_DEPTH = 40


def declared_arguments(actions: tuple[ir.Action, ...], conditional: bool = False
                       ) -> Iterator[tuple[ir.DeclareArgument, bool]]:
    """Every ``DeclareLaunchArgument`` of a description (``get_launch_arguments``), with whether it
    is conditionally included."""
    for a in actions:
        cond = conditional or a.condition is not None
        if isinstance(a, ir.DeclareArgument):
            yield a, cond
        elif isinstance(a, ir.Group):
            yield from declared_arguments(a.actions, cond)
        elif isinstance(a, ir.OpaqueAction):
            yield from declared_arguments(a.actions, True)


def required_missing(actions: tuple[ir.Action, ...], passed: Collection[str]) -> Iterator[ir.DeclareArgument]:
    """The unconditional declarations without a default whose names ``passed`` lacks: what
    ``IncludeLaunchDescription.execute`` raises on ("missing required argument")."""
    for d, conditional in declared_arguments(actions):
        if not conditional and d.default is None and d.name not in passed:
            yield d


def include(inst: Instantiator, a: ir.Include, scope: Scope) -> None:
    fr = inst.frame
    path = inst.ev.eval(a.path, scope)
    args: list[tuple[str, str | None, object]] = []
    # The arguments become SetLaunchConfiguration actions in the includer's scope, run in order
    # before the description is visited, so an argument may read the ones before it.
    for arg in a.arguments or ():
        value = inst.ev.eval(arg.value, scope)
        args.append((arg.name, value, arg.span))
        scope.configs[arg.name] = value
    rec = IncludeRecord(span=a.span, file=fr.file, target=path, target_source=None, status="unknown",
                        arguments=args, declared=None, active=fr.active)  # type: ignore[arg-type]
    inst.new_record(rec)
    if path is None:
        inst.note_opaque((a.span, "include of a file that cannot be known statically"))
        return
    located = inst.packages.locate(path) if inst.packages is not None else None
    if located is None:
        rec.status = "unknown"
        return
    rec.status = located.status
    rec.target_source = located.source
    if located.status != "ok" or located.source is None:
        if located.status == "unknown":
            inst.note_opaque((a.span, f'include of "{path}" outside the workspace'))
        return
    source = located.source
    if source in fr.chain:
        rec.status = "cycle"
        rec.cycle = fr.chain[fr.chain.index(source):] + (source,)
        return
    if len(fr.chain) >= MAX_INCLUDE_DEPTH:
        rec.status = "unparsed"
        inst.note_opaque((a.span, f"include chain deeper than {MAX_INCLUDE_DEPTH} files"))
        return
    lf = inst.loader(source)
    if lf is None:
        rec.status = "unparsed"
        inst.note_opaque((a.span, f'included file "{source}" could not be parsed'))
        return
    passed = {name for name, _, _ in args}
    # Arguments that cannot be known (launch_arguments computed from a file, or forwarded from
    # context.launch_configurations) may pass any name: no required one is known to be missing.
    rec.required_missing = () if a.arguments is None else tuple(sorted({
        d.name for d in required_missing(lf.actions, passed)}))
    if source not in inst.result.files:
        inst.result.files.append(source)
    n_decl, n_reads, n_opaque, n_inc, n_open = (
        len(inst.result.declared_args), len(inst.result.config_reads), len(inst.result.opaque),
        len(inst.result.includes), len(inst.result.open_reads))
    scope.locals["current_launch_file_directory"] = posixpath.dirname(path)
    scope.locals["current_launch_file_path"] = path
    scope.locals["_owner"] = source
    inst.frame = replace(fr, file=source, chain=fr.chain + (source,), passed=frozenset(passed),
                         passed_at=tuple((name, span) for name, _, span in args if isinstance(span, Span)),
                         dir=posixpath.dirname(path), load=inst.next_load())
    try:
        inst.lookups(lf, scope)
        inst._walk(lf.actions, scope)
    finally:
        inst.frame = fr
    if (len(inst.result.opaque) > n_opaque and a.arguments is not None) or len(inst.result.open_reads) > n_open:
        rec.declared = None  # something below is unknown, or may read any configuration
    else:
        names = {d.name for d in inst.result.declared_args[n_decl:]}
        names |= {r.name for r in inst.result.config_reads[n_reads:]}
        # configurations a Python file hands to code the linter cannot follow (a helper module's
        # function given LaunchConfiguration('limited')): that code may read them at launch
        walked = {source} | {r.target_source for r in inst.result.includes[n_inc:]
                             if r.status == "ok" and r.target_source}
        for file in sorted(walked):
            names.update(getattr(getattr(inst.loader(file), "python", None), "escaped", ()))
        rec.declared = None if EVERY_CONFIGURATION in names else tuple(sorted(names))
