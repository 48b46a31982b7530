"""Runs ``physai_lint.cli.main`` with a stand-in engine and api, so CLI tests do not depend on the
real pipeline. The fake flags every line containing ``BAD`` (N101, error) or ``WARN`` (P101, warning),
records the options it got in ``$FAKE_RECORD`` and raises when ``$FAKE_CRASH`` is set."""
from __future__ import annotations

import json
import os
import sys
import types
from dataclasses import asdict, dataclass, field

from physai_lint.model.findings import Finding, Related
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
    rule_options: dict[str, dict] = field(default_factory=dict)
    baseline: str | None = None
    write_baseline: str | None = None
    jobs: int | None = None
    cache: bool = True
    respect_gitignore: bool = True
    strict: bool = False


@dataclass
class Report:
    findings: list[Finding]
    files: list[str]
    cwd: str
    duration_s: float
    baseline_suppressed: int = 0


def _files(paths: list[str]) -> list[str]:
    out = []
    for p in paths:
        if os.path.isdir(p):
            for root, _dirs, names in os.walk(p):
                out += [os.path.join(root, n) for n in names]
        else:
            out.append(p)
    return sorted(out)


def run_check(opts: CheckOptions) -> Report:
    if os.environ.get("FAKE_RECORD"):
        with open(os.environ["FAKE_RECORD"], "w") as fh:
            json.dump(asdict(opts), fh)
    if os.environ.get("FAKE_CRASH"):
        raise RuntimeError("boom")
    findings = []
    files = _files(opts.paths)
    for path in files:
        with open(path, encoding="utf-8") as fh:
            for i, line in enumerate(fh.read().splitlines(), 1):
                for word, code, name, sev in (("BAD", "N101", "duplicate-node-name", "error"), ("WARN", "P101", "parameter-file-missing", "warning")):
                    col = line.find(word) + 1
                    if col:
                        span = Span(path, i, col, i, col + len(word))
                        findings.append(Finding(code, name, sev, span, f'flagged "{word}"', "remove it",
                                                (Related(Span(path, 1, 1, 1, 2), "first defined here"),), key=word))
    return Report(findings, files, os.getcwd(), 0.5, 0)


engine = types.ModuleType("physai_lint.engine")
engine.CheckOptions, engine.Report, engine.run_check = CheckOptions, Report, run_check  # type: ignore[attr-defined]
sys.modules["physai_lint.engine"] = engine
api = types.ModuleType("physai_lint.api")
api.graph = lambda opts, entry, fmt: f"graph {os.path.basename(entry)} {fmt} {json.dumps(opts.launch_args)}"  # type: ignore[attr-defined]
sys.modules["physai_lint.api"] = api

from physai_lint.cli import main  # noqa: E402

raise SystemExit(main(sys.argv[1:]))
