"""Released ROS 2 packages per distro, from the rosdistro snapshot shipped in ``physai_lint/data``
(see its ``_source`` entry for the commit), and the names the launch packages' public modules
export per distro. Loaded lazily, once per process."""
from __future__ import annotations

import json
import os
from functools import lru_cache

DISTROS = ("humble", "jazzy", "kilted", "lyrical", "rolling")
_DATA_DIR = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "data")
_DATA = os.path.join(_DATA_DIR, "rosdistro-packages.json")


@lru_cache(maxsize=1)
def _load() -> dict[str, frozenset[str]]:
    with open(_DATA, encoding="utf-8") as fh:
        raw = json.load(fh)
    return {k: frozenset(v) for k, v in raw.items() if k in DISTROS}


def released_packages(distro: str) -> frozenset[str]:
    """Package names released in ``distro`` (one of ``DISTROS``; ValueError otherwise)."""
    if distro not in DISTROS:
        raise ValueError(f"unknown ROS 2 distro {distro!r} (expected one of {', '.join(DISTROS)})")
    return _load()[distro]


def released_in(name: str) -> tuple[str, ...]:
    """The distros (of ``DISTROS``, in that order) that release package ``name``."""
    return tuple(d for d in DISTROS if name in _load()[d])


def source_commit() -> str:
    with open(_DATA, encoding="utf-8") as fh:
        return str(json.load(fh)["_source"]["commit"])


@lru_cache(maxsize=1)
def launch_exports() -> dict[str, dict[str, frozenset[str]]]:
    """distro -> public launch / launch_ros module -> the names ``from <module> import`` finds
    (``launch-exports.json``: humble, jazzy, rolling)."""
    with open(os.path.join(_DATA_DIR, "launch-exports.json"), encoding="utf-8") as fh:
        raw = json.load(fh)
    return {d: {m: frozenset(n) for m, n in t.items()} for d, t in raw.items() if not d.startswith("_")}
