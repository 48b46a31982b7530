"""The quick, seeded fuzz run: a few hundred generated and mutated inputs through every frontend, the
whole pipeline and every reporter; no exception may escape and no X003 (internal error) may appear.
The long run is ``scripts/fuzz_long.py`` (docs/fuzzing.md)."""
from __future__ import annotations

from collections.abc import Iterator

import fuzz_harness as fh
import pytest
from hypothesis import HealthCheck, given, settings

QUICK = settings(max_examples=60, derandomize=True, database=None, deadline=None,
                 suppress_health_check=list(HealthCheck), phases=["explicit", "generate", "shrink"])


@pytest.fixture(scope="module")
def runner() -> Iterator[fh.Runner]:
    r = fh.Runner()
    yield r
    r.close()


@pytest.mark.parametrize("fmt", fh.FORMATS)
def test_fuzz_quick(fmt: str, runner: fh.Runner) -> None:
    count = [0]

    @QUICK
    @given(fh.inputs(fmt))
    def one(data: bytes) -> None:
        count[0] += 1
        runner.run(fmt, data, api=count[0] % 5 == 0)

    one()
    assert count[0] >= 50


@pytest.mark.parametrize("fmt", fh.FORMATS)
def test_seeds_are_clean(fmt: str, runner: fh.Runner) -> None:
    """The unmutated seeds parse: mutations start from valid files, so they probe deep code."""
    from physai_lint.engine import CheckOptions, run_check

    runner.target(fmt).write_bytes(fh.SEEDS[fmt].encode())
    try:
        report = run_check(CheckOptions(paths=[str(runner.root)], workspace=str(runner.root), cache=False),
                           cwd=str(runner.root))
    finally:
        runner.target(fmt).unlink()
    assert not [f for f in report.findings if f.code.startswith("X")], report.findings
