"""The command line: ``physai-lint PATH... [NAME:=VALUE ...] [options]`` and its subcommands.

Start-up is kept light: ``--version`` is answered before typer is imported, and heavy modules
(rich, jsonschema, yaml, the engine) are imported inside the commands that need them. Every
failure is one ``error: ...`` line on stderr and exit code 2; findings at or above ``--fail-on``
give exit code 1.
"""
import os
import sys
from typing import Any, Dict, List, NoReturn, Optional, Sequence, Tuple

SUBCOMMANDS = ("check", "graph", "plan", "params", "rules", "rule")
CHECK_FORMATS = ("text", "json", "sarif", "github", "junit")
GRAPH_FORMATS = ("json", "dot", "mermaid", "html", "text")
PLAN_FORMATS = ("text", "json", "dot", "mermaid")
PARAMS_FORMATS = ("text", "json")
RULES_FORMATS = ("table", "json", "markdown")
DISTROS = ("humble", "jazzy", "kilted", "lyrical", "rolling")
SEVERITIES = ("error", "warning", "note")
# Options that take a value: needed to find the first positional argument before typer runs.
_VALUE_OPTIONS = frozenset(
    "--format --output -o --workspace --distro --interfaces --select --ignore --extend-select --fail-on"
    " --config --baseline --write-baseline --jobs -j --xunit-file --node".split()
)


def main(argv: Optional[Sequence[str]] = None) -> int:
    """Run the command line; returns the exit code (0 clean, 1 findings, 2 errors)."""
    args = list(sys.argv[1:] if argv is None else argv)
    if args[:1] in (["--version"], ["-V"]):
        from physai_lint import __version__

        sys.stdout.write(f"physai-lint {__version__}\n")
        return 0
    try:
        return _run(_route(args))
    except KeyboardInterrupt:
        _error("interrupted")
        return 2


def entry() -> NoReturn:
    """The ``physai-lint`` command (console script and ``python -m physai_lint``): ``main``, then
    leave without tearing the run's objects down.

    Everything the user asked for is written and closed by the time ``main`` returns (reports and
    baselines are written in ``with`` blocks, cache entries are renamed into place, forked helpers
    and any parse pool have ended); what is left is the interpreter freeing millions of objects one by one and a
    final collection: 0.25 s after the Autoware run, 0.6 s after the 1,180-file workspace (7-12% of
    the runs), for nothing. Like mypy's default ``--fast-exit``, flush the standard streams and
    ``os._exit``. ``main`` itself stays a function that returns, for callers in a process that
    lives on."""
    from physai_lint import datastack, gcpolicy

    gcpolicy.ending_process()  # and no collector restored for it: the run's objects go with it
    code = datastack.call(main)  # its frames in one chunk of the frame stack (datastack.py)
    for stream in (sys.stdout, sys.stderr):
        try:
            stream.flush()
        except (OSError, ValueError):  # a closed pipe (`physai-lint ... | head`): nothing to flush to
            pass
    os._exit(code)


def _route(args: List[str]) -> List[str]:
    """``physai-lint PATH...`` means ``physai-lint check PATH...``."""
    i = 0
    while i < len(args):
        tok = args[i]
        if tok == "--":
            break
        if tok.startswith("-") and tok != "-":
            i += 2 if tok in _VALUE_OPTIONS else 1
            continue
        return args if tok in SUBCOMMANDS else ["check", *args]
    if not args:
        return ["--help"]
    if any(a in ("-h", "--help") for a in args):
        return args
    return ["check", *args]


def _error(message: str) -> None:
    sys.stderr.write(f"error: {' '.join(message.split())}\n")


def _run(args: List[str]) -> int:
    from physai_lint import gcpolicy

    # The cyclic collector is tuned for the run (gcpolicy: 12-20% of a large run otherwise).
    with gcpolicy.for_run():
        return _run_command(args)


def _run_command(args: List[str]) -> int:
    from physai_lint.errors import ConfigError, UnloadableLaunch, UsageError

    try:
        import typer

        command = typer.main.get_command(_build_app())
        try:
            rv = command.main(args=args, prog_name="physai-lint", standalone_mode=False)
        except typer.Exit as exc:
            return int(exc.exit_code)
        except typer.Abort:
            _error("aborted")
            return 2
        except typer.TyperException as exc:
            _error(exc.format_message().rstrip(".") + " (see physai-lint --help)")
            return 2
        return rv if isinstance(rv, int) else 0
    except (UsageError, ConfigError) as exc:
        _error(str(exc))
        return 2
    except UnloadableLaunch as exc:
        for line in exc.lines:
            _error(line)
        return 1
    except BrokenPipeError:
        return 2
    except Exception as exc:  # a crash is a bug: one line, never a traceback
        if os.environ.get("PHYSAI_LINT_TRACEBACK"):
            raise
        _error(f"internal error: {type(exc).__name__}: {exc} (please report)")
        return 2


# --------------------------------------------------------------------------- helpers


def _choice(option: str, value: str, allowed: Sequence[str]) -> str:
    from physai_lint.errors import UsageError

    if value not in allowed:
        raise UsageError(f'invalid value "{value}" for {option} (choose from {", ".join(allowed)})')
    return value


def _split_args(args: Optional[List[str]]) -> Tuple[List[str], Dict[str, str]]:
    """Paths and ``NAME:=VALUE`` launch arguments."""
    from physai_lint.errors import UsageError

    paths: List[str] = []
    launch_args: Dict[str, str] = {}
    for arg in args or []:
        if ":=" in arg:
            name, _, value = arg.partition(":=")
            if not name:
                raise UsageError(f'launch argument "{arg}" has no name (expected NAME:=VALUE)')
            launch_args[name] = value
        else:
            paths.append(arg)
    return paths, launch_args


def _existing(paths: List[str]) -> None:
    from physai_lint.errors import UsageError

    for p in paths:
        if not os.path.exists(p):
            raise UsageError(f'path "{p}" does not exist')


def _use_color(stream: Any, to_file: bool) -> bool:
    """Colour on a terminal; never with ``NO_COLOR``; always with ``FORCE_COLOR``."""
    if os.environ.get("NO_COLOR"):
        return False
    if os.environ.get("FORCE_COLOR", "") not in ("", "0"):
        return True
    if to_file or os.environ.get("TERM") == "dumb":
        return False
    isatty = getattr(stream, "isatty", None)
    return bool(isatty and isatty())


def _emit(text: str, output: Optional[str]) -> None:
    if output:
        from physai_lint.errors import UsageError

        try:
            os.makedirs(os.path.dirname(os.path.abspath(output)), exist_ok=True)
            with open(output, "w", encoding="utf-8", newline="\n") as fh:
                fh.write(text)
        except OSError as exc:
            raise UsageError(f'cannot write "{output}": {exc.strerror or exc}') from None
    else:
        sys.stdout.write(text)
        sys.stdout.flush()


class _Common:
    """Command-line values shared by check, graph, plan and params (None: not given).

    A plain class: importing ``dataclasses`` costs ``inspect``, too much for ``--version``."""

    def __init__(
        self,
        workspace: Optional[str] = None,
        distro: Optional[str] = None,
        interfaces: Optional[List[str]] = None,
        select: Optional[List[str]] = None,
        ignore: Optional[List[str]] = None,
        extend_select: Optional[List[str]] = None,
        fail_on: Optional[str] = None,
        config: Optional[str] = None,
        baseline: Optional[str] = None,
        write_baseline: Optional[str] = None,
        jobs: Optional[int] = None,
        cache: bool = True,
        respect_gitignore: Optional[bool] = None,
        strict: bool = False,
    ) -> None:
        self.workspace, self.distro, self.interfaces = workspace, distro, interfaces
        self.select, self.ignore, self.extend_select = select, ignore, extend_select
        self.fail_on, self.config, self.baseline, self.write_baseline = fail_on, config, baseline, write_baseline
        self.jobs, self.cache, self.respect_gitignore, self.strict = jobs, cache, respect_gitignore, strict


def _settings(paths: List[str], launch_args: Dict[str, str], c: _Common) -> Tuple[Any, Dict[str, Any], Any]:
    """Merge the configuration file with the command line: (CheckOptions, extras, catalog).

    The command line wins for single values (``--select`` replaces ``select``); lists that add up
    (``--ignore``, ``--extend-select``, ``--interfaces``) extend the file's.
    """
    from physai_lint.catalog import load_catalog
    from physai_lint.config import load_config, normalise_rule_keys
    from physai_lint.errors import UsageError
    from physai_lint.selection import Selector, split_selectors

    cwd = os.getcwd()
    cfg = load_config(cwd, c.config)
    catalog = load_catalog()
    severity, rule_options = normalise_rule_keys(cfg, catalog)
    select = split_selectors(c.select) if c.select else cfg.select
    ignore = [*cfg.ignore, *split_selectors(c.ignore)]
    extend_select = [*cfg.extend_select, *split_selectors(c.extend_select)]
    Selector(select, ignore, extend_select, cfg.per_file_ignores, catalog)  # validates the selectors
    fail_on = _choice("--fail-on", c.fail_on, SEVERITIES) if c.fail_on else (cfg.fail_on or "error")
    distro = _choice("--distro", c.distro, DISTROS) if c.distro else (cfg.distro or "humble")
    if c.jobs is not None and c.jobs < 1:
        raise UsageError(f"--jobs must be at least 1, got {c.jobs}")
    workspace = os.path.abspath(c.workspace) if c.workspace else cfg.workspace
    if workspace and not os.path.isdir(workspace):
        raise UsageError(f'workspace "{c.workspace or workspace}" is not a directory')
    interfaces = [*cfg.interfaces, *(os.path.abspath(p) for p in c.interfaces or [])]
    _existing([p for p in interfaces])
    baseline = os.path.abspath(c.baseline) if c.baseline else cfg.baseline
    if baseline and not c.write_baseline:
        from physai_lint.baseline import load

        load(baseline)  # a missing or malformed baseline is a usage error, before any work
    values: Dict[str, Any] = {
        "paths": [os.path.abspath(p) for p in paths],
        "launch_args": launch_args,
        "workspace": workspace,
        "distro": distro,
        "interfaces": interfaces,
        "select": select,
        "ignore": ignore,
        "extend_select": extend_select,
        "per_file_ignores": cfg.per_file_ignores,
        "fail_on": fail_on,
        "rule_options": rule_options,
        "baseline": None if c.write_baseline else baseline,
        "write_baseline": os.path.abspath(c.write_baseline) if c.write_baseline else None,
        "jobs": c.jobs,
        "cache": c.cache,
        "respect_gitignore": c.respect_gitignore if c.respect_gitignore is not None else cfg.respect_gitignore is not False,
        "strict": c.strict,
        # Passed only when the engine's CheckOptions has such fields; otherwise applied here.
        "severity": severity,
        "exclude": cfg.exclude,
        "config": cfg.path,
    }
    try:
        from physai_lint.engine import CheckOptions
    except ImportError as exc:
        raise UsageError(f"the check engine is not available: {exc}") from None
    import dataclasses

    names = {f.name for f in dataclasses.fields(CheckOptions)}
    opts = CheckOptions(**{k: v for k, v in values.items() if k in names})
    extras = {k: v for k, v in values.items() if k not in names}
    return opts, extras, catalog


def _post_process(report: Any, extras: Dict[str, Any]) -> Any:
    """Severity overrides and ``exclude`` when the engine does not apply them itself."""
    import dataclasses

    from physai_lint.report import rel
    from physai_lint.selection import path_matches

    severity: Dict[str, str] = extras.get("severity") or {}
    exclude: List[str] = extras.get("exclude") or []
    if not severity and not exclude:
        return report
    findings = [
        dataclasses.replace(f, severity=severity[f.code]) if f.code in severity else f
        for f in report.findings
        if not (exclude and path_matches(exclude, rel(f.span.file, report.cwd)))
    ]
    files = [p for p in report.files if not (exclude and path_matches(exclude, rel(p, report.cwd)))]
    return dataclasses.replace(report, findings=findings, files=files)


def _check(
    args: Optional[List[str]],
    common: _Common,
    fmt: str,
    output: Optional[str],
    exit_zero: bool,
    statistics: bool,
    xunit_file: Optional[str],
    show_source: bool,
    quiet: bool,
) -> int:
    from physai_lint.errors import UsageError

    _choice("--format", fmt, CHECK_FORMATS)
    paths, launch_args = _split_args(args)
    if not paths:
        raise UsageError("no paths given (try: physai-lint .)")
    _existing(paths)
    opts, extras, catalog = _settings(paths, launch_args, common)
    opts.progress = not quiet  # shown only when stderr is a terminal and the run takes over 1 s
    from physai_lint.engine import run_check
    from physai_lint.report import at_least, render

    report = _post_process(run_check(opts), extras)
    _warn_unchecked(report, paths)
    fail_on = opts.fail_on
    text = render(
        fmt,
        report,
        catalog,
        color=_use_color(sys.stdout, bool(output)),
        show_source=show_source,
        statistics=statistics,
        quiet=quiet,
        fail_on=fail_on,
    )
    _emit(text, output)
    if xunit_file:
        _emit(render("junit", report, catalog, fail_on=fail_on), xunit_file)
    if common.write_baseline:
        n = len(report.findings)
        sys.stderr.write(f"physai-lint: wrote {n} finding{'' if n == 1 else 's'} to the baseline {common.write_baseline}\n")
        return 0
    return 0 if exit_zero or not at_least(report.findings, fail_on) else 1


def _warn_unchecked(report: Any, paths: List[str]) -> None:
    """Say on stderr what was not checked, so that "All checks passed! (0 files)" is never all a user
    sees: each named file left out (a ROS 1 launch file), or, like ruff's "No Python files found",
    directories holding nothing to check. Findings and the exit code are not affected."""
    from physai_lint.report import rel

    skipped = getattr(report, "skipped", [])
    for path, reason in skipped:
        sys.stderr.write(f'physai-lint: warning: skipped "{rel(path, report.cwd)}": {reason}\n')
    if not skipped and not report.files and not report.findings and all(os.path.isdir(p) for p in paths):
        where = ", ".join(f'"{p}"' for p in paths)
        sys.stderr.write(f"physai-lint: warning: no launch or parameter file found in {where}\n")


def _api_command(kind: str, args: Optional[List[str]], common: _Common, fmt: str, output: Optional[str], node: Optional[str] = None) -> int:
    from physai_lint.errors import UsageError

    paths, launch_args = _split_args(args)
    if len(paths) != 1:
        raise UsageError(f"{kind} takes exactly one launch file, got {len(paths)}")
    _existing(paths)
    opts, _extras, _catalog = _settings(paths, launch_args, common)
    try:
        from physai_lint import api

        func = getattr(api, kind)
    except (ImportError, AttributeError) as exc:
        raise UsageError(f"`physai-lint {kind}` is not available in this build: {exc}") from None
    entry = os.path.abspath(paths[0])
    out = func(opts, entry, node, fmt) if kind == "params" else func(opts, entry, fmt)
    _emit(out if out.endswith("\n") else out + "\n", output)
    return 0


def _rules(fmt: str, output: Optional[str]) -> int:
    from physai_lint.catalog import load_catalog
    from physai_lint.report import rules_doc

    _choice("--format", fmt, RULES_FORMATS)
    catalog = load_catalog()
    render = {"table": rules_doc.render_table, "json": rules_doc.render_json, "markdown": rules_doc.render_markdown}[fmt]
    _emit(render(catalog), output)
    return 0


def _rule(code: str) -> int:
    from physai_lint.catalog import load_catalog, lookup, suggest
    from physai_lint.errors import UsageError
    from physai_lint.report.rules_doc import render_rule

    catalog = load_catalog()
    doc = lookup(code, catalog)
    if doc is None:
        hint = suggest(code, [*catalog, *(d.name for d in catalog.values())])
        raise UsageError(f'unknown rule "{code}"' + (f' (did you mean "{hint}"?)' if hint else " (see physai-lint rules)"))
    _emit(render_rule(doc), None)
    return 0


# --------------------------------------------------------------------------- typer app


def _build_app() -> Any:
    import typer

    app = typer.Typer(
        name="physai-lint",
        add_completion=False,
        rich_markup_mode=None,
        pretty_exceptions_enable=False,
        context_settings={"help_option_names": ["-h", "--help"]},
        help="Static analysis for ROS 2 launch files and parameter YAML.\n\n"
        "`physai-lint PATH... [NAME:=VALUE ...]` is short for `physai-lint check ...`. "
        "Exit codes: 0 clean, 1 findings at or above --fail-on, 2 usage, configuration or internal error.",
    )
    Opt, Arg = typer.Option, typer.Argument
    fmt_help = "Output format: " + ", ".join(CHECK_FORMATS) + "."

    @app.command("check", help="Check launch files, parameter files and folders (the default command).")
    def check(
        args: Optional[List[str]] = Arg(None, metavar="PATH... [NAME:=VALUE]...", help="Files or folders, and launch arguments.", show_default=False),
        fmt: str = Opt("text", "--format", metavar="FORMAT", help=fmt_help),
        output: Optional[str] = Opt(None, "--output", "-o", help="Write the report to FILE.", metavar="FILE"),
        workspace: Optional[str] = Opt(None, "--workspace", help="The colcon workspace (default: found from the paths).", metavar="DIR"),
        distro: Optional[str] = Opt(None, "--distro", metavar="DISTRO", help="ROS 2 distribution: " + ", ".join(DISTROS) + " (default humble)."),
        interfaces: Optional[List[str]] = Opt(None, "--interfaces", help="Node interface declarations (repeatable).", metavar="FILE"),
        select: Optional[List[str]] = Opt(None, "--select", metavar="CODES", help="Rules to enable: codes, prefixes or names, comma-separated (replaces the configured list)."),
        ignore: Optional[List[str]] = Opt(None, "--ignore", metavar="CODES", help="Rules to disable, comma-separated."),
        extend_select: Optional[List[str]] = Opt(None, "--extend-select", metavar="CODES", help="Rules to enable on top of the selection."),
        fail_on: Optional[str] = Opt(None, "--fail-on", metavar="LEVEL", help="Exit 1 on findings of this severity or worse: error, warning, note (default error)."),
        exit_zero: bool = Opt(False, "--exit-zero", help="Exit 0 even with findings."),
        config: Optional[str] = Opt(None, "--config", help="Configuration file (default: found walking up from here).", metavar="FILE"),
        statistics: bool = Opt(False, "--statistics", help="Print a count per rule instead of the findings."),
        baseline: Optional[str] = Opt(None, "--baseline", help="Hide the findings recorded in FILE.", metavar="FILE"),
        write_baseline: Optional[str] = Opt(None, "--write-baseline", help="Record the current findings in FILE and exit 0.", metavar="FILE"),
        jobs: Optional[int] = Opt(None, "--jobs", "-j", metavar="N", help="Processes that parse, resolve and check in parallel (default: number of CPUs); the report is the same for any N."),
        no_cache: bool = Opt(False, "--no-cache", help="Do not read or write the parse cache (see PHYSAI_LINT_CACHE_DIR)."),
        no_respect_gitignore: bool = Opt(False, "--no-respect-gitignore", help="Also check files ignored by git."),
        strict: bool = Opt(False, "--strict", help="Report some statically unknown values as notes."),
        xunit_file: Optional[str] = Opt(None, "--xunit-file", help="Also write a JUnit XML report to FILE (colcon test).", metavar="FILE"),
        show_source: bool = Opt(True, "--show-source/--no-show-source", help="Show the source line under each finding."),
        quiet: bool = Opt(False, "--quiet", "-q", help="Print the findings only, no summary."),
    ) -> int:
        common = _Common(
            workspace, distro, interfaces, select, ignore, extend_select, fail_on, config, baseline,
            write_baseline, jobs, not no_cache, False if no_respect_gitignore else None, strict,
        )
        raise typer.Exit(_check(args, common, fmt, output, exit_zero, statistics, xunit_file, show_source, quiet))

    def _api(kind: str, formats: Sequence[str], default: str, help: str, with_node: bool = False) -> None:
        def command(
            args: List[str] = Arg(..., metavar="FILE [NAME:=VALUE]...", help="The entry launch file and launch arguments."),
            fmt: str = Opt(default, "--format", metavar="FORMAT", help="Output format: " + ", ".join(formats) + "."),
            output: Optional[str] = Opt(None, "--output", "-o", metavar="FILE", help="Write to FILE."),
            node: Optional[str] = Opt(None, "--node", metavar="FQN", help="Only this node (fully qualified name, /ns/name)."),
            workspace: Optional[str] = Opt(None, "--workspace", metavar="DIR", help="The colcon workspace."),
            distro: Optional[str] = Opt(None, "--distro", metavar="DISTRO", help="ROS 2 distribution: " + ", ".join(DISTROS) + "."),
            interfaces: Optional[List[str]] = Opt(None, "--interfaces", metavar="FILE", help="Node interface declarations (repeatable)."),
            select: Optional[List[str]] = Opt(None, "--select", hidden=True),
            ignore: Optional[List[str]] = Opt(None, "--ignore", hidden=True),
            fail_on: Optional[str] = Opt(None, "--fail-on", hidden=True),
            exit_zero: bool = Opt(False, "--exit-zero", hidden=True),
            config: Optional[str] = Opt(None, "--config", metavar="FILE", help="Configuration file."),
        ) -> int:
            _choice("--format", fmt, formats)
            if node is not None and not with_node:
                from physai_lint.errors import UsageError

                raise UsageError(f"--node is an option of `physai-lint params`, not of `{kind}`")
            common = _Common(workspace, distro, interfaces, select, ignore, None, fail_on, config)
            raise typer.Exit(_api_command(kind, args, common, fmt, output, node))

        app.command(kind, help=help)(command)

    _api("graph", GRAPH_FORMATS, "text", "Print the system graph of a launch file (nodes, topics, parameters).")
    _api("plan", PLAN_FORMATS, "text", "Print the startup plan of a launch file (what starts when).")
    _api("params", PARAMS_FORMATS, "text", "Print the effective parameters of the nodes of a launch file.", with_node=True)

    @app.command("rules", help="List the rules.")
    def rules(
        fmt: str = Opt("table", "--format", metavar="FORMAT", help="table, json or markdown (docs/rules.md)."),
        output: Optional[str] = Opt(None, "--output", "-o", metavar="FILE", help="Write to FILE."),
    ) -> int:
        raise typer.Exit(_rules(fmt, output))

    @app.command("rule", help="Print the documentation of one rule.")
    def rule(code: str = Arg(..., metavar="CODE|NAME", help="A rule code (N101) or name (duplicate-node-name).")) -> int:
        raise typer.Exit(_rule(code))

    return app
