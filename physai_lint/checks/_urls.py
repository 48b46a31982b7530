"""String parameter values, and the resource URLs among them (``package://pkg/path``,
``file:///path``) that nodes resolve themselves: camera_info_manager's ``camera_info_url``
(``CameraInfoManager::loadCalibration``), resource_retriever's mesh and file resources.

Shared by U101 (the package of a ``package://`` URL), U104 (the file a URL names) and P114 (a
``camera_info_url`` that is no URL camera_info_manager reads)."""
from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass
from typing import Any

from physai_lint.checks.base import CheckContext
from physai_lint.model.span import Span
from physai_lint.resolve.model import ResolvedParam, ResolvedParamDict, ResolvedParamFile


@dataclass(frozen=True)
class ParamString:
    """A string a parameter is set to (or an item of a list of strings), where it is written."""

    value: str
    span: Span
    name: str  # the parameter's name ("a.b" for nested keys)
    whose: str  # 'of /camera' (a launch file gives it), 'for "/camera" in a parameter file'
    packages: frozenset[str] = frozenset()  # of the nodes given it (for a file: the nodes loading it)

    @property
    def base(self) -> str:
        """The last part of the name: "camera_info_url" of "camera.camera_info_url"."""
        return self.name.rpartition(".")[2]


def path_values(rp: ResolvedParam) -> Iterator[tuple[str, Span]]:
    """The string values of a parameter (each item of a list) with where each is written."""
    yield from _strings(rp.value, rp.span, rp.item_spans)


def _strings(value: Any, span: Span, item_spans: Any) -> Iterator[tuple[str, Span]]:
    if isinstance(value, str):
        yield value, span
    elif isinstance(value, list):
        spans = item_spans if item_spans and len(item_spans) == len(value) else None
        for i, item in enumerate(value):
            if isinstance(item, str):
                yield item, spans[i] if spans else span


def parameter_strings(ctx: CheckContext) -> Iterator[ParamString]:
    """Every string parameter value a launch file gives a node (a dict, ``<param>``,
    ``SetParameter``), then every one in a parameter file (not a file a substitution rewrites: its
    source is one of them), each (position, value) once."""
    seen: set[tuple[Span, str]] = set()
    loaders: dict[str, set[str]] = {}  # parameter file -> packages of the nodes loading it
    for launch in ctx.launches:
        for node in launch.nodes:
            for source in node.param_sources:
                if isinstance(source, ResolvedParamFile):
                    for path in (source.source, source.derived_from):
                        if path and node.package:
                            loaders.setdefault(path, set()).add(node.package)
                if not isinstance(source, ResolvedParamDict):
                    continue
                for rp in source.params:
                    for value, span in path_values(rp):
                        if (span, value) not in seen:
                            seen.add((span, value))
                            yield ParamString(value, span, rp.name, f"of {node.fqn or node.executable}",
                                              frozenset({node.package} if node.package else ()))
    for path in sorted(ctx.param_files):
        users = frozenset(loaders.get(path, ()))
        for block in ctx.param_files[path].blocks:
            for prm in block.params:
                for value, span in _strings(prm.value, prm.value_span, prm.item_spans):
                    if (span, value) not in seen:
                        seen.add((span, value))
                        yield ParamString(value, span, prm.name, f'for "{block.key}" in a parameter file', users)


def package_url(value: str) -> tuple[str, str] | None:
    """(package, path inside its share directory) of a ``package://<package>/<path>`` URL, as
    camera_info_manager (``parseURL``: the scheme in any case, a non-empty name, something after
    its "/") and resource_retriever read it; None for anything else, and for a URL holding "$"
    (camera_info_manager's ``${NAME}``, an unexpanded substitution): its text is not yet known."""
    if value[:10].lower() != "package://" or "$" in value:
        return None
    pkg, slash, rel = value[10:].partition("/")
    if not pkg or not slash or not rel:
        return None
    return pkg, rel


def file_url_path(value: str) -> str | None:
    """The absolute path of a ``file:///<path>`` URL (camera_info_manager reads the text after
    "file://"), None for anything else or a URL holding "$"."""
    if value[:8].lower() != "file:///" or "$" in value:
        return None
    return value[7:]

