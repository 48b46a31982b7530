"""Workspace access: discovery of launch/parameter files and the ``PackageIndex`` (workspace
packages read statically, ``AMENT_PREFIX_PATH`` prefixes, released distro packages, the virtual
install space). The only module that reads the filesystem besides the engine's file loader."""
from __future__ import annotations

from ._model import BuildInfo, InstallRule
from .discovery import (
    Discovery,
    UsageError,
    discover,
    find_workspace_root,
    is_launch_file,
)
from .distro import DISTROS, released_packages
from .index import (
    Located,
    PackageIndex,
    WorkspacePackage,
    build_package_index,
    read_text_file,
)

__all__ = [
    "DISTROS",
    "BuildInfo",
    "Discovery",
    "InstallRule",
    "Located",
    "PackageIndex",
    "UsageError",
    "WorkspacePackage",
    "build_package_index",
    "discover",
    "find_workspace_root",
    "is_launch_file",
    "read_text_file",
    "released_packages",
]
