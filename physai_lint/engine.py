"""The pipeline: discover -> parse -> resolve -> check -> suppress/select/baseline -> Report."""
from __future__ import annotations

import os
import time
from collections.abc import Iterator
from dataclasses import dataclass, field
from typing import Any

from physai_lint.errors import ConfigError, UsageError
from physai_lint.files import MAX_FILE_BYTES, FileStore, internal_error
from physai_lint.model.findings import SEVERITY_RANK, Diagnostic, Finding
from physai_lint.model.span import Span


@dataclass
class CheckOptions:
    paths: list[str]
    launch_args: dict[str, str] = field(default_factory=dict)
    workspace: str | None = None
    distro: str = "humble"
    interfaces: list[str] = field(default_factory=list)
    select: list[str] | None = None
    ignore: list[str] = field(default_factory=list)
    extend_select: list[str] = field(default_factory=list)
    per_file_ignores: dict[str, list[str]] = field(default_factory=dict)
    fail_on: str = "error"
    rule_options: dict[str, dict[str, Any]] = field(default_factory=dict)
    baseline: str | None = None
    write_baseline: str | None = None
    jobs: int | None = None
    cache: bool = True
    respect_gitignore: bool = True
    strict: bool = False
    severity: dict[str, str] = field(default_factory=dict)
    exclude: list[str] = field(default_factory=list)
    progress: bool = False  # a progress bar on stderr (the CLI sets it only for a TTY)


@dataclass
class Report:
    findings: list[Finding]
    files: list[str]
    cwd: str
    duration_s: float = 0.0
    baseline_suppressed: int = 0
    skipped: list[tuple[str, str]] = field(default_factory=list)  # named files not checked, and why


@dataclass
class Project:
    """Everything the checks, the graph and the plan read."""

    cwd: str
    root: str
    store: FileStore
    packages: Any
    launches: list[Any]
    entries: list[str]
    param_files: dict[str, Any]
    interfaces: Any
    targets: frozenset[str]
    diagnostics: list[Diagnostic]
    skipped: list[tuple[str, str]] = field(default_factory=list)  # named files not checked, and why


def _abs(path: str, cwd: str) -> str:
    return os.path.normpath(os.path.join(cwd, path)).replace(os.sep, "/")


def build_project(opts: CheckOptions, cwd: str | None = None, progress: Any = None) -> Project:
    """Discover, parse and resolve: the model that every subcommand reads."""
    from physai_lint import gcpolicy
    from physai_lint import workspace as ws
    from physai_lint.resolve.instantiate import resolve_launch
    from physai_lint.resolve.roots import choose_roots

    cwd = (cwd or os.getcwd()).replace(os.sep, "/")
    if opts.distro not in ws.DISTROS:
        raise UsageError(f'unknown distro "{opts.distro}" (expected one of: {", ".join(ws.DISTROS)})')
    paths = [_abs(p, cwd) for p in opts.paths]
    try:
        found = ws.discover(paths, respect_gitignore=opts.respect_gitignore)
        root = _abs(opts.workspace, cwd) if opts.workspace else ws.find_workspace_root(paths)
    except ws.UsageError as exc:
        raise UsageError(exc.message) from None
    if opts.workspace and not os.path.isdir(root):
        raise UsageError(f'workspace "{opts.workspace}" is not a directory')
    from physai_lint.cache import ParseCache

    cache = ParseCache.open(opts.cache)  # parse results, package reading, C++ extraction
    max_bytes = int(opts.rule_options.get("X002", {}).get("max-bytes", MAX_FILE_BYTES))
    store = FileStore(cache=cache, max_bytes=max_bytes)
    skipped = _sort_out(store, found)
    # Without a launch file to resolve, the index is read only for the problems of the checked
    # packages' manifests (nothing resolves, so no rule asks it anything): build only that.
    scope = None if found.launch_files else sorted(set(paths) | set(found.param_files))
    packages = ws.build_package_index(root, opts.distro, os.environ.get("AMENT_PREFIX_PATH"), scope,
                                      cache=cache)
    from physai_lint.parallel import default_jobs, interface_side, package_reads, resolve_entries
    from physai_lint.progress import Progress

    progress = progress or Progress(False)
    jobs = opts.jobs or default_jobs()
    # The packages holding checked files are read at the end anyway; with --jobs, on every CPU
    # first, along with the parsing when that forks (parallel.package_reads).
    reads = package_reads(packages, packages.names_holding([*paths, *found.launch_files, *found.param_files]),
                          jobs, files=len(found.launch_files) + len(found.param_files)) \
        if hasattr(packages, "names_holding") else None
    # Parse every discovered file once, up front: from the disk cache, else in --jobs workers.
    store.preload(found.launch_files, found.param_files, opts.distro, jobs, progress, reads)
    if reads is not None:
        reads.run()  # not taken along (everything parsed from the cache, or too few files)
    gcpolicy.parsing_done()
    diagnostics: list[Diagnostic] = []

    def loader(path: str) -> Any:
        return store.launch(path, packages.read_text if hasattr(packages, "read_text") else None)

    explicit = set(found.explicit)
    launch_files = list(found.launch_files)

    def read_located(path: str) -> str | None:
        """A file an OpaqueFunction reads once its path is known, where ``ros2 launch`` would
        find it: a workspace package's installed file is read from its source."""
        found = packages.locate(path)
        return packages.read_text(found.source) if found.status == "ok" and found.source else None

    reader = read_located if hasattr(packages, "locate") and hasattr(packages, "read_text") else None

    def specialize(path: str, action: Any, known: tuple[tuple[Any, str], ...]) -> Any:
        return store.specialize(path, action, known, reader)

    def resolve_quiet(entry: str) -> Any:
        return resolve_launch(entry, dict(opts.launch_args), loader, packages,
                              explicit_entry=entry in explicit, specialize=specialize)

    def resolve(entry: str) -> Any:
        progress.advance()
        return resolve_quiet(entry)

    # The interfaces of the executables the parsed files name are extracted along with the
    # resolution when that forks (parallel.interface_side); the rules' prefetch does the rest.
    iface_diags: list[Diagnostic] = []
    interfaces = _interfaces(opts, cwd, packages, iface_diags, cache)
    files = len(store.launches) + len(store.params)
    side = interface_side(interfaces, _named_interface_keys(store.launches.values()), jobs, files) \
        if interfaces is not None else None

    def resolve_many(entries: list[str], leaves: bool) -> list[Any]:
        # with --jobs, forked helpers take a share (physai_lint/parallel.py)
        return resolve_entries(entries, resolve_quiet, store, loader, jobs, progress,
                               files=files, leaves=leaves, side=None if leaves else side)

    progress.stage("resolving", len(launch_files))
    launches = choose_roots(launch_files, loader, resolve, progress.advance, resolve_many,
                            getattr(packages, "package_name_of", None))
    targets = (set(paths) - {p for p, _ in skipped}) | set(found.launch_files) | set(found.param_files)
    for r in launches:
        if r.entry in explicit or any(r.entry.startswith(p.rstrip("/") + "/") for p in paths) or \
                any(f in explicit for f in r.files):
            targets.update(r.files)
            targets.update(_param_sources(r))
    param_models = _load_params(store, sorted(set(found.param_files) | _all_param_sources(launches)),
                                opts.distro, diagnostics,
                                set().union(*(_param_sources(r, True) for r in launches)))
    diagnostics.extend(iface_diags)
    # Packages are read when first asked for; the checked ones are read here, for their problems.
    if hasattr(packages, "read_packages_holding"):
        packages.read_packages_holding(targets)
    for path, message, line in getattr(packages, "problems", []):
        diagnostics.append(Diagnostic("X001", Span.point(path, max(line or 1, 1)), message,
                                      help="fix package.xml so that colcon can read it"))
    diagnostics.extend(store.diagnostics)
    for r in launches:
        diagnostics.extend(r.diagnostics)
    return Project(cwd, root, store, packages, launches, [r.entry for r in launches], param_models,
                   interfaces, frozenset(targets), diagnostics, skipped)


def _sort_out(store: FileStore, found: Any) -> list[tuple[str, str]]:
    """Decide, from their texts, what discovery's undecided files are (``sniff.classify``): add
    them to its launch or parameter files, or leave them out. Returns the explicitly named files
    left out, with the reason. The texts stay in the store: each file is still read once."""
    from physai_lint.sniff import classify, only_named_launch
    from physai_lint.workspace import is_launch_file

    explicit = set(found.explicit)
    launch, params, skipped = set(found.launch_files), set(found.param_files), []
    for path in found.launch_files:  # found by a *launch.py name: left out if only the name says so
        if path not in explicit:
            text = store.peek(path)
            if text is not None and (only_named_launch(text) or _package_module(path, text)):
                launch.discard(path)
    for path in found.undecided:
        name = os.path.basename(path)
        # An unreadable file is reported (X002) when its name or the user says it is a launch file;
        # else it is most likely no launch file at all (a binary *.launch of a ROS 1 package).
        named = path in explicit or is_launch_file(name)
        verdict = classify(name, store.text(path) if named else store.peek(path), path in explicit)
        if verdict.kind == "launch":
            launch.add(path)
        elif verdict.kind == "params":
            params.add(path)
        elif path in explicit:
            skipped.append((path, verdict.reason or "not a launch or parameter file"))
    found.launch_files, found.param_files = sorted(launch), sorted(params)
    return skipped


def _package_module(path: str, text: str) -> bool:
    """A module named ``launch.py`` in a Python package (an ``__init__.py`` beside it) that defines
    no ``generate_launch_description``: a library of launch helpers the package's launch files
    import (``vrx_gz/launch.py``), not a file ``ros2 launch`` runs. (``x_launch.py`` there is a
    launch file by its name.)"""
    from physai_lint.sniff import defines_entry

    return os.path.basename(path) == "launch.py" and not defines_entry(text) and \
        os.path.isfile(os.path.join(os.path.dirname(path), "__init__.py"))


def _param_sources(r: Any, composable_only: bool = False) -> set[str]:
    """Workspace parameter files that the nodes of a launch load (and that exist after install);
    ``composable_only``: those of its composable nodes, which launch_ros reads with PyYAML (rcl
    reads a node's through --params-file)."""
    out: set[str] = set()
    for n in r.nodes:
        if composable_only and n.kind != "composable_node":
            continue
        for s in n.param_sources:
            if composable_only and getattr(s, "origin", None) == "forwarded":
                continue  # the container's file: rcl reads it for the component too
            # a file whose $(...) cannot all be performed here is still read, and its reads checked
            if getattr(s, "status", None) == "ok" or \
                    getattr(s, "derived_from", None) and getattr(s, "allow_substs", False):
                f = getattr(s, "source", None) or getattr(s, "derived_from", None)  # RewrittenYaml: its source
                if f:
                    out.add(f)
    return out


def _all_param_sources(launches: list[Any]) -> set[str]:
    return set().union(*(_param_sources(r) for r in launches)) if launches else set()


def _load_params(store: FileStore, paths: list[str], distro: str, sink: list[Diagnostic],
                 pyyaml_read: set[str]) -> dict[str, Any]:
    models: dict[str, Any] = {}
    for path in paths:
        model = store.param_file(path, distro)
        if model is None:
            continue
        models[path] = model
        # P1xx structure findings are reported by their rules (checks/param_files.py).
        sink.extend(d for d in model.diagnostics if not d.code.startswith("P"))
        if path in pyyaml_read:  # a repeated node key loses its first block only there
            sink.extend(model.merged_keys)
    sink.extend(store.param_diagnostics)  # parser crashes (X003)
    store.param_diagnostics.clear()
    return models


def _interfaces(opts: CheckOptions, cwd: str, packages: Any, sink: list[Diagnostic],
                cache: Any = None) -> Any:
    from physai_lint.interfaces.store import build_interface_store

    files = []
    for f in opts.interfaces:
        path = _abs(f, cwd)
        if not os.path.isfile(path):
            raise UsageError(f'interfaces file "{f}" does not exist')
        with open(path, encoding="utf-8", errors="replace") as fh:
            files.append((path, fh.read()))
    store, diags = build_interface_store(files, packages, opts.distro, cache)
    sink.extend(diags)
    return store


def run_checks(project: Project, opts: CheckOptions, progress: Any = None) -> list[Diagnostic]:
    from physai_lint.checks.base import CheckContext, load_all
    from physai_lint.parallel import default_jobs, prefetch_interfaces, run_rules

    ctx = CheckContext(
        launch_files={p: lf for p, lf in project.store.launches.items() if lf is not None},
        param_files=project.param_files, launches=project.launches, packages=project.packages,
        interfaces=project.interfaces, distro=opts.distro, targets=project.targets,
        # A copy: rules keep per-run memos in it (keyed by node identity), which must neither
        # leak into the caller's options nor outlive this run.
        options=dict(opts.rule_options),
    )
    rules = sorted(load_all().items())
    where = project.entries[0] if project.entries else project.root

    def run_one(code: str, impl: Any) -> list[Diagnostic]:
        found: list[Diagnostic] = []
        try:
            found.extend(impl.func(ctx))
        except Exception as exc:  # noqa: BLE001 - a rule that raises becomes an X003 finding
            found.append(internal_error(where, f"rule {code} ({impl.name})", exc))
        return found

    jobs = opts.jobs or default_jobs()
    files = len(ctx.launch_files) + len(ctx.param_files)
    if progress is not None:
        progress.stage("checking", len(rules))
    # With --jobs > 1 on a large project, the interfaces of the nodes' executables are extracted
    # first on every CPU, then groups of rules run in forked processes: same findings, same order
    # (physai_lint/parallel.py).
    if project.interfaces is not None:
        prefetch_interfaces(project.interfaces, _interface_keys(project.launches), jobs, files)
    name_nodes(project)
    return run_rules(rules, run_one, jobs, progress, files=files)


def name_nodes(project: Project) -> None:
    """The nodes launch names nothing take the name their code gives them (once the interfaces
    are extracted: ``interfaces/naming.py``)."""
    from physai_lint.interfaces.naming import apply_default_names

    apply_default_names(project.launches, project.interfaces)


def _named_interface_keys(launch_files: Any) -> Iterator[tuple[str, str]]:
    """(package, executable or plugin) that parsed launch files give nodes literally: the keys
    ``_interface_keys`` will most likely list once they are resolved. A generator: the files are
    walked only if ``parallel.interface_side`` shares the keys (not with one job, nor on a small
    run)."""
    from physai_lint.model import launch as ir
    from physai_lint.model.values import literal_of
    from physai_lint.resolve.roots import actions_of

    for lf in launch_files:
        for a in actions_of(lf):
            comps: tuple[Any, ...] = ()
            if isinstance(a, ir.NodeAction):
                pkg, exe = literal_of(a.package), literal_of(a.executable)
                if pkg and exe:
                    yield pkg, exe
                comps = a.composable_nodes
            elif isinstance(a, ir.LoadComposableNodes):
                comps = a.nodes
            for c in comps:
                pkg, plugin = literal_of(c.package), literal_of(c.plugin)
                if pkg and plugin:
                    yield pkg, plugin


def _interface_keys(launches: list[Any]) -> list[tuple[str, str]]:
    """(package, executable) of the nodes whose interfaces the rules ask for: every active node
    that is not a plain process (``graph.system.build_graph``)."""
    return [(n.package, n.executable) for r in launches for n in r.nodes
            if n.kind != "process" and n.active is not False and n.package and n.executable]


def to_findings(diags: list[Diagnostic], catalog: dict[str, Any], severity: dict[str, str]) -> list[Finding]:
    from physai_lint.checks.base import REGISTRY

    out = []
    for d in diags:
        doc = catalog.get(d.code)
        impl = REGISTRY.get(d.code)
        name = doc.name if doc is not None else (impl.name if impl is not None else d.code.lower())
        sev = severity.get(d.code) or (doc.severity if doc is not None else "error")
        out.append(Finding(d.code, name, sev, d.span, d.message, d.help, d.related, d.key, d.fix))  # type: ignore[arg-type]
    return out


def run_check(opts: CheckOptions, cwd: str | None = None) -> Report:
    """The whole ``check`` pipeline."""
    from physai_lint import baseline as bl
    from physai_lint import gcpolicy, suppress
    from physai_lint.catalog import load_catalog
    from physai_lint.progress import Progress
    from physai_lint.report import rel
    from physai_lint.selection import Selector

    started = time.perf_counter()
    catalog = load_catalog()
    selector = Selector(opts.select, opts.ignore, opts.extend_select, opts.per_file_ignores, catalog)
    progress = Progress.start(opts.progress)
    try:
        project = build_project(opts, cwd, progress)
        gcpolicy.keep_to_exit(project)  # not freed object by object before the report
        diags = project.diagnostics + run_checks(project, opts, progress)
    finally:
        progress.stop()
    seen: set[tuple[Any, ...]] = set()
    unique = []
    for d in diags:
        k = (d.code, d.span, d.message)
        if k not in seen:
            seen.add(k)
            unique.append(d)
    findings = [f for f in to_findings(unique, catalog, opts.severity)
                if f.span.file in project.targets or f.code.startswith("X")
                and (f.span.file in project.store.texts or _manifest_of_targets(f.span.file, project.targets))]
    findings = [f for f in findings if selector.enabled_for(f.code, rel(f.span.file, project.cwd))]
    findings, extra = _suppress(findings, project, catalog, selector, suppress)
    findings += [f for f in to_findings(extra, catalog, opts.severity)
                 if selector.enabled_for(f.code, rel(f.span.file, project.cwd))]
    suppressed = 0
    if opts.baseline:
        findings, suppressed = bl.load(opts.baseline).filter(findings, project.cwd)
    findings.sort(key=Finding.sort_key)
    if opts.write_baseline:
        bl.write(opts.write_baseline, findings, project.cwd)
    files = sorted(project.targets & (set(project.store.texts) | set(project.param_files)))
    return Report(findings, files, project.cwd, time.perf_counter() - started, suppressed, project.skipped)


def _suppress(findings: list[Finding], project: Project, catalog: dict[str, Any], selector: Any,
              suppress: Any) -> tuple[list[Finding], list[Diagnostic]]:
    from physai_lint.sniff import launch_format

    directives = {}
    for path, text in project.store.texts.items():
        if text is None or path not in project.targets:
            continue
        fmt = launch_format(path, text)
        if fmt is not None:
            directives[path] = suppress.parse_directives(path, text, fmt)
    return suppress.apply(findings, directives, catalog, enabled=selector.enabled)  # type: ignore[no-any-return]


def _manifest_of_targets(path: str, targets: set[str]) -> bool:
    """A package.xml (read by the package index, not the file store) of a package being checked."""
    if os.path.basename(path) != "package.xml":
        return False
    pkg_dir = os.path.dirname(path) + "/"
    return any(t.startswith(pkg_dir) for t in targets)


def exit_code(report: Report, fail_on: str) -> int:
    threshold = SEVERITY_RANK.get(fail_on, 2)
    return 1 if any(SEVERITY_RANK[f.severity] >= threshold for f in report.findings) else 0


__all__ = ["CheckOptions", "ConfigError", "Project", "Report", "UsageError", "build_project",
           "exit_code", "run_check"]
