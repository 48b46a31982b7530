"""Where the shipped data folders are: inside an installed wheel they sit beside the package
(``physai_lint/_rules``, ``physai_lint/_schemas``); in a source checkout or an editable install
they are the top-level ``rules/`` and ``schemas/`` folders."""
from __future__ import annotations

from pathlib import Path

_PACKAGE = Path(__file__).resolve().parent
_CHECKOUT = {"_rules": "rules", "_schemas": "schemas"}


def data_dir(name: str) -> Path:
    """The folder of ``physai_lint.<name>`` package data (``_rules`` or ``_schemas``)."""
    installed = _PACKAGE / name
    if installed.is_dir():
        return installed
    return _PACKAGE.parent / _CHECKOUT[name]
