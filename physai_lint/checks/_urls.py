"""String parameter values, and the resource URLs among them (``package://pkg/path``,
``file:///path``) that nodes resolve themselves: camera_info_manager's ``camera_info_url``
(``CameraInfoManager::loadCalibration``), resource_retriever's mesh and file resources.

Shared by U101 (the package of a ``package://`` URL), U104 (the file a URL names) and P114 (a
``camera_info_url`` that is no URL camera_info_manager reads)."""
from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass
from typing import Any

from physai_lint.checks._util import run_memo
from physai_lint.checks.base import CheckContext
from physai_lint.model.span import Span
from physai_lint.resolve.model import ResolvedParamDict, ResolvedParamFile


@dataclass(frozen=True)
class ParamString:
    """A string a parameter is set to (or an item of a list of strings), where it is written."""

    value: str
    span: Span
    name: str  # the parameter's name ("a.b" for nested keys)
    whose: str  # 'of /camera' (a launch file gives it), 'for "/camera" in a parameter file'
    # the packages of the nodes given it: every node a launch dict reaches, for a file's block the
    # nodes whose name it matches
    packages: frozenset[str] = frozenset()
    item: bool = False  # an item of a list

    @property
    def base(self) -> str:
        """The last part of the name: "camera_info_url" of "camera.camera_info_url"."""
        return self.name.rpartition(".")[2]


def _strings(value: Any, span: Span, item_spans: Any) -> Iterator[tuple[str, Span, bool]]:
    """The string values of a parameter (each item of a list) with where each is written."""
    if isinstance(value, str):
        yield value, span, False
    elif isinstance(value, list):
        spans = item_spans if item_spans and len(item_spans) == len(value) else None
        for i, item in enumerate(value):
            if isinstance(item, str):
                yield item, spans[i] if spans else span, True


def parameter_strings(ctx: CheckContext) -> list[ParamString]:
    """Every string parameter value a launch file gives a node (a dict, ``<param>``,
    ``SetParameter``), then the ones in parameter files that the rules read there (not a file a
    substitution rewrites: its source is one of them): URLs and ``camera_info_url`` values (a
    parameter file holds no path into the install space, which launch builds); each (position,
    value) once. Listed once per run (U101, U104, P114)."""
    return run_memo(ctx.options, "_param_strings", ctx.launches, lambda: _parameter_strings(ctx))


def _parameter_strings(ctx: CheckContext) -> list[ParamString]:
    given: dict[tuple[Span, str], tuple[str, str, set[str], bool]] = {}
    loaders: dict[str, list[Any]] = {}  # parameter file -> the nodes loading it
    for launch in ctx.launches:
        for node in launch.nodes:
            for source in node.param_sources:
                if isinstance(source, ResolvedParamFile):
                    for path in {source.source, source.derived_from} - {None}:
                        loaders.setdefault(path, []).append(node)  # type: ignore[index]
                    continue
                if not isinstance(source, ResolvedParamDict):
                    continue
                for rp in source.params:
                    for value, span, item in _strings(rp.value, rp.span, rp.item_spans):
                        entry = given.setdefault((span, value), (rp.name, f"of {node.fqn or node.executable}",
                                                                 set(), item))
                        if node.package:
                            entry[2].add(node.package)
    out = [ParamString(value, span, name, whose, frozenset(pkgs), item)
           for (span, value), (name, whose, pkgs, item) in given.items()]
    seen = set(given)
    for path in sorted(ctx.param_files):
        model = ctx.param_files[path]
        users = [(n, _blocks_reaching(n, model)) for n in loaders.get(path, ())]
        for block in model.blocks:
            pkgs = frozenset(n.package for n, reached in users if n.package and id(block) in reached)
            for prm in block.params:
                for value, span, item in _strings(prm.value, prm.value_span, prm.item_spans):
                    if "://" not in value[:11] and not prm.name.endswith("camera_info_url"):
                        continue
                    if (span, value) not in seen:
                        seen.add((span, value))
                        out.append(ParamString(value, span, prm.name, f'for "{block.key}" in a parameter file',
                                               pkgs, item))
    return out


def _blocks_reaching(node: Any, model: Any) -> set[int]:
    """The blocks of a parameter file that give ``node`` its parameters (by ``id``); none when
    its name is not known."""
    from physai_lint.params.effective import matching_keys
    from physai_lint.params.match import file_key_name

    fqn = file_key_name(node)
    return set() if fqn is None else {id(b) for b in matching_keys(fqn, model, node.kind == "composable_node")}


def package_url(value: str) -> tuple[str, str] | None:
    """(package, path inside its share directory) of a ``package://<package>/<path>`` URL, as
    camera_info_manager (``parseURL``: the scheme in any case, a non-empty name, something after
    its "/") and resource_retriever read it; None for anything else, and for a package name
    holding "$" (an unexpanded substitution). The path may hold camera_info_manager's
    ``${NAME}``: it is not known here."""
    if value[:10].lower() != "package://":
        return None
    pkg, slash, rel = value[10:].partition("/")
    if not pkg or not slash or not rel or "$" in pkg:
        return None
    return pkg, rel


def file_url_path(value: str) -> str | None:
    """The absolute path of a ``file:///<path>`` URL (camera_info_manager reads the text after
    "file://"), None for anything else or a URL holding "$"."""
    if value[:8].lower() != "file:///" or "$" in value:
        return None
    return value[7:]

