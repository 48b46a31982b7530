"""``bounded_read.read_at_most``: a size limit without allocating the limit."""
from __future__ import annotations

import io
import os
import tracemalloc

import pytest

from physai_lint.bounded_read import read_at_most


def test_read_at_most_reads_small_files_whole_and_marks_large_ones(tmp_path):
    small = tmp_path / "small.yaml"
    small.write_bytes(b"a: 1\n")
    big = tmp_path / "big.yaml"
    big.write_bytes(b"x" * 100)
    with open(small, "rb") as fh:
        assert read_at_most(fh, 64) == b"a: 1\n"
    with open(big, "rb") as fh:
        assert read_at_most(fh, 64) == b"x" * 65  # one over: the caller reports it as too large
    assert read_at_most(io.BytesIO(b"y" * 10), 4) == b"yyyyy"  # no file descriptor


def test_read_at_most_allocates_the_file_not_the_limit(tmp_path):
    path = tmp_path / "a.launch.xml"
    path.write_bytes(b"<launch/>\n")
    tracemalloc.start()
    try:
        with open(path, "rb") as fh:
            assert read_at_most(fh, 50 * 1024 * 1024) == b"<launch/>\n"
        _, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    assert peak < 1024 * 1024


@pytest.mark.skipif(not os.path.exists("/proc/self/status"), reason="a file that reports no size")
def test_read_at_most_reads_on_past_a_size_that_says_nothing():
    with open("/proc/self/status", "rb") as fh:
        data = read_at_most(fh, 1 << 20)
    assert data.startswith(b"Name:") and b"VmRSS" in data
