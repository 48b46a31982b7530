"""``InterfaceStore``: what each ``(package, executable)`` declares, merged from (highest first)

1. ``--interfaces`` files (contracts/README.md format),
2. generate_parameter_library YAML linked to the executable (``packages.parameter_yaml_for``),
3. extraction from the workspace sources (``packages.source_files_for``, when the index has it),
4. the bundled declarations in ``schemas/`` for well-known packages.

Per endpoint category the highest source that lists it wins; parameters merge per name (higher
sources win) and are complete when a complete source (gpl, a complete bundled file, an interfaces
entry with ``parameters_complete: true``) provides them.
"""
from __future__ import annotations

import json
from pathlib import Path
from typing import Any, Iterable, Protocol

import yaml

from physai_lint.model.findings import Diagnostic
from physai_lint.model.span import Span

from .extract_py import extract_py
from .gpl import _span as node_span
from .gpl import compose, normalize_type, parse_gpl, to_python
from .linked import extract_linked
from .model import ENDPOINT_KINDS, Endpoint, NodeInterface, ParamDecl


class PackageIndexLike(Protocol):
    def parameter_yaml_for(self, package: str, executable: str) -> list[str]: ...
    def read_text(self, path: str) -> str | None: ...


Key = tuple[str, str]
_CPP = (".cpp", ".cc", ".cxx", ".hpp", ".h", ".hh")


def _schemas_dir() -> Path | None:
    from physai_lint.resources import data_dir

    d = data_dir("_schemas")
    return d if d.is_dir() else None


# ---- interfaces files -------------------------------------------------------------------------

def _endpoints(node: yaml.Node, path: str, diags: list[Diagnostic]) -> list[Endpoint] | None:
    if isinstance(node, yaml.ScalarNode) and node.value in ("", "~", "null"):
        return []
    if not isinstance(node, yaml.SequenceNode):
        diags.append(Diagnostic("P104", node_span(path, node),
                                "expected a list of names or of {name, type}"))
        return None
    out: list[Endpoint] = []
    for item in node.value:
        if isinstance(item, yaml.ScalarNode):
            out.append(Endpoint(item.value, None, node_span(path, item)))
        elif isinstance(item, yaml.MappingNode):
            fields = {k.value: v for k, v in item.value if isinstance(k, yaml.ScalarNode)}
            name = fields.get("name")
            if not isinstance(name, yaml.ScalarNode):
                diags.append(Diagnostic("P104", node_span(path, item), "endpoint without a name"))
                continue
            t = fields.get("type")
            when = fields.get("when")
            conditions: tuple[tuple[str, Any], ...] = ()
            if isinstance(when, yaml.MappingNode):
                conditions = tuple(sorted((str(k.value), to_python(c)) for k, c in when.value
                                          if isinstance(k, yaml.ScalarNode) and isinstance(c, yaml.ScalarNode)))
            if when is not None and (not isinstance(when, yaml.MappingNode) or len(conditions) != len(when.value)):
                diags.append(Diagnostic("P104", node_span(path, when), "when maps parameter names to plain values"))
            out.append(Endpoint(name.value, t.value if isinstance(t, yaml.ScalarNode) else None,
                                node_span(path, name), conditions))
        else:
            diags.append(Diagnostic("P104", node_span(path, item), "expected a name"))
    return out


def _param_decl(name: str, node: yaml.Node, key: yaml.Node, path: str,
                diags: list[Diagnostic]) -> ParamDecl:
    decl = ParamDecl(name, span=node_span(path, key), source=path)
    if not isinstance(node, yaml.MappingNode):
        if isinstance(node, yaml.ScalarNode):
            decl.type = normalize_type(node.value)
        return decl
    for k, v in node.value:
        if not isinstance(k, yaml.ScalarNode):
            continue
        val = to_python(v)
        if k.value == "type":
            decl.type = normalize_type(val)
            if decl.type is None:
                diags.append(Diagnostic("P104", node_span(path, v), f"unknown parameter type {val!r}"))
        elif k.value in ("default", "default_value"):
            decl.default, decl.has_default = val, True
        elif k.value == "min":
            decl.min = val
        elif k.value == "max":
            decl.max = val
        elif k.value in ("choices", "one_of"):
            decl.choices = list(val) if isinstance(val, list) else None
        elif k.value == "read_only":
            decl.read_only = bool(val)
        elif k.value == "description":
            decl.description = str(val)
        elif k.value in ("validation", "validators") and isinstance(val, dict):
            decl.validators = [(str(n)[:-2] if str(n).endswith("<>") else str(n),
                                a if isinstance(a, list) else [a]) for n, a in val.items()]
    return decl


def parse_interfaces_file(path: str, text: str) -> tuple[dict[Key, NodeInterface], list[Diagnostic]]:
    """Parse an interfaces file (``"<package>/<executable>": {publishers: [...], ...}``)."""
    root, diags = compose(path, text)
    out: dict[Key, NodeInterface] = {}
    if root is None:
        return out, diags
    if isinstance(root, yaml.ScalarNode) and root.value == "":
        return out, diags
    if not isinstance(root, yaml.MappingNode):
        diags.append(Diagnostic("P104", node_span(path, root),
                                "an interfaces file maps \"<package>/<executable>\" to declarations"))
        return out, diags
    for k, v in root.value:
        if not isinstance(k, yaml.ScalarNode) or "/" not in k.value:
            diags.append(Diagnostic("P104", node_span(path, k),
                                    "keys must be \"<package>/<executable>\""))
            continue
        pkg, _, exe = k.value.partition("/")
        iface = NodeInterface(source=path)
        if isinstance(v, yaml.MappingNode):
            for fk, fv in v.value:
                if not isinstance(fk, yaml.ScalarNode):
                    continue
                field = fk.value
                if field in ENDPOINT_KINDS:
                    setattr(iface, field, _endpoints(fv, path, diags))
                elif field == "parameters":
                    if isinstance(fv, yaml.MappingNode):
                        iface.parameters = {}
                        for pk, pv in fv.value:
                            if isinstance(pk, yaml.ScalarNode):
                                iface.parameters[pk.value] = _param_decl(pk.value, pv, pk, path,
                                                                         diags)
                    elif not (isinstance(fv, yaml.ScalarNode) and fv.value in ("", "~", "null")):
                        diags.append(Diagnostic("P104", node_span(path, fv),
                                                "parameters must map names to declarations"))
                elif field == "parameters_complete":
                    iface.parameters_complete = bool(to_python(fv))
                elif field == "node_name":
                    _declared_node_name(iface, fv, path, diags)
                elif field == "lifecycle":
                    iface.lifecycle = to_python(fv) is True
                else:
                    diags.append(Diagnostic("P104", node_span(path, fk),
                                            f"unknown field \"{field}\" in an interfaces entry"))
        elif not (isinstance(v, yaml.ScalarNode) and v.value in ("", "~", "null")):
            diags.append(Diagnostic("P104", node_span(path, v), "expected a mapping"))
        out[(pkg, exe)] = iface
    return out, diags


def _declared_node_name(iface: NodeInterface, value: yaml.Node, path: str, diags: list[Diagnostic]) -> None:
    """``node_name: talker``: the name the executable gives its node when launch gives none;
    ``null`` when it cannot be told (the executable makes several nodes, or computes the name)."""
    from physai_lint.resolve.names import validate_node_name

    if isinstance(value, yaml.ScalarNode) and value.tag == "tag:yaml.org,2002:null":
        iface.node_name_decided = True
        return
    if not isinstance(value, yaml.ScalarNode) or validate_node_name(value.value):
        diags.append(Diagnostic("P104", node_span(path, value),
                                "node_name must be a valid node name (letters, digits, underscores), or null"))
        return
    iface.node_name, iface.node_name_span, iface.node_name_decided = value.value, node_span(path, value), True


def _python_script(path: str, text: str) -> bool:
    """A program without an extension whose first line runs Python (``#!/usr/bin/env python3``)."""
    return "." not in path.rsplit("/", 1)[-1] and text.startswith("#!") and "python" in text.split("\n", 1)[0]


# ---- bundled schemas ----------------------------------------------------------------------------

def _bundled_entry(data: dict[str, Any], path: str, distro: str = "humble") -> NodeInterface:
    iface = NodeInterface(source=f"bundled {data.get('upstream', path)}")
    for kind in ENDPOINT_KINDS:
        if kind in data:
            iface_list = []
            for e in data[kind] or []:
                if isinstance(e, str):
                    iface_list.append(Endpoint(e))
                elif isinstance(e, dict) and isinstance(e.get("distros"), list) and distro not in e["distros"]:
                    # named so only on other distros: here its name follows another topic's
                    # remapped name at run time (image_transport's camera_info)
                    iface.unnamed.append((kind, e.get("type")))
                elif isinstance(e, dict) and "name" in e:
                    when = e.get("when") if isinstance(e.get("when"), dict) else {}
                    iface_list.append(Endpoint(str(e["name"]), e.get("type"), None,
                                               tuple(sorted((str(k), v) for k, v in when.items()))))
            setattr(iface, kind, iface_list)
    if "parameters" in data:
        iface.parameters = {}
        for name, spec in (data["parameters"] or {}).items():
            spec = spec or {}
            decl = ParamDecl(str(name), normalize_type(spec.get("type")), spec.get("default"),
                             spec.get("min"), spec.get("max"), spec.get("choices"),
                             bool(spec.get("read_only", False)), [], spec.get("description"),
                             None, iface.source, "default" in spec,
                             bool(spec.get("dynamic_type", False)))
            iface.parameters[str(name)] = decl
    iface.parameters_complete = bool(data.get("parameters_complete", False))
    if "node_name" in data:
        name = data["node_name"]
        iface.node_name, iface.node_name_decided = (name if isinstance(name, str) else None), True
    iface.parameter_patterns = list(data.get("parameter_patterns", []) or [])
    iface.lifecycle = data.get("lifecycle") is True
    for u in data.get("unnamed") or ():  # plugins' endpoints: names known only at run time
        if isinstance(u, dict) and u.get("kind") in ENDPOINT_KINDS:
            iface.unnamed.append((u["kind"], u.get("type")))
    return iface


def load_bundled(distro: str = "humble") -> dict[Key, NodeInterface]:
    out: dict[Key, NodeInterface] = {}
    d = _schemas_dir()
    if d is None:
        return out
    for f in sorted(d.glob("*.yaml")) + sorted(d.glob("*.json")):
        if f.name == "interface.schema.json":
            continue
        try:
            text = f.read_text(encoding="utf-8")
            data = json.loads(text) if f.suffix == ".json" else yaml.load(
                text, Loader=getattr(yaml, "CSafeLoader", yaml.SafeLoader))
        except (OSError, ValueError, yaml.YAMLError):
            continue
        if not isinstance(data, dict):
            continue
        distros = data.get("distros")
        if distros and distro not in distros:
            continue
        pkg = data.get("package")
        for exe, entry in (data.get("nodes") or {}).items():
            if isinstance(entry, dict) and isinstance(pkg, str):
                out[(pkg, str(exe))] = _bundled_entry(dict(entry, upstream=data.get("upstream")),
                                                      str(f), distro)
    return out


# ---- merging ------------------------------------------------------------------------------------

def merge(layers: Iterable[NodeInterface]) -> NodeInterface | None:
    """Merge interfaces, highest priority first."""
    layers = [x for x in layers if x is not None]
    if not layers:
        return None
    out = NodeInterface(source=" + ".join(x.source for x in layers if x.source))
    for kind in ENDPOINT_KINDS:
        chosen = None
        for layer in layers:
            v = getattr(layer, kind)
            if v is not None and (v or layer.source.startswith("bundled") or
                                  not layer.source.startswith("extracted")):
                setattr(out, kind, list(v))
                chosen = layer
                break
        if chosen is None:  # no list of this kind anywhere: every layer's endpoints named at run time
            out.unnamed.extend(u for layer in layers for u in layer.unnamed if u[0] == kind)
        elif chosen.source.startswith("extracted"):  # the code's word on this kind
            out.unnamed.extend(u for layer in layers if layer.source.startswith("extracted")
                               for u in layer.unnamed if u[0] == kind)
        else:  # a declaration's: those of its endpoints named only at run time
            out.unnamed.extend(u for u in chosen.unnamed if u[0] == kind)
    params: dict[str, ParamDecl] | None = None
    complete = False
    patterns: list[str] = []
    for layer in reversed(layers):
        if layer.parameters is not None:
            params = dict(params or {})
            params.update(layer.parameters)
            complete = complete or layer.parameters_complete
        patterns.extend(p for p in layer.parameter_patterns if p not in patterns)
    out.parameters = params
    out.parameters_complete = complete and params is not None
    out.parameter_patterns = patterns
    out.lifecycle = any(layer.lifecycle for layer in layers)
    named = next((layer for layer in layers if layer.node_name_decided), None)
    if named is not None:
        out.node_name, out.node_name_span, out.node_name_decided = named.node_name, named.node_name_span, True
        out.node_namespace = named.node_namespace
    return out


class InterfaceStore:
    def __init__(self, packages: Any = None, distro: str = "humble", cache: Any = None) -> None:
        self.packages = packages
        self.distro = distro
        self.cache = cache  # a cache.ParseCache for per-file C++ extraction, or None
        self.declared: dict[Key, NodeInterface] = {}
        self.bundled: dict[Key, NodeInterface] = {}
        self.diagnostics: list[Diagnostic] = []
        self._cache: dict[Key, NodeInterface | None] = {}
        self._extracted: dict[Key, NodeInterface] = {}
        self._foreign: dict[tuple[str, str], Any] = {}  # (package, include) -> _foreign_header's

    def add_extracted(self, package: str, executable: str, files: list[tuple[str, str]],
                      library: list[tuple[str, str]] | None = None,
                      roots: list[str] | None = None) -> None:
        """Give the store the sources of an executable (the caller knows which files build it):
        its own ``files``, and the ``library`` sources a library it links brings, of which only
        the classes its own code names (or the ``roots``: a component's plugin class) run."""
        cpp = [(p, t) for p, t in files if p.endswith(_CPP)]
        lib = [(p, t) for p, t in library or () if p.endswith(_CPP)]
        py = [(p, t) for p, t in files if p.endswith(".py") or _python_script(p, t)]
        layers = []
        if cpp or lib:
            layers.append(extract_linked(cpp, lib, list(roots or ()), self.cache, self._read,
                                         self._foreign_header(package), package))
        if py:
            layers.append(extract_py(py, self._read))
        merged = merge(layers) if layers else None
        if merged is not None:
            merged.parameters_complete = False
            self._extracted[(package, executable)] = merged
            self._cache.pop((package, executable), None)

    def _gpl(self, package: str, executable: str) -> NodeInterface | None:
        fn = getattr(self.packages, "parameter_yaml_for", None)
        reader = getattr(self.packages, "read_text", None)
        if fn is None or reader is None:
            return None
        try:
            paths = list(fn(package, executable) or [])
        except Exception:  # noqa: BLE001 -- an index failure must not break linting
            return None
        if not paths:
            return None
        iface = NodeInterface(parameters={}, parameters_complete=True,
                              source="generate_parameter_library " + ", ".join(paths))
        for path in paths:
            text = reader(path)
            if text is None:
                iface.parameters_complete = False
                continue
            decls, patterns, diags = parse_gpl(path, text)
            self.diagnostics.extend(diags)
            if diags:
                iface.parameters_complete = False
            iface.parameters.update(decls)  # type: ignore[union-attr]
            iface.parameter_patterns.extend(patterns)
        return iface

    def _foreign_header(self, package: str) -> Any:
        """``linked.foreign_bases``'s ``locate`` for the executables of ``package``: a header
        ``#include "p/x.hpp"`` names in another workspace package ``p`` (under its ``include/``),
        with that package's C++ sources."""
        workspace = getattr(self.packages, "workspace_package", None)
        mine = workspace(package) if workspace is not None else None
        if mine is None:
            return None
        # a base class of another package needs that package to build: a <depend> on it, or a
        # find_package() of it (ament_cmake_auto finds the manifest's <depend>s)
        others = {n: pkg for n in (*mine.exec_depends, *mine.found_packages)
                  if n != package and (pkg := workspace(n)) is not None}
        if not others:
            return None

        def locate(include: str) -> tuple[str, str, Any] | None:
            key = (package, include)
            if key not in self._foreign:
                self._foreign[key] = find(include)
            return self._foreign[key]

        def find(include: str) -> tuple[str, str, Any] | None:
            pkg = others.get(include.split("/", 1)[0]) if "/" in include else None
            if pkg is None:
                return None
            path = f"{pkg.path}/include/{include}"
            text = self._read(path)
            if text is None:
                return None

            found: dict[str, list[tuple[str, str]]] = {}

            def sources(word: str) -> list[tuple[str, str]]:
                if word not in found:
                    found[word] = [(f"{pkg.path}/{rel}", t) for rel in sorted(pkg.files)
                                   if rel.endswith((".cpp", ".cc", ".cxx")) and not rel.startswith("test")
                                   and (t := self._read(f"{pkg.path}/{rel}")) is not None and word in t]
                return found[word]

            return path, text, sources

        return locate

    def _read(self, path: str) -> str | None:
        reader = getattr(self.packages, "read_text", None)
        return None if reader is None else reader(path)

    def _sources(self, package: str, executable: str) -> None:
        if (package, executable) in self._extracted:
            return
        parts = getattr(self.packages, "source_parts_for", None)
        fn = getattr(self.packages, "source_files_for", None)
        reader = getattr(self.packages, "read_text", None)
        if (fn is None and parts is None) or reader is None:
            return
        try:
            if parts is not None:
                own, library, roots = parts(package, executable)
            else:
                own, library, roots = list(fn(package, executable) or []), [], []  # type: ignore[misc]
        except Exception:  # noqa: BLE001
            return
        own = list(own)[:500]
        files = [(p, t) for p in own if (t := reader(p)) is not None]
        lib = [(p, t) for p in list(library)[:500 - len(own)] if (t := reader(p)) is not None]
        if files or lib:
            self.add_extracted(package, executable, files, lib, roots)

    def get(self, package: str | None, executable: str | None) -> NodeInterface | None:
        if not package or not executable:
            return None
        key = (package, executable)
        if key in self._cache:
            return self._cache[key]
        self._sources(package, executable)
        layers = [self.declared.get(key), self._gpl(package, executable),
                  self._extracted.get(key), self.bundled.get(key)]
        result = merge([x for x in layers if x is not None])
        self._cache[key] = result
        return result

    def cached(self, key: Key) -> bool:
        """Whether ``get(*key)`` has been computed (here, or taken from a helper by ``prime``)."""
        return key in self._cache

    def prime(self, key: Key, value: NodeInterface | None) -> None:
        """Take ``get(*key)`` as computed elsewhere (a forked helper: ``parallel.prefetch_interfaces``)."""
        self._cache.setdefault(key, value)

    def known(self) -> list[Key]:
        return sorted(set(self.declared) | set(self.bundled) | set(self._extracted))


def build_interface_store(interface_files: list[tuple[str, str]], packages: Any,
                          distro: str = "humble", cache: Any = None
                          ) -> tuple[InterfaceStore, list[Diagnostic]]:
    """The store; ``cache`` (a ``cache.ParseCache``, or None) keeps C++ extraction across runs."""
    store = InterfaceStore(packages, distro, cache)
    diags: list[Diagnostic] = []
    for path, text in interface_files:
        entries, d = parse_interfaces_file(path, text)
        diags.extend(d)
        for key, iface in entries.items():
            store.declared[key] = merge([iface, store.declared[key]]) if key in store.declared \
                else iface
    store.bundled = load_bundled(distro)
    store.diagnostics = diags
    return store, diags


__all__ = ["InterfaceStore", "build_interface_store", "parse_interfaces_file", "load_bundled",
           "merge", "Span"]
