"""--jobs, the parse cache and the progress bar: things a user would notice.

Output must not depend on the number of jobs or on the cache; a broken or unwritable cache must
never fail a run; nothing but the report may appear on a redirected run.
"""
from __future__ import annotations

import io
import os
import subprocess
import sys
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[2]
BUGGY = REPO / "examples" / "buggy_ws"
sys.path.insert(0, str(REPO / "benchmarks"))

from gen_workspace import generate


def lint(args: list[str], cwd: Path, cache_dir: Path | str) -> subprocess.CompletedProcess[str]:
    env = {k: v for k, v in os.environ.items() if k not in ("NO_COLOR", "FORCE_COLOR")}
    env.update({"PYTHONPATH": str(REPO), "PHYSAI_LINT_CACHE_DIR": str(cache_dir), "COLUMNS": "100"})
    proc = subprocess.run([sys.executable, "-m", "physai_lint", "check", *args], cwd=cwd, env=env,
                          check=False, capture_output=True, text=True, timeout=300)
    assert proc.returncode in (0, 1), (proc.returncode, proc.stderr)
    assert "Traceback" not in proc.stderr
    return proc


def buggy_args(fmt: str) -> list[str]:
    return ["src", "--workspace", ".", "--interfaces", "interfaces.yaml", "--format", fmt]


@pytest.fixture(scope="module")
def synthetic(tmp_path_factory: pytest.TempPathFactory) -> Path:
    # 12 packages x 3 launch files + 12 parameter files: enough files for the pool to start.
    ws = tmp_path_factory.mktemp("synthetic")
    generate(12, 3, ws)
    return ws


@pytest.mark.parametrize("fmt", ["json", "sarif"])
def test_two_jobs_print_the_same_report_as_one_on_the_example(fmt: str, tmp_path: Path) -> None:
    one = lint([*buggy_args(fmt), "-j", "1", "--no-cache"], BUGGY, tmp_path)
    two = lint([*buggy_args(fmt), "-j", "2", "--no-cache"], BUGGY, tmp_path)
    assert one.stdout and one.stdout == two.stdout
    assert one.returncode == two.returncode == 1


@pytest.mark.parametrize("fmt", ["json", "sarif"])
def test_two_jobs_print_the_same_report_as_one_on_a_synthetic_workspace(fmt: str, synthetic: Path,
                                                                      tmp_path: Path) -> None:
    args = ["src", "--workspace", ".", "--format", fmt, "--no-cache"]
    one = lint([*args, "-j", "1"], synthetic, tmp_path)
    two = lint([*args, "-j", "2"], synthetic, tmp_path)
    assert '"results"' in one.stdout or '"findings"' in one.stdout
    assert one.stdout == two.stdout


def cache_entries(cache: Path) -> list[Path]:
    return sorted(p for p in cache.rglob("*.pickle")) if cache.exists() else []


def test_a_warm_cache_gives_the_same_report_and_no_cache_writes_nothing(synthetic: Path,
                                                                        tmp_path: Path) -> None:
    cache = tmp_path / "cache"
    args = ["src", "--workspace", ".", "--format", "json"]
    cold = lint([*args, "-j", "2"], synthetic, cache)
    entries = cache_entries(cache)
    assert len(entries) >= 36  # one per launch and parameter file
    warm = lint([*args, "-j", "1"], synthetic, cache)
    assert warm.stdout == cold.stdout
    fresh = tmp_path / "unused"
    off = lint([*args, "--no-cache"], synthetic, fresh)
    assert off.stdout == cold.stdout and not fresh.exists()


def test_corrupt_cache_entries_are_ignored(synthetic: Path, tmp_path: Path) -> None:
    cache = tmp_path / "cache"
    args = ["src", "--workspace", ".", "--format", "json", "-j", "1"]
    good = lint(args, synthetic, cache)
    for i, entry in enumerate(cache_entries(cache)):
        entry.write_bytes([b"", b"\x80\x05garbage", b"not a pickle at all"][i % 3])
    assert lint(args, synthetic, cache).stdout == good.stdout
    assert lint(args, synthetic, cache).stdout == good.stdout  # rewritten entries read back


def test_an_unwritable_cache_directory_does_not_fail_the_run(tmp_path: Path) -> None:
    blocker = tmp_path / "a-file"
    blocker.write_text("not a directory")
    ok = lint(buggy_args("json"), BUGGY, tmp_path / "nocache")
    broken = lint(buggy_args("json"), BUGGY, blocker / "cache")
    assert broken.stdout == ok.stdout and broken.stderr == ""


def test_a_python_launch_file_that_reads_other_files_is_not_cached(tmp_path: Path) -> None:
    from physai_lint.cache import ParseCache
    from physai_lint.files import FileStore

    launch = tmp_path / "a.launch.py"
    (tmp_path / "extra.yaml").write_text("x: 1\n")
    launch.write_text(
        "import os\nimport yaml\nfrom launch import LaunchDescription\n\n\n"
        "def generate_launch_description():\n"
        f"    with open('{tmp_path}/extra.yaml') as f:\n        yaml.safe_load(f)\n"
        "    return LaunchDescription([])\n")
    plain = tmp_path / "b.launch.py"
    plain.write_text("from launch import LaunchDescription\n\n\n"
                     "def generate_launch_description():\n    return LaunchDescription([])\n")
    cache = ParseCache(str(tmp_path / "cache"))
    store = FileStore(cache=cache)
    store.preload([str(launch), str(plain)], [], "humble", jobs=1)
    assert store.launches[str(launch)] is not None and store.launches[str(plain)] is not None
    assert cache.writes == 1  # only b.launch.py: a.launch.py depends on extra.yaml


def test_redirected_runs_print_no_progress(synthetic: Path, tmp_path: Path) -> None:
    proc = lint(["src", "--workspace", ".", "--format", "json", "--no-cache"], synthetic, tmp_path)
    assert proc.stderr == ""


class FakeTTY(io.StringIO):
    def __init__(self, tty: bool) -> None:
        super().__init__()
        self.tty = tty

    def isatty(self) -> bool:
        return self.tty


def test_progress_bar_appears_only_on_a_terminal_after_the_delay(monkeypatch: pytest.MonkeyPatch) -> None:
    from physai_lint import progress as progress_mod

    piped = FakeTTY(False)
    bar = progress_mod.Progress.start(True, piped)
    monkeypatch.setattr(progress_mod, "DELAY_S", 0.0)
    bar.stage("parsing", 3)
    bar.advance()
    bar.stop()
    assert piped.getvalue() == ""

    quick = FakeTTY(True)
    monkeypatch.setattr(progress_mod, "DELAY_S", 3600.0)
    bar = progress_mod.Progress.start(True, quick)
    bar.stage("parsing", 3)
    bar.advance()
    bar.stop()
    assert quick.getvalue() == ""  # a run shorter than the delay shows nothing

    slow = FakeTTY(True)
    monkeypatch.setattr(progress_mod, "DELAY_S", 0.0)
    bar = progress_mod.Progress.start(True, slow)
    bar.stage("parsing", 3)
    bar.advance()
    bar.stop()
    assert "parsing" in slow.getvalue()
