import os
import shutil
import sys

import pytest

# tests run without an install
sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))))

FIXTURES = os.path.join(os.path.dirname(os.path.abspath(__file__)), "fixtures")


@pytest.fixture
def ws(tmp_path):
    """A private copy of fixtures/ws1 (so the repository's own .gitignore does not apply)."""
    dst = tmp_path / "ws"
    shutil.copytree(os.path.join(FIXTURES, "ws1"), dst, symlinks=True)
    for exe in ("src/cpp_pkg/scripts/tool.py",):
        os.chmod(dst / exe, 0o755)
    return dst
