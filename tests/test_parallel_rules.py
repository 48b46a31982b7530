"""--jobs > 1 on a large project: groups of rules run in forked processes (physai_lint/parallel.py).

The findings must be exactly those of one process, in the same order, whatever happens to a
child: a rule that raises there still gives its X003, a child that dies or whose findings cannot
travel back has its group run again in the parent. The fixtures are small, so the tests lower
the size threshold through PHYSAI_LINT_FORK_MIN_FILES.
"""
from __future__ import annotations

import inspect
import os
import shutil
import signal
import subprocess
import sys
import threading
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest

from physai_lint import engine, parallel
from physai_lint.checks import base
from physai_lint.model.findings import Diagnostic
from physai_lint.model.span import Span

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO / "benchmarks"))

from gen_workspace import generate

PARENT = os.getpid()
UNPICKLABLE = threading.Lock()  # the same object in every run: findings holding it compare equal


@pytest.fixture(scope="module")
def workspace(tmp_path_factory: pytest.TempPathFactory) -> Path:
    ws = tmp_path_factory.mktemp("parallel_rules")
    generate(12, 3, ws)  # 36 launch files and 12 parameter files
    # and the example workspace's packages: findings of many rules, C++ sources for interfaces
    shutil.copytree(REPO / "examples" / "buggy_ws" / "src", ws / "src", dirs_exist_ok=True)
    return ws


@pytest.fixture(scope="module")
def project(workspace: Path) -> tuple[Any, engine.CheckOptions]:
    ws = workspace
    opts = engine.CheckOptions(paths=[str(ws / "src")], workspace=str(ws), cache=False, jobs=1)
    return engine.build_project(opts, str(ws)), opts


@pytest.fixture
def forks(monkeypatch: pytest.MonkeyPatch) -> list[int]:
    """Lower the threshold so that the fixture forks, and count the forks."""
    monkeypatch.setenv(parallel.FORK_MIN_ENV, "0")
    calls: list[int] = []
    real = os.fork

    def fork() -> int:
        calls.append(1)
        return real()

    monkeypatch.setattr(os, "fork", fork)
    return calls


@pytest.fixture
def extra_rules(monkeypatch: pytest.MonkeyPatch) -> Iterator[dict[str, Any]]:
    """Register test rules for one test; they run in a helper (the last unit, which the helper is
    given before it forks)."""
    added: dict[str, Any] = {}
    real_plan = parallel.plan_units

    def plan(codes: list[str]) -> list[list[int]]:
        units = real_plan(codes)
        mine = [i for i, c in enumerate(codes) if c in added]
        units = [[i for i in u if i not in mine] for u in units]
        return [u for u in units if u] + ([mine] if mine else [])

    monkeypatch.setattr(parallel, "plan_units", plan)
    yield added
    for code in added:
        base.REGISTRY.pop(code, None)


def add_rule(added: dict[str, Any], code: str, func: Any) -> None:
    base.load_all()
    base.REGISTRY[code] = base.RuleImpl(code, f"test-{code.lower()}", func)
    added[code] = func


def run(project: tuple[Any, engine.CheckOptions], jobs: int, progress: Any = None) -> list[Diagnostic]:
    proj, opts = project
    opts.jobs = jobs
    return engine.run_checks(proj, opts, progress)


class Steps:
    """A progress bar that only counts."""

    def __init__(self) -> None:
        self.total, self.done = 0, 0

    def stage(self, name: str, total: int) -> None:
        self.total, self.done = total, 0

    def advance(self, steps: int = 1) -> None:
        self.done += steps


def a_finding(code: str, path: str, message: str, **kw: Any) -> Diagnostic:
    return Diagnostic(code, Span.whole_file(path), message, **kw)


def test_two_processes_give_the_findings_of_one_in_the_same_order(project: Any, forks: list[int]) -> None:
    one = run(project, 1)
    assert not forks
    steps = Steps()
    two = run(project, 2, steps)
    assert forks  # the rules did run in two processes
    assert len({d.code for d in one}) >= 8 and two == one
    assert steps.done == steps.total == len(base.REGISTRY)


def test_a_rule_that_raises_in_a_child_gives_its_x003(project: Any, forks: list[int],
                                                      extra_rules: dict[str, Any], tmp_path: Path) -> None:
    where = tmp_path / "pid"

    def raises(ctx: Any) -> Iterator[Diagnostic]:
        where.write_text(str(os.getpid()))
        yield a_finding("Z901", project[0].entries[0], "before the error")
        raise RuntimeError("boom")

    add_rule(extra_rules, "Z901", raises)
    one = run(project, 1)
    two = run(project, 2)
    assert forks and int(where.read_text()) != os.getpid()  # it did run in a child
    assert two == one
    tail = [d for d in two if d.code in ("Z901", "X003")]
    assert [d.code for d in tail] == ["Z901", "X003"]
    assert tail[1].message == "internal error in rule Z901 (test-z901): RuntimeError: boom"


@pytest.mark.parametrize("how", ["exit", "kill", "unpicklable"])
def test_a_child_that_fails_loses_no_finding(project: Any, forks: list[int], extra_rules: dict[str, Any],
                                             how: str, tmp_path: Path) -> None:
    in_child = tmp_path / "in-child"

    def fails_in_a_child(ctx: Any) -> Iterator[Diagnostic]:
        if os.getpid() != PARENT:
            in_child.touch()
            if how == "exit":
                os._exit(3)
            if how == "kill":
                os.kill(os.getpid(), signal.SIGKILL)
        yield a_finding("Z902", project[0].entries[0], "found in the parent",
                        fix=UNPICKLABLE if how == "unpicklable" else None)

    add_rule(extra_rules, "Z902", fails_in_a_child)
    one = run(project, 1)
    steps = Steps()
    two = run(project, 2, steps)
    assert forks and in_child.exists()
    assert two == one and any(d.code == "Z902" for d in two)
    assert steps.done == steps.total  # the bar still ends at its total


def test_forks_only_from_the_size_threshold_on(project: Any, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv(parallel.FORK_MIN_ENV, raising=False)
    calls: list[int] = []
    real = os.fork
    monkeypatch.setattr(os, "fork", lambda: calls.append(1) or real())
    small = engine.CheckOptions(paths=[str(REPO / "examples" / "buggy_ws" / "src")],
                                workspace=str(REPO / "examples" / "buggy_ws"), cache=False, jobs=8)
    built = engine.build_project(small, str(REPO / "examples" / "buggy_ws"))
    assert len(built.store.launches) + len(built.param_files) < parallel.MIN_FORK_FILES
    engine.run_checks(built, small)
    assert not calls  # a small run (pre-commit on a few files) stays in one process
    files = len(project[0].store.launches) + len(project[0].param_files)
    monkeypatch.setattr(parallel, "MIN_FORK_FILES", files + 1)
    run(project, 2)
    assert not calls
    monkeypatch.setattr(parallel, "MIN_FORK_FILES", files)
    run(project, 2)
    assert calls


def test_units_keep_shared_memos_together_and_cover_every_rule_once() -> None:
    codes = sorted(base.load_all())
    units = parallel.plan_units(codes)
    assert sorted(i for u in units for i in u) == list(range(len(codes)))
    assert all(u == sorted(u) for u in units)
    for _, members in parallel.SHARED_MEMOS:
        assert len({k for k, u in enumerate(units) for i in u if codes[i] in members}) == 1
    costs = [parallel.unit_cost(codes, u) for u in units]
    assert costs == sorted(costs, reverse=True)  # this process takes the heaviest first
    assert parallel.plan_units(codes[:1]) == [[0]]


def test_a_helper_does_its_first_item_however_late_it_starts(monkeypatch: pytest.MonkeyPatch) -> None:
    """The item given to a helper before its fork is done there, even when this process could
    finish every other item before the helper gets a CPU."""
    done_in: dict[int, int] = {}

    def local(i: int) -> None:
        done_in[i] = os.getpid()

    def remote(i: int) -> bytes:
        return str(os.getpid()).encode()

    def accept(i: int, data: bytes) -> bool:
        done_in[i] = int(data)
        return True

    parallel.share(50, local, remote, accept, 1)
    assert sorted(done_in) == list(range(50))
    assert done_in[49] != os.getpid()


def _reaches(func: Any, names: set[str]) -> set[str]:
    """The names of ``names`` that a rule uses, itself or through the checks' helper functions."""
    found: set[str] = set()
    seen: set[Any] = set()
    stack = [func]
    while stack:
        f = stack.pop()
        if f in seen:
            continue
        seen.add(f)
        code_objects = [f.__code__]
        while code_objects:
            co = code_objects.pop()
            found.update(n for n in co.co_names if n in names)
            for n in co.co_names:
                obj = f.__globals__.get(n)
                if inspect.isfunction(obj) and obj.__module__.startswith("physai_lint.checks"):
                    stack.append(obj)
            code_objects.extend(c for c in co.co_consts if inspect.iscode(c))
    return found


def test_every_rule_that_uses_a_shared_memo_is_listed() -> None:
    shared = {c for _, members in parallel.SHARED_MEMOS for c in members}
    for code, impl in sorted(base.load_all().items()):
        uses = _reaches(impl.func, {"graphs", "effective", "interface", "interfaces"})
        assert not uses or code in shared or code in parallel.LIGHT_MEMO_USERS, (code, uses)


@pytest.mark.parametrize("fmt", ["json", "sarif"])
def test_the_cli_prints_the_same_report_with_forked_rules(fmt: str, workspace: Path, tmp_path: Path) -> None:
    ws = workspace
    env = {k: v for k, v in os.environ.items() if k not in ("NO_COLOR", "FORCE_COLOR")}
    env.update({"PYTHONPATH": str(REPO), "PHYSAI_LINT_CACHE_DIR": str(tmp_path), parallel.FORK_MIN_ENV: "0"})
    out = []
    for jobs in ("1", "2"):
        proc = subprocess.run([sys.executable, "-m", "physai_lint", "check", "src", "--workspace", ".",
                               "--format", fmt, "--no-cache", "-j", jobs], cwd=ws, env=env,
                              check=False, capture_output=True, text=True, timeout=300)
        assert proc.returncode == 1 and proc.stderr == "", proc.stderr
        out.append(proc.stdout)
    assert out[0] and out[0] == out[1]
