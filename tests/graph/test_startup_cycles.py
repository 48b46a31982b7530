"""``plan.startup_cycles`` (what S101 reads) against ``build_plan``, and its networkx-free path."""
from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import networkx as nx
from hypothesis import given, settings
from hypothesis import strategies as st

from physai_lint.engine import CheckOptions, build_project
from physai_lint.graph import plan as plan_mod
from physai_lint.model.span import Span

HERE = Path(__file__).resolve().parents[1]
CASES = [
    (HERE / "plan_fixtures" / "chain_ws", "src/demo/launch/chain.launch.py"),
    (HERE / "plan_fixtures" / "loop_ws", "src/bot/launch/bot.launch.py"),
    (HERE / "plan_fixtures" / "nav_ws", None),
    (HERE / "rules" / "S101-startup-cycle" / "bad", "src/demo/launch/x.launch.py"),
    (HERE / "rules" / "S101-startup-cycle" / "good", None),
]


def _launches(ws: Path, entry: str | None) -> list[object]:
    if entry is None:
        entry = str(next(iter(sorted((ws / "src").rglob("*.launch.py")))).relative_to(ws))
    project = build_project(CheckOptions(paths=[entry], workspace=str(ws), cache=False, jobs=1),
                            str(ws))
    return list(project.launches)


def test_the_same_cycles_and_never_starts_as_the_whole_plan() -> None:
    seen_cycle = seen_acyclic = False
    for ws, entry in CASES:
        for launch in _launches(ws, entry):
            whole = plan_mod.build_plan(launch, None, lambda n: {})  # type: ignore[arg-type]
            part = plan_mod.startup_cycles(launch, lambda n: {})  # type: ignore[arg-type]
            assert part.cycles == whole.cycles and part.never_starts == whole.never_starts
            assert set(part.vertices) == set(whole.vertices)
            assert part.labels == whole.labels
            seen_cycle |= bool(whole.cycles)
            seen_acyclic |= not whole.cycles and bool(launch.edges)  # type: ignore[attr-defined]
    assert seen_cycle and seen_acyclic


def _edges(pairs: list[tuple[int, int]]) -> list[plan_mod.PlanEdge]:
    span = Span("/x.py", 1, 1, 1, 2)
    return [plan_mod.PlanEdge(f"n{a}", f"n{b}", "on_process_start", False, 0.0, span) for a, b in pairs]


@settings(max_examples=400, deadline=None)
@given(st.lists(st.tuples(st.integers(0, 7), st.integers(0, 7)), max_size=16))
def test_has_cycle_agrees_with_networkx(pairs: list[tuple[int, int]]) -> None:
    g = nx.DiGraph()
    g.add_edges_from(pairs)
    assert plan_mod._has_cycle(_edges(pairs)) is (not nx.is_directed_acyclic_graph(g))


def test_an_acyclic_launch_is_checked_without_importing_networkx() -> None:
    ws = HERE / "plan_fixtures" / "chain_ws"
    code = ("import sys\n"
            "from physai_lint.engine import CheckOptions, run_check\n"
            f"run_check(CheckOptions(paths=['src/demo/launch/chain.launch.py'], workspace={str(ws)!r},"
            " cache=False, jobs=1), cwd=" + repr(str(ws)) + ")\n"
            "print('networkx' in sys.modules)\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120,
                         check=False)
    assert out.returncode == 0, out.stderr
    assert out.stdout.strip() == "False"
