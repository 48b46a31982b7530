"""Includes: L105 include-file-missing, L106 include-undeclared-argument, L107 include-cycle."""
from __future__ import annotations

from collections.abc import Iterator

from physai_lint.checks._util import RELATIVE_PATH, suggestion
from physai_lint.checks._util import relpath as _rel
from physai_lint.checks.base import CheckContext, rule
from physai_lint.model.findings import Diagnostic


@rule("L105", "include-file-missing")
def include_missing(ctx: CheckContext) -> Iterator[Diagnostic]:
    seen: set[object] = set()
    for launch in ctx.launches:
        for inc in launch.includes:
            if inc.status not in ("missing", "not_installed") or inc.span in seen:
                continue
            seen.add(inc.span)
            if inc.status == "missing" and not (inc.target or "/").startswith("/"):
                msg = f'included launch file "{inc.target}" {RELATIVE_PATH}'
                fix = "give the installed path: PathJoinSubstitution([FindPackageShare('<package>'), 'launch', " \
                      "'x.launch.py']) / $(find-pkg-share <package>)/launch/x.launch.xml, or ThisLaunchFileDir()"
            elif inc.status == "missing":
                msg = f'included launch file "{inc.target}" does not exist'
                fix = "fix the path or the package name, or create the file"
            else:
                msg = (f'included launch file "{_rel(inc.target_source)}" exists in the source tree '
                       f'but is not installed (launch looks for "{inc.target}")')
                hint = ctx.packages.locate(inc.target).install_hint if inc.target else None
                fix = hint or "install the launch folder in CMakeLists.txt or setup.py data_files"
            yield Diagnostic("L105", inc.span, msg, help=fix, key=inc.target or "")


# How many of an included file's arguments an L106 message lists (the did-you-mean hint names the
# close ones among all of them).
_LISTED = 12


@rule("L106", "include-undeclared-argument")
def include_undeclared(ctx: CheckContext) -> Iterator[Diagnostic]:
    seen: set[object] = set()
    for launch in ctx.launches:
        for inc in launch.includes:
            if inc.declared is None or inc.status != "ok":
                continue
            target = (inc.target_source or inc.target or "").rsplit("/", 1)[-1]
            for name, _value, span in inc.arguments:
                if name in inc.declared or (span, name) in seen:
                    continue
                seen.add((span, name))
                hint = suggestion(name, inc.declared)
                declared = ", ".join(f'"{d}"' for d in inc.declared[:_LISTED]) or "no arguments"
                if len(inc.declared) > _LISTED:  # Autoware's perception.launch.xml: 400 of them
                    declared += f" and {len(inc.declared) - _LISTED} more"
                yield Diagnostic(
                    "L106", span,  # type: ignore[arg-type]
                    f'argument "{name}" is passed to "{target}", which never declares or reads it '
                    f"(it declares or reads {declared}); the value is silently ignored"
                    + (f"; {hint}" if hint else ""),
                    help="pass an argument the included file declares, or declare this one there",
                    key=f"{target}:{name}")


@rule("L107", "include-cycle")
def include_cycle(ctx: CheckContext) -> Iterator[Diagnostic]:
    seen: set[object] = set()
    for launch in ctx.launches:
        for inc in launch.includes:
            if inc.status != "cycle" or not inc.cycle or inc.span in seen:
                continue
            seen.add(inc.span)
            chain = " -> ".join(f'"{_rel(p)}"' for p in inc.cycle)
            yield Diagnostic(
                "L107", inc.span, f"include cycle: {chain}",
                help="break the cycle: an included file must not include (directly or not) its includer",
                key=chain)
