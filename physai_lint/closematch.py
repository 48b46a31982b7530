"""``difflib.get_close_matches`` with the same answers, faster on the long candidate lists of a
large workspace (thousands of package names, hundreds of topics)."""
from __future__ import annotations

import difflib
import functools
import heapq

# From this many candidates, the longest-common-subsequence bound of every candidate is computed
# at once (``_Lanes``); below it, one candidate at a time (building the lanes costs more).
LANES_FROM = 256


@functools.lru_cache(maxsize=4096)
def close_matches(name: str, candidates: tuple[str, ...], n: int, cutoff: float) -> tuple[str, ...]:
    """``difflib.get_close_matches(name, candidates, n, cutoff)``, the same list, faster.

    Memoised: the same unknown name is looked up against the same few thousand package names once
    per reference. Before the full ``ratio()`` (the costliest step of a run on a large workspace),
    a candidate must pass a tighter upper bound than difflib's ``quick_ratio()``: the matching
    blocks ``ratio()`` counts form a common subsequence, so ``2 * LCS / total`` bounds it; the LCS
    length comes from the bit-parallel algorithm (Hyyrö 2004). It leaves about 1 in 20 of the
    candidates that pass ``quick_ratio()``.
    """
    size = len(name)
    lanes = _lanes(candidates) if len(candidates) >= LANES_FROM else None
    if lanes is not None:
        # (the LCS is at most the shorter length: the length bound below adds nothing here)
        hopeful = [x for x, common, length in zip(candidates, lanes.lcs(name), lanes.lengths)
                   if not (length + size and 2.0 * common / (length + size) < cutoff)]
    else:
        masks: dict[str, int] = {}
        for i, ch in enumerate(name):
            masks[ch] = masks.get(ch, 0) | (1 << i)
        full = (1 << size) - 1
        hopeful = []
        for x in candidates:
            total = len(x) + size
            # difflib's real_quick_ratio() and quick_ratio() bound ratio() less tightly than this.
            if total and (2.0 * min(len(x), size) / total < cutoff or
                          2.0 * _lcs_length(x, masks, full, size) / total < cutoff):
                continue
            hopeful.append(x)
    matcher = difflib.SequenceMatcher()
    matcher.set_seq2(name)
    scored = []
    for x in hopeful:
        matcher.set_seq1(x)
        ratio = matcher.ratio()
        if ratio >= cutoff:
            scored.append((ratio, x))
    return tuple(x for _, x in heapq.nlargest(n, scored))


def _lcs_length(a: str, masks: dict[str, int], full: int, n: int) -> int:
    """Length of the longest common subsequence of ``a`` and the word whose character bit masks
    (bit i set where the word has that character) are ``masks``; ``full`` has its ``n`` bits."""
    v = full
    for ch in a:
        u = v & masks.get(ch, 0)
        v = ((v + u) | (v - u)) & full
    return n - v.bit_count()


class _Lanes:
    """The same bit-parallel LCS with every candidate at once: the candidates side by side in one
    integer, each in a lane of its own length (bit ``off + i`` for its character ``i``) followed by
    a guard bit, and the name's characters run over them. A carry out of a lane stops in its guard
    bit (0 in both operands), which the mask then clears; ``v - u`` never borrows (``u`` is a subset
    of ``v``). So each lane evolves as the one-candidate loop would, in a few operations on one
    large integer per character of the name instead of a loop per candidate."""

    def __init__(self, candidates: tuple[str, ...]) -> None:
        joined = "".join(x + "\0" for x in candidates)  # "\0": the guard after each candidate
        self.size = len(joined)
        self.offsets: list[int] = []
        off = 0
        for x in candidates:
            self.offsets.append(off)
            off += len(x) + 1
        self.lengths = [len(x) for x in candidates]
        reverse = joined[::-1].encode("ascii")  # int(s, 2) reads the first one as the highest bit
        self.masks: dict[str, int] = {}
        for code in set(reverse) - {0}:
            table = bytearray(b"0" * 256)
            table[code] = ord("1")
            self.masks[chr(code)] = int(reverse.translate(table), 2)
        table = bytearray(b"1" * 256)
        table[0] = ord("0")
        self.full = int(reverse.translate(table) or b"0", 2)

    def lcs(self, name: str) -> list[int]:
        """The LCS length of ``name`` with every candidate, in order."""
        full, masks = self.full, self.masks
        v = full
        for ch in name:
            m = masks.get(ch)
            if m is not None:
                u = v & m
                v = ((v + u) | (v - u)) & full
        bits = format(v, "b").zfill(self.size)[::-1]  # bits[p]: bit p
        count = bits.count
        return [n - count("1", off, off + n) for off, n in zip(self.offsets, self.lengths)]


@functools.lru_cache(maxsize=4)
def _lanes(candidates: tuple[str, ...]) -> _Lanes | None:
    """The lanes of an ASCII candidate list (package and topic names are); None otherwise."""
    if not all(x.isascii() and "\0" not in x for x in candidates):
        return None
    return _Lanes(candidates)
