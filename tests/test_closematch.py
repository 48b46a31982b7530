"""close_matches is difflib.get_close_matches, answer for answer (it only skips hopeless candidates)."""
import difflib

from hypothesis import given, settings
from hypothesis import strategies as st

from physai_lint.closematch import close_matches

_WORDS = st.text(alphabet="abcde_/", min_size=0, max_size=12)


@settings(max_examples=400, deadline=None)
@given(_WORDS, st.lists(_WORDS, max_size=30), st.integers(1, 4), st.sampled_from([0.0, 0.3, 0.6, 0.7, 0.9, 1.0]))
def test_same_as_difflib(name: str, candidates: list[str], n: int, cutoff: float) -> None:
    pool = tuple(sorted(set(candidates)))
    assert list(close_matches(name, pool, n, cutoff)) == difflib.get_close_matches(name, pool, n, cutoff)


def test_topic_names() -> None:
    pool = ("/cmd_vel", "/odom", "/scan", "/robot/cmd_vel", "/tf", "/tf_static")
    assert list(close_matches("/cmd_vels", pool, 3, 0.6)) == difflib.get_close_matches("/cmd_vels", pool, 3, 0.6)


@settings(max_examples=400, deadline=None)
@given(_WORDS, st.lists(_WORDS, max_size=30), st.integers(1, 4), st.sampled_from([0.0, 0.3, 0.6, 0.7, 0.9, 1.0]))
def test_lanes_same_as_difflib(name: str, candidates: list[str], n: int, cutoff: float) -> None:
    # every candidate's LCS bound at once (the path of long lists), on short lists
    from physai_lint import closematch

    pool = tuple(sorted(set(candidates)))
    lanes = closematch._Lanes(pool)
    assert lanes.lcs(name) == [closematch._lcs_length(x, *_masks(name)) for x in pool]
    old = closematch.LANES_FROM
    closematch.LANES_FROM = 0
    try:
        closematch.close_matches.cache_clear()
        assert list(close_matches(name, pool, n, cutoff)) == difflib.get_close_matches(name, pool, n, cutoff)
    finally:
        closematch.LANES_FROM = old
        closematch.close_matches.cache_clear()


def _masks(name: str) -> tuple[dict[str, int], int, int]:
    masks: dict[str, int] = {}
    for i, ch in enumerate(name):
        masks[ch] = masks.get(ch, 0) | (1 << i)
    return masks, (1 << len(name)) - 1, len(name)


def test_long_lists_and_non_ascii_candidates() -> None:
    pool = tuple(sorted({f"pkg_{i}_{c}" for i in range(150) for c in "ab"} | {"päckage", "package"}))
    for name in ("pkg_7_c", "packag", "päck", "zzz"):
        assert list(close_matches(name, pool, 3, 0.6)) == difflib.get_close_matches(name, pool, 3, 0.6)
