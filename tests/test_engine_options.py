"""Per-run memos of the rules stay out of the caller's options."""
from pathlib import Path

from physai_lint.engine import CheckOptions, run_check

EXAMPLE = Path(__file__).resolve().parents[1] / "examples" / "buggy_ws"


def test_rule_memos_do_not_leak_into_the_callers_options():
    options = {"T201": {}}
    opts = CheckOptions(paths=[str(EXAMPLE / "src")], workspace=str(EXAMPLE), cache=False, jobs=1,
                        interfaces=[str(EXAMPLE / "interfaces.yaml")], rule_options=options)
    first = run_check(opts)
    assert options == {"T201": {}}
    assert [f.code for f in run_check(opts).findings] == [f.code for f in first.findings]
