"""The disk cache keeps itself bounded: other generations' entries go after a week, everything
beyond the size limit goes oldest first, and nothing it did not write is ever touched."""
from __future__ import annotations

import os
import tempfile
import time
from pathlib import Path

import pytest

from physai_lint.cache import PRUNE_EVERY, STALE_AFTER, TMP_STALE, ParseCache

NOW = 2_000_000_000.0
DAY = 24 * 3600


def entry(folder: Path, name: str = "ab", age: float = 0.0, size: int = 10, stem: str = "c") -> Path:
    """A file named as the cache names its entries, written ``age`` seconds before NOW."""
    shard = folder / name
    shard.mkdir(parents=True, exist_ok=True)
    path = shard / (stem * 62 + ".pickle")
    path.write_bytes(b"x" * size)
    os.utime(path, (NOW - age, NOW - age))
    return path


@pytest.fixture()
def cache(tmp_path: Path) -> ParseCache:
    return ParseCache(str(tmp_path / "cache"), fingerprint=b"\x01" * 32)


def test_entries_live_in_a_folder_of_their_generation(cache: ParseCache) -> None:
    key = cache.key("launch", "/a.launch.py", "text")
    cache.put(key, {"value": 1})
    written = list(Path(cache.root).rglob("*.pickle"))
    assert [p.relative_to(cache.root).parts[0] for p in written] == ["v2-" + "01" * 8]
    assert cache.get(key) == {"value": 1}
    other = ParseCache(cache.root, fingerprint=b"\x02" * 32)  # other code: another folder, a miss
    assert other.get(other.key("launch", "/a.launch.py", "text")) is None


def test_other_generations_go_after_a_week_and_this_one_stays(cache: ParseCache) -> None:
    root = Path(cache.root)
    mine_old = entry(Path(cache.directory), age=30 * DAY)
    foreign_old = entry(root / ("v2-" + "02" * 8), age=STALE_AFTER + 60)
    foreign_young = entry(root / ("v2-" + "03" * 8), age=DAY)
    flat_old = entry(root, name="cd", age=STALE_AFTER + 60)  # format 1: no generation folder
    flat_young = entry(root, name="ce", age=60)

    assert cache.prune(now=NOW) == 2
    assert mine_old.exists() and foreign_young.exists() and flat_young.exists()
    assert not foreign_old.exists() and not flat_old.exists()
    # the folders they left empty go too; the others stay
    assert not (root / ("v2-" + "02" * 8)).exists() and not (root / "cd").exists()
    assert (root / ("v2-" + "03" * 8) / "ab").is_dir()


def test_beyond_the_size_limit_the_oldest_entries_go(cache: ParseCache,
                                                     monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("PHYSAI_LINT_CACHE_MAX_MB", "1")
    folder = Path(cache.directory)
    # ten entries of 200 KiB (2 MB in all), entry 0 the oldest
    paths = [entry(folder, name=f"{i:02x}", age=(10 - i) * 60, size=200 * 1024) for i in range(10)]
    removed = cache.prune(now=NOW)
    left = [p for p in paths if p.exists()]
    assert removed == len(paths) - len(left)
    assert left == paths[-len(left):]  # the newest stay
    each = paths[-1].stat().st_blocks * 512 or paths[-1].stat().st_size  # what one takes on disk
    assert len(left) == (2**20 * 4 // 5) // each  # as many of the newest as fit in four fifths


def test_a_bad_size_limit_falls_back_to_the_default(cache: ParseCache,
                                                    monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("PHYSAI_LINT_CACHE_MAX_MB", "lots")
    kept = entry(Path(cache.directory), size=4096)
    assert cache.prune(now=NOW) == 0
    assert kept.exists()


def test_interrupted_writes_go_but_writes_in_progress_stay(cache: ParseCache) -> None:
    shard = Path(cache.directory) / "ab"
    shard.mkdir(parents=True)
    old, fresh = shard / ".tmp-old", shard / ".tmp-fresh"
    for path, age in ((old, TMP_STALE + 60), (fresh, 5)):
        path.write_bytes(b"partial")
        os.utime(path, (NOW - age, NOW - age))
    assert cache.prune(now=NOW) == 1
    assert not old.exists() and fresh.exists()


def test_nothing_the_cache_did_not_write_is_touched(cache: ParseCache, tmp_path: Path,
                                                    monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("PHYSAI_LINT_CACHE_MAX_MB", "0")  # everything of ours must go
    root = Path(cache.root)
    ours = entry(Path(cache.directory), age=STALE_AFTER * 2)
    notes = root / "notes.txt"
    odd_name = root / "ab" / "mine.pickle"
    odd_dir = root / "zz" / ("c" * 62 + ".pickle")
    odd_gen = root / "v2-backup" / "ab" / ("c" * 62 + ".pickle")
    outside = tmp_path / "elsewhere"
    kept = [notes, odd_name, odd_dir, odd_gen, outside / ("c" * 62 + ".pickle")]
    for path in kept:
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_bytes(b"keep")
        os.utime(path, (NOW - STALE_AFTER * 2, NOW - STALE_AFTER * 2))
    (root / "ef").symlink_to(outside, target_is_directory=True)  # a shard that is a link

    assert cache.prune(now=NOW) == 1
    assert not ours.exists()
    assert all(p.exists() for p in kept)
    assert (root / "ef").is_symlink()


def test_a_directory_is_pruned_at_most_once_a_day(cache: ParseCache) -> None:
    folder = Path(cache.root) / ("v2-" + "02" * 8)
    first = entry(folder, name="aa", age=STALE_AFTER + 60)
    assert cache.prune(now=NOW) == 1
    assert (Path(cache.root) / ".last-prune").stat().st_mtime == NOW
    second = entry(folder, name="ab", age=STALE_AFTER + 60)
    assert cache.prune(now=NOW + PRUNE_EVERY - 60) == 0
    assert second.exists()
    assert cache.prune(now=NOW + PRUNE_EVERY + 60) == 1
    assert not first.exists() and not second.exists()
    assert cache.prune(now=NOW + PRUNE_EVERY + 120, force=True) == 0


def test_a_missing_or_unusable_directory_is_not_an_error(tmp_path: Path) -> None:
    missing = ParseCache(str(tmp_path / "nowhere"))
    assert missing.prune() == 0
    assert not (tmp_path / "nowhere").exists()  # nothing created for nothing
    a_file = tmp_path / "file"
    a_file.write_text("not a folder")
    assert ParseCache(str(a_file)).prune() == 0
    assert a_file.read_text() == "not a folder"


def test_opening_the_cache_prunes_it(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    root = tmp_path / "cache"
    old = entry(root / ("v2-" + "02" * 8))
    weeks_ago = time.time() - STALE_AFTER - 60
    os.utime(old, (weeks_ago, weeks_ago))
    monkeypatch.setenv("PHYSAI_LINT_CACHE_DIR", str(root))
    opened = ParseCache.open()
    assert opened is not None and opened.root == str(root)
    assert not old.exists()
    assert ParseCache.open(enabled=False) is None


def test_a_write_survives_its_folder_being_pruned_meanwhile(cache: ParseCache,
                                                             monkeypatch: pytest.MonkeyPatch) -> None:
    real_mkstemp = tempfile.mkstemp
    calls = []

    def racing_mkstemp(*args: object, **kwargs: object) -> tuple[int, str]:
        calls.append(kwargs.get("dir"))
        if len(calls) == 1:  # another run's prune removes the empty folder just now
            os.rmdir(str(kwargs["dir"]))
        return real_mkstemp(*args, **kwargs)  # type: ignore[arg-type]

    monkeypatch.setattr(tempfile, "mkstemp", racing_mkstemp)
    key = cache.key("launch", "/a.launch.py", "text")
    cache.put(key, [1, 2])
    assert len(calls) == 2 and cache.enabled
    assert cache.get(key) == [1, 2]
