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
