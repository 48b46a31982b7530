"""Frontends: pure functions from (path, text) to the launch IR plus parse diagnostics."""
from __future__ import annotations

from dataclasses import dataclass, field

from physai_lint.model.findings import Diagnostic
from physai_lint.model.launch import LaunchFile


@dataclass
class FrontendResult:
    launch: LaunchFile | None
    diagnostics: list[Diagnostic] = field(default_factory=list)
