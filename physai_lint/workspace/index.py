"""``PackageIndex``: every package the launch files may name -- workspace packages (read
statically from package.xml, setup.py/setup.cfg, CMakeLists.txt), packages in ``AMENT_PREFIX_PATH``
prefixes, and packages released in the chosen distro -- plus the *virtual install space*: where
``FindPackageShare`` would point after ``colcon build`` and which source file lands there."""
from __future__ import annotations

import difflib
import hashlib
import os
import posixpath
import re
import stat
from collections.abc import Collection, Iterable, Iterator, Mapping
from dataclasses import dataclass, field
from typing import Any, Literal

from physai_lint.bounded_read import read_at_most

from ._glob import compile_glob
from ._model import BuildInfo, InstallRule
from .cmake import read_cmake_package, read_listfile
from .discovery import UsageError, dir_identity, ignore_marker, skip_dir_name
from .distro import DISTROS, released_packages
from .package_xml import _NAME_RX, ManifestInfo, parse_manifest
from .setup_py import read_setup_py

Origin = Literal["workspace", "installed", "distro"]
Status = Literal["ok", "missing", "not_installed", "unknown"]

READ_LIMIT = 50 * 1024 * 1024
SNAPSHOT_LIMIT = 50_000  # files per package
RESOURCE_INDEX = "share/ament_index/resource_index"


@dataclass(frozen=True)
class Located:
    status: Status
    source: str | None = None
    package: str | None = None
    install_hint: str | None = None


@dataclass
class WorkspacePackage:
    name: str
    path: str  # the package directory (absolute, "/")
    package_xml: str
    build_type: str
    format: int
    exec_depends: dict[str, int]
    executables: frozenset[str]
    executables_in_bin: frozenset[str]
    plugins: frozenset[str]
    install_rules: tuple[InstallRule, ...]
    parameter_yamls: dict[str, tuple[str, ...]]
    parameter_modules: tuple[tuple[str, str], ...]
    # relative "/" paths of the files in the package (``PackageTree.files``; a frozenset for a
    # package built by hand)
    files: Collection[str]
    install_complete: bool = True
    executables_complete: bool = True
    registers_in_index: bool = True
    valid: bool = True  # False when catkin_pkg rejected package.xml
    dirs: Collection[str] = field(default_factory=frozenset)
    sources: dict[str, tuple[str, ...]] = field(default_factory=dict)  # executable -> sources
    # executable -> those of its sources a linked library brings; -> classes known to run in it
    library_sources: dict[str, tuple[str, ...]] = field(default_factory=dict)
    source_roots: dict[str, tuple[str, ...]] = field(default_factory=dict)
    scripts_dir: str | None = None  # setup.cfg's script_dir when it is not lib/<name>
    # CMake: commands the reader did not interpret, the packages find_package() names, and the
    # CONFIG_EXTRAS macros of this package that install something (BuildInfo)
    calls: frozenset[str] = field(default_factory=frozenset)
    found_packages: frozenset[str] = field(default_factory=frozenset)
    installers: frozenset[str] = field(default_factory=frozenset)
    # run dependencies declared under a condition that is false for the distro: -> condition
    excluded_depends: dict[str, str] = field(default_factory=dict)
    test_depends: frozenset[str] = frozenset()


def _norm(path: str) -> str:
    return posixpath.normpath(os.path.abspath(path).replace(os.sep, "/"))


class _Packages(Mapping[str, WorkspacePackage]):
    """The workspace packages by name. Names are known when the index is built; a package is read
    (catkin_pkg, CMakeLists.txt or setup.py, a file listing) the first time it is asked for, so a
    check of one launch file reads the packages it names, not all of a large workspace's."""

    def __init__(self, index: PackageIndex) -> None:
        self._index = index
        self._dirs: dict[str, str] = {}  # name -> package directory, in crawl order
        self._read: dict[str, WorkspacePackage] = {}

    def add(self, name: str, pkg_dir: str, pkg: WorkspacePackage | None = None) -> None:
        self._dirs[name] = pkg_dir
        if pkg is not None:
            self._read[name] = pkg

    def dir_of(self, name: str) -> str:
        return self._dirs[name]

    def __getitem__(self, name: str) -> WorkspacePackage:
        pkg = self._read.get(name)
        if pkg is None:
            pkg = _read_package(self._index, self._dirs[name])
            if pkg is None:  # the manifest became unreadable since the index was built
                raise KeyError(name)
            pkg.name = name
            self._read[name] = pkg
        return pkg

    def __contains__(self, name: object) -> bool:
        return name in self._dirs

    def __iter__(self) -> Iterator[str]:
        return iter(self._dirs)

    def __len__(self) -> int:
        return len(self._dirs)


class PackageIndex:
    def __init__(self, workspace_root: str, distro: str, prefixes: list[str]) -> None:
        self.workspace_root = _norm(workspace_root)
        self.install_root = self.workspace_root + "/install"
        self.distro = distro
        self.prefixes = prefixes
        self.packages = _Packages(self)
        self.installed: dict[str, str] = {}  # name -> prefix
        # packages of the workspace colcon skips (an ignore marker in their directory): name ->
        # (directory, marker); not packages of the index
        self.ignored: dict[str, tuple[str, str]] = {}
        # package.xml files colcon would reject (path, message, line): the engine reports these
        self.problems: list[tuple[str, str, int]] = []
        # what the static readers could not follow in setup.py / CMakeLists.txt (path, message,
        # line): informational, the affected package's install rules are marked incomplete
        self.notes: list[tuple[str, str, int]] = []
        self._text_cache: dict[str, str | None] = {}
        self._exists_cache: dict[str, bool] = {}
        self._isdir_cache: dict[str, bool] = {}
        self._installed_exes: dict[str, frozenset[str] | None] = {}
        self._installed_plugins: dict[str, frozenset[str] | None] = {}
        self._by_dir: dict[str, str] = {}  # source directory -> package name
        self._located: dict[str, Located] = {}
        self._names: tuple[tuple[int, int], tuple[str, ...]] | None = None  # package_names()
        # a cache.ParseCache for what one build file says (manifests, CMakeLists.txt), or None
        self.cache: Any = None

    # ---- identity -------------------------------------------------------------------------------

    def _distro_set(self) -> frozenset[str]:
        return released_packages(self.distro)

    def has_package(self, name: str) -> bool:
        return self.origin(name) is not None

    def origin(self, name: str) -> Origin | None:
        if name in self.packages:
            return "workspace"
        if name in self.installed:
            return "installed"
        if name in self._distro_set():
            return "distro"
        return None

    def workspace_package(self, name: str) -> WorkspacePackage | None:
        return self.packages.get(name)

    def package_names(self) -> tuple[str, ...]:
        """Every known package name, sorted: one tuple while the set of names stays the same (a
        suggestion for an unknown package looks through it; rebuilding it per finding was a
        sort of ~4,000 names each time)."""
        size = (len(self.packages), len(self.installed))
        if self._names is None or self._names[0] != size:
            self._names = (size, tuple(sorted(set(self.packages) | set(self.installed)
                                              | self._distro_set())))
        return self._names[1]

    def suggest(self, name: str, n: int = 3) -> list[str]:
        """Likely meant packages for an unknown name: close spellings (workspace first), then
        packages having the name as a ``_``-separated component (``move_group`` ->
        ``moveit_ros_move_group``, an executable taken for a package)."""
        out: list[str] = []
        ws = sorted(self.packages)
        others = sorted((set(self.installed) | self._distro_set()) - set(self.packages))

        def add(items: list[str]) -> None:
            out.extend(m for m in items if m not in out and m != name)

        def by_len(items: list[str]) -> list[str]:
            return sorted(items, key=lambda p: (p not in self.packages, len(p), p))

        add(difflib.get_close_matches(name, ws, n=n, cutoff=0.6))
        suffixed = by_len([p for p in ws + others if p.endswith("_" + name)]) if len(name) >= 3 else []
        if "_" in name:  # a multi-word name is more likely a component than a misspelling
            add(suffixed)
        add(difflib.get_close_matches(name, others, n=n, cutoff=0.7))
        add(suffixed)
        if len(name) >= 3:
            add(by_len([p for p in ws + others
                        if "_" + name + "_" in p or p.startswith(name + "_")]))
        return out[:n]

    def exec_depends(self, package: str) -> dict[str, int]:
        pkg = self.packages.get(package)
        return dict(pkg.exec_depends) if pkg else {}

    def test_depends(self, package: str) -> frozenset[str]:
        """What a workspace package's tests may use: its <test_depend>s (run dependencies aside)."""
        pkg = self.packages.get(package)
        return pkg.test_depends if pkg else frozenset()

    def excluded_depends(self, package: str) -> dict[str, str]:
        """Run dependencies of a workspace package that its package.xml declares under a condition
        false for this distro, with the condition."""
        pkg = self.packages.get(package)
        return dict(pkg.excluded_depends) if pkg else {}

    # ---- executables and plugins ---------------------------------------------------------------

    def executables(self, name: str) -> frozenset[str] | None:
        pkg = self.packages.get(name)
        if pkg is not None:
            return pkg.executables if pkg.executables_complete else None
        if name in self.installed:
            if name not in self._installed_exes:
                self._installed_exes[name] = _list_executables(f"{self.installed[name]}/lib/{name}")
            return self._installed_exes[name]
        return None

    def scripts_outside_lib(self, name: str) -> tuple[frozenset[str], str | None]:
        """Console scripts of a workspace ament_python package that do not go to ``lib/<package>``,
        where ``ros2 run`` and launch look, and where they go instead: the directory its setup.cfg
        names, as written, or None for ``bin/``."""
        pkg = self.packages.get(name)
        return (pkg.executables_in_bin, pkg.scripts_dir) if pkg is not None else (frozenset(), None)

    def plugins(self, name: str) -> frozenset[str] | None:
        pkg = self.packages.get(name)
        if pkg is not None:
            if pkg.build_type == "ament_python":
                return frozenset()
            return pkg.plugins if pkg.install_complete else None
        if name in self.installed:
            if name not in self._installed_plugins:
                path = f"{self.installed[name]}/{RESOURCE_INDEX}/rclcpp_components/{name}"
                text = self.read_text(path)
                if text is None:
                    self._installed_plugins[name] = None if os.path.exists(path) else frozenset()
                else:
                    self._installed_plugins[name] = frozenset(
                        ln.split(";", 1)[0].strip() for ln in text.splitlines() if ln.strip())
            return self._installed_plugins[name]
        return None

    def parameter_yaml_for(self, package: str, executable: str) -> list[str]:
        pkg = self.packages.get(package)
        if pkg is None:
            return []
        return list(pkg.parameter_yamls.get(executable, ()))

    def source_files_for(self, package: str, executable: str) -> list[str]:
        """The workspace source files an executable (or component plugin) is built from."""
        pkg = self.packages.get(package)
        if pkg is None:
            return []
        return list(pkg.sources.get(executable, ()))

    def source_parts_for(self, package: str, executable: str
                         ) -> tuple[list[str], list[str], list[str]]:
        """``source_files_for`` split: (the executable's own sources, those a library it links
        brings, the classes known to run in it: a component's plugin class)."""
        pkg = self.packages.get(package)
        if pkg is None:
            return [], [], []
        library = pkg.library_sources.get(executable, ())
        own = [p for p in pkg.sources.get(executable, ()) if p not in library]
        return own, list(library), list(pkg.source_roots.get(executable, ()))

    # ---- install space -------------------------------------------------------------------------

    def prefix_dir(self, name: str) -> str | None:
        origin = self.origin(name)
        if origin == "workspace":
            return f"{self.install_root}/{name}"
        if origin == "installed":
            return self.installed[name]
        if origin == "distro":
            return f"/opt/ros/{self.distro}"
        return None

    def share_dir(self, name: str) -> str | None:
        prefix = self.prefix_dir(name)
        return None if prefix is None else f"{prefix}/share/{name}"

    def package_of_source(self, path: str) -> WorkspacePackage | None:
        """The workspace package whose source directory holds ``path``."""
        name = self.package_name_of(path)
        return None if name is None else self.packages.get(name)

    def package_name_of(self, path: str) -> str | None:
        """The name of the workspace package whose directory holds ``path`` (the deepest), without
        reading the package."""
        return next(self._names_holding(_norm(path)), None)

    def _names_holding(self, path: str) -> Iterator[str]:
        """The packages whose directories hold ``path``, deepest first: a walk up the path (a
        dict lookup per level, instead of a scan of every package per call)."""
        while path:
            name = self._by_dir.get(path)
            if name is not None:
                yield name
            parent = posixpath.dirname(path)
            path = "" if parent == path else parent

    def read_packages_holding(self, paths: Iterable[str]) -> None:
        """Read every package whose directory holds one of ``paths`` (their manifests' problems
        are reported only then: the engine asks for those of the checked packages)."""
        for name in self.names_holding(paths):
            self.packages.get(name)

    def names_holding(self, paths: Iterable[str]) -> list[str]:
        """The names of the packages whose directories hold one of ``paths``, sorted."""
        return sorted({name for path in paths for name in self._names_holding(posixpath.dirname(_norm(path)))})

    def read_package_elsewhere(self, name: str) -> tuple[Any, list[Any], list[Any]]:
        """Read package ``name`` in a forked helper (``parallel.package_reads``): the package (None
        when unreadable) and the problems and notes its reading added, for ``adopt_package``."""
        problems, notes = len(self.problems), len(self.notes)
        pkg = self.packages.get(name)
        return pkg, self.problems[problems:], self.notes[notes:]

    def unread(self, name: str) -> bool:
        """Whether ``name`` is a workspace package that has not been read yet."""
        return name in self.packages and name not in self.packages._read

    def adopt_package(self, name: str, read: tuple[Any, list[Any], list[Any]]) -> None:
        """Take what ``read_package_elsewhere`` returned as if the package had been read here."""
        pkg, problems, notes = read
        if name in self.packages._read:
            return
        self.problems.extend(problems)
        self.notes.extend(notes)
        if pkg is not None:  # unreadable: read (and reported) again when asked, as here
            self.packages._read[name] = pkg

    def installed_copy(self, path: str) -> str | None:
        """Where the install space holds the workspace source file ``path`` (the copy ``ros2
        launch <package> <file>`` runs), or None when its package does not install it or it is
        not in a workspace package. The install rules are read backwards; each candidate is
        checked forwards (``locate``)."""
        path = _norm(path)
        pkg = self.package_of_source(path)
        if pkg is None:
            return None
        rel = path[len(pkg.path) + 1 :]
        prefix = f"{self.install_root}/{pkg.name}/"
        candidates = [f"share/{pkg.name}/{rel}"]  # install(DIRECTORY launch DESTINATION share/<pkg>)
        for rule in pkg.install_rules:
            if rule.source is None:
                continue
            if rule.kind == "file" and rule.source == path:
                candidates.append(posixpath.join(rule.dest, rule.rename or posixpath.basename(path)))
            elif rule.kind == "directory" and path.startswith(rule.source + "/"):
                base = rule.dest if rule.contents_only else posixpath.join(rule.dest, posixpath.basename(rule.source))
                candidates.append(posixpath.join(base, path[len(rule.source) + 1 :]))
        for cand in candidates:
            found = self.locate(prefix + cand)
            if found.status == "ok" and found.source == path:
                return prefix + cand
        return None

    def locate(self, path: str) -> Located:
        """Where a path launch would open comes from (see module docstring). Memoised: every node
        of a large workspace asks for its parameter files, and the answer is a walk over install
        rules."""
        found = self._located.get(path)
        if found is None:
            # launch opens a relative path from the directory ``ros2 launch`` runs in (open(),
            # SourceFileLoader, rcl): not this linter's, nor the package's or the launch file's
            found = self._located[path] = self._locate(_norm(path)) if path.startswith("/") else \
                Located("missing", None, None)
        return found

    def _locate(self, path: str) -> Located:
        # 1. the virtual install space of a workspace package
        if path.startswith(self.install_root + "/"):
            rest = path[len(self.install_root) + 1 :]
            name, _, rel = rest.partition("/")
            pkg = self.packages.get(name)
            if pkg is not None:
                return self._locate_installed(pkg, rel)
            return Located("ok" if self._exists(path) else "unknown", None, name or None)
        # 2. the workspace source tree
        pkg = self.package_of_source(path)
        if pkg is not None:
            rel = path[len(pkg.path) + 1 :] if path != pkg.path else ""
            ok = rel == "" or rel in pkg.files or rel in pkg.dirs
            return Located("ok" if ok else "missing", path, pkg.name)
        # 3. AMENT_PREFIX_PATH prefixes (real files)
        for prefix in self.prefixes:
            if path == prefix or path.startswith(prefix + "/"):
                rel = path[len(prefix) + 1 :]
                parts = rel.split("/")
                owner = parts[1] if len(parts) > 1 and parts[0] in ("share", "lib") else None
                return Located("ok" if self._exists(path) else "missing", path, owner)
        # 4. the distro's prefix, for packages we only know by name
        opt = f"/opt/ros/{self.distro}/"
        if path.startswith(opt):
            parts = path[len(opt) :].split("/")
            owner = parts[1] if len(parts) > 1 and parts[0] in ("share", "lib") else None
            return Located("unknown", None, owner)
        # 5. anywhere else
        if path == self.workspace_root or path.startswith(self.workspace_root + "/"):
            return Located("ok" if self._exists(path) else "missing", path, None)
        return Located("ok", path, None) if self._exists(path) else Located("unknown", None, None)

    def _locate_installed(self, pkg: WorkspacePackage, rel: str) -> Located:
        name = pkg.name
        share = f"share/{name}"
        if rel in ("", share, "share", "lib", f"lib/{name}"):
            return Located("ok", pkg.path, name)
        unknown_hit = False
        missing_source: str | None = None
        for rule in pkg.install_rules:
            dest = rule.dest
            if rule.source is None:
                if dest == "" or rel == dest or rel.startswith(dest + "/"):
                    unknown_hit = True
                continue
            if rule.kind == "file":
                target = posixpath.join(dest, rule.rename or posixpath.basename(rule.source))
                if rel == target:
                    if self._source_exists(pkg, rule.source):
                        return Located("ok", rule.source, name)
                    missing_source = missing_source or rule.source
                elif rel == dest or target.startswith(rel + "/"):
                    return Located("ok", None, name)  # an install directory itself
                continue
            base = dest if rule.contents_only else posixpath.join(dest, posixpath.basename(rule.source))
            if rel == base or (base and base.startswith(rel + "/")):
                return Located("ok", rule.source, name)
            if base and not rel.startswith(base + "/"):
                continue
            sub = rel[len(base) + 1 :] if base else rel
            if not _rule_admits(rule, sub):
                continue
            cand = rule.source + "/" + sub
            if self._source_exists(pkg, cand) or self._source_is_dir(pkg, cand):
                return Located("ok", cand, name)
        if f"lib/{name}/" in rel + "/" and posixpath.basename(rel) in pkg.executables:
            return Located("ok", None, name)
        if missing_source is not None:
            return Located("missing", missing_source, name)
        tail = rel[len(share) + 1 :] if rel.startswith(share + "/") else None
        counterpart = f"{pkg.path}/{tail}" if tail else None
        if unknown_hit or not pkg.install_complete or self._installs_through_dependency(pkg):
            return Located("unknown", counterpart if tail and tail in pkg.files else None, name)
        if tail is not None and (tail in pkg.files or tail in pkg.dirs):
            return Located("not_installed", counterpart, name, _install_hint(pkg, tail))
        return Located("missing", counterpart, name)

    def _installs_through_dependency(self, pkg: WorkspacePackage) -> bool:
        """Whether ``pkg``'s CMakeLists.txt calls a macro that a workspace package it finds
        defines in its CONFIG_EXTRAS and that installs something: what it installs then is not
        known here (asked only once a file looks not installed, so only then are those read)."""
        if not pkg.calls:
            return False
        for dep in sorted(pkg.found_packages - {pkg.name}):
            other = self.packages.get(dep)
            if other is not None and other.installers & pkg.calls:
                return True
        return False

    def _source_exists(self, pkg: WorkspacePackage, path: str) -> bool:
        if path.startswith(pkg.path + "/"):
            return path[len(pkg.path) + 1 :] in pkg.files
        return self._exists(path)

    def _source_is_dir(self, pkg: WorkspacePackage, path: str) -> bool:
        if path.startswith(pkg.path + "/"):
            return path[len(pkg.path) + 1 :] in pkg.dirs
        return os.path.isdir(path)

    def _exists(self, path: str) -> bool:
        if path not in self._exists_cache:
            self._exists_cache[path] = os.path.exists(path)
        return self._exists_cache[path]

    def exists(self, path: str) -> bool:
        """Does a file or directory exist on disk (cached)?"""
        return self._exists(_norm(path))

    def is_dir(self, path: str) -> bool:
        """Is ``path`` a directory on disk (cached: every node asks it of its parameter files)?"""
        found = self._isdir_cache.get(path)
        if found is None:
            found = self._isdir_cache[path] = os.path.isdir(path)
        return found

    # ---- reading ---------------------------------------------------------------------------------

    def read_text(self, path: str) -> str | None:
        """A file's text: None when unreadable, larger than 50 MB, binary (NUL bytes) or not UTF-8.
        Cached: every layer reads workspace files through here."""
        path = _norm(path)
        if path in self._text_cache:
            return self._text_cache[path]
        text = read_text_file(path)
        self._text_cache[path] = text
        return text


def read_text_file(path: str) -> str | None:
    try:
        if os.path.getsize(path) > READ_LIMIT:
            return None
        with open(path, "rb") as fh:
            data = read_at_most(fh, READ_LIMIT)
    except OSError:
        return None
    if len(data) > READ_LIMIT or b"\x00" in data:
        return None
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError:
        return None
    return text.removeprefix("\ufeff")


def _rule_admits(rule: InstallRule, sub: str) -> bool:
    parts = sub.split("/")
    for ex in rule.excludes:
        rx = compile_glob(ex, False)
        if any(rx.match(p) for p in parts):
            return False
    if rule.files_matching and rule.patterns:
        return any(compile_glob(p, False).match(parts[-1]) for p in rule.patterns)
    return True


def _installed_elsewhere(pkg: WorkspacePackage, tail: str) -> str | None:
    """How to fix a rule that installs the source file ``tail`` (relative to the package) to another
    place of the install space: a directory installed with a trailing slash (its contents land in
    the destination itself), a file sent to the wrong DESTINATION or data_files folder."""
    source = f"{pkg.path}/{tail}"
    share = f"share/{pkg.name}"
    for rule in pkg.install_rules:
        if rule.source is None:
            continue
        if rule.kind == "file":
            if rule.source != source:
                continue
            put = posixpath.join(rule.dest, rule.rename or posixpath.basename(rule.source))
        elif source.startswith(rule.source.rstrip("/") + "/"):
            sub = source[len(rule.source.rstrip("/")) + 1:]
            if not _rule_admits(rule, sub):
                continue
            base = rule.dest if rule.contents_only else posixpath.join(rule.dest, posixpath.basename(rule.source))
            put = posixpath.join(base, sub)
        else:
            continue
        if put == f"{share}/{tail}":
            continue
        where = f"{posixpath.basename(rule.origin)}:{rule.line}"
        want = posixpath.dirname(f"{share}/{tail}")
        if rule.kind == "directory" and rule.contents_only and rule.dest == share and \
                f"{pkg.path}/{tail.split('/', 1)[0]}" == rule.source.rstrip("/"):
            top = tail.split("/", 1)[0]
            return (f'it is installed as "{put}" instead: install(DIRECTORY {top}/ ...) at {where} installs '
                    f'what is in "{top}" (the trailing slash), not the folder; write "{top}" without the slash')
        if rule.kind == "file" and pkg.build_type == "ament_python":
            folder = ", ".join(["'share'", "package_name", *(repr(x) for x in want.split("/")[2:])])
            return (f'it is installed as "{put}" instead (data_files at {where}): install it to '
                    f"os.path.join({folder})")
        return f'it is installed as "{put}" instead ({where}): install it to "{want}"'
    return None


def _install_hint(pkg: WorkspacePackage, tail: str) -> str:
    elsewhere = _installed_elsewhere(pkg, tail)
    if elsewhere is not None:
        return elsewhere
    d = posixpath.dirname(tail)
    base = posixpath.basename(tail)
    top = tail.split("/", 1)[0]
    if pkg.build_type == "ament_python":
        ext = posixpath.splitext(base)[1]
        if d:
            parts = ", ".join(repr(p) for p in d.split("/"))
            return (f"add (os.path.join('share', package_name, {parts}), "
                    f"glob('{d}/*{ext}')) to data_files in setup.py")
        return f"add (os.path.join('share', package_name), ['{base}']) to data_files in setup.py"
    if d:
        return f'add "{top}" to install(DIRECTORY ... DESTINATION share/${{PROJECT_NAME}}) in CMakeLists.txt'
    return f'add install(FILES {base} DESTINATION share/${{PROJECT_NAME}}) to CMakeLists.txt'


def _list_executables(libdir: str) -> frozenset[str] | None:
    try:
        entries = list(os.scandir(libdir))
    except OSError:
        return frozenset() if not os.path.exists(libdir) else None
    out = set()
    for e in entries:
        try:
            if e.is_file() and os.access(e.path, os.X_OK):
                out.add(e.name)
        except OSError:
            continue
    return frozenset(out)


# ---- building ---------------------------------------------------------------------------------


def _find_packages(root: str, ignored: list[tuple[str, str]] | None = None) -> list[str]:
    """Directories below ``root`` holding a package.xml, the way colcon crawls: ignore markers skip
    a directory and everything below; a package's subdirectories hold no further packages.
    ``ignored`` collects (directory, marker) of the package directories a marker of their own
    skips (a package disabled with COLCON_IGNORE)."""
    found: list[str] = []
    seen: set[tuple[int, int]] = set()

    def walk(d: str) -> None:
        real = dir_identity(d)
        if real is None or real in seen:
            return
        seen.add(real)
        try:
            entries = list(os.scandir(d))
        except OSError:
            return
        names = {e.name for e in entries}
        marker = ignore_marker(d, names)
        if marker is not None:
            if ignored is not None and "package.xml" in names:
                ignored.append((d, marker))
            return
        if "package.xml" in names:
            found.append(d)
            return
        for e in sorted(entries, key=lambda e: e.name):
            if skip_dir_name(e.name):
                continue
            try:
                if e.is_dir():
                    walk(d + "/" + e.name)
            except OSError:
                continue

    walk(root)
    return found


_SKIPPED_DIRS = (".git", "__pycache__", ".svn", ".hg")


def _snapshot(pkg_dir: str) -> tuple[frozenset[str], frozenset[str]]:
    files: set[str] = set()
    dirs: set[str] = set()
    seen: set[tuple[int, int]] = set()
    stack = [("", pkg_dir)]
    while stack and len(files) < SNAPSHOT_LIMIT:
        rel, d = stack.pop()
        real = dir_identity(d)
        if real is None or real in seen:
            continue
        seen.add(real)
        try:
            entries = list(os.scandir(d))
        except OSError:
            continue
        for e in entries:
            r = rel + e.name if not rel else rel + "/" + e.name
            try:
                if e.is_dir():
                    if e.name in _SKIPPED_DIRS:
                        continue
                    dirs.add(r)
                    stack.append((r, d + "/" + e.name))
                elif e.is_file():
                    files.add(r)
            except OSError:
                continue
    return frozenset(files), frozenset(dirs)


class PackageTree:
    """The files and directories under a package directory, read on demand.

    Most packages a run reads are asked about a few paths (is ``launch/x.launch.py`` there?); a
    whole listing of their trees was 8% of a run on Autoware's top-level launch file (202 packages,
    source trees included). A membership question is answered by one ``stat`` of that path
    (remembered), the same answer as the listing's except that a listing stops at
    ``SNAPSHOT_LIMIT`` files and lists a file reached twice through a directory link once. Iterating
    (globs of setup.py ``data_files``, directories installed into ``lib/<pkg>``) lists the tree
    once (``_snapshot``). ``files`` and ``dirs`` are the two views."""

    __slots__ = ("root", "_stats", "_listing", "files", "dirs")

    def __init__(self, root: str) -> None:
        self.root = root
        self._stats: dict[str, str | None] = {}  # rel path -> "file" / "dir" / None
        self._listing: tuple[frozenset[str], frozenset[str]] | None = None
        self.files = _TreeView(self, "file")
        self.dirs = _TreeView(self, "dir")

    def listing(self) -> tuple[frozenset[str], frozenset[str]]:
        if self._listing is None:
            self._listing = _snapshot(self.root)
        return self._listing

    def kind(self, rel: str) -> str | None:
        """"file", "dir" or None for ``rel`` (a relative "/" path) as the listing would see it: a
        path through a skipped directory (.git, __pycache__, ...) is not in the package."""
        if rel in self._stats:
            return self._stats[rel]
        if self._listing is not None:
            files, dirs = self._listing
            found = "file" if rel in files else "dir" if rel in dirs else None
        else:
            parts = rel.split("/")
            if any(p in ("", ".", "..") for p in parts) or any(p in _SKIPPED_DIRS for p in parts[:-1]):
                found = None
            else:
                try:
                    st = os.stat(self.root + "/" + rel)
                except (OSError, ValueError):
                    found = None
                else:
                    found = "dir" if stat.S_ISDIR(st.st_mode) and parts[-1] not in _SKIPPED_DIRS \
                        else "file" if stat.S_ISREG(st.st_mode) else None
        self._stats[rel] = found
        return found


class _TreeView:
    """``PackageTree.files`` or ``.dirs``: a read-only set of relative "/" paths."""

    __slots__ = ("tree", "what")

    def __init__(self, tree: PackageTree, what: str) -> None:
        self.tree = tree
        self.what = what

    def __contains__(self, rel: object) -> bool:
        return isinstance(rel, str) and self.tree.kind(rel) == self.what

    def _all(self) -> frozenset[str]:
        files, dirs = self.tree.listing()
        return files if self.what == "file" else dirs

    def __iter__(self) -> Iterator[str]:
        return iter(self._all())

    def __len__(self) -> int:
        return len(self._all())

    def __eq__(self, other: object) -> bool:  # as the sets they stand for (lists the tree)
        if isinstance(other, _TreeView):
            return self._all() == other._all()
        return isinstance(other, (set, frozenset)) and self._all() == other

    __hash__ = None  # type: ignore[assignment]  # like a set's

    def __repr__(self) -> str:
        return f"<{self.what}s under {self.tree.root}>"


def build_package_index(workspace_root: str, distro: str = "humble",
                        ament_prefix_path: str | None = None,
                        scope: Iterable[str] | None = None, cache: Any = None) -> PackageIndex:
    """The index of the workspace. With ``scope`` (paths), no package is indexed: only the
    ``problems`` of the manifests of the packages holding those paths are computed (exactly,
    duplicate names included). That is all a run that resolves no launch file reads. ``cache``
    (a ``cache.ParseCache``, or None) keeps what each manifest and CMakeLists.txt says across
    runs; directory listings are always read afresh."""
    if distro not in DISTROS:
        raise UsageError(f"unknown distro {distro!r}: expected one of {', '.join(DISTROS)}")
    root = _norm(workspace_root)
    prefixes: list[str] = []
    for p in (ament_prefix_path or "").split(os.pathsep):
        if p.strip():
            np = _norm(p.strip())
            if np not in prefixes:
                prefixes.append(np)
    index = PackageIndex(root, distro, prefixes)
    index.cache = cache

    for prefix in prefixes:
        try:
            names = os.listdir(f"{prefix}/{RESOURCE_INDEX}/packages")
        except OSError:
            continue
        for n in sorted(names):
            if not n.startswith("."):
                index.installed.setdefault(n, prefix)

    ignored: list[tuple[str, str]] = []
    pkg_dirs = _find_packages(root, ignored) if os.path.isdir(root) else []
    for pkg_dir, marker in ignored:
        text = index.read_text(pkg_dir + "/package.xml")
        name = _plain_name(text) if text is not None else None
        if name:
            index.ignored.setdefault(name, (pkg_dir, marker))
    if scope is not None:
        _scoped_problems(index, pkg_dirs, scope)
        return index
    for pkg_dir in pkg_dirs:
        text = index.read_text(pkg_dir + "/package.xml")
        name = _plain_name(text) if text is not None else None
        pkg = None
        if name is None:  # unreadable, or a name only catkin_pkg can tell: read it now
            pkg = _read_package(index, pkg_dir)
            if pkg is None:
                continue
            name = pkg.name
        if name in index.packages:
            if pkg is None:
                _read_manifest(index, pkg_dir)  # its own problems, as when it is read
            index.problems.append(_duplicate(pkg_dir + "/package.xml", name, index.packages.dir_of(name)))
            continue
        index.packages.add(name, pkg_dir, pkg)
        index._by_dir[pkg_dir] = name
    return index


def _plain_name(text: str) -> str | None:
    """The package name ``_read_package`` gives this manifest whether or not catkin_pkg accepts
    it, when the text leaves no doubt: one ``<name>`` element outside comments, plain text, that
    the fallback pattern reads the same. Else None (then the package is read at once)."""
    if "<![CDATA[" in text:
        return None
    found = _NAME_ELEMENT_RX.findall(_COMMENT_RX.sub("", text))
    fallback = _NAME_RX.search(text)
    if len(found) != 1 or fallback is None or any(c in found[0] for c in "&<\r"):
        return None
    name = found[0].strip(" \n\r\t")
    return name if name and name == fallback.group(1) else None


def _duplicate(package_xml: str, name: str, first_dir: str) -> tuple[str, str, int]:
    """The problem of a second package with an already indexed name."""
    message = f'duplicate package name "{name}" (also in {first_dir}); colcon refuses to build this workspace'
    return package_xml, message, 1


_COMMENT_RX = re.compile(r"<!--.*?-->|<\?.*?\?>", re.DOTALL)
_NAME_ELEMENT_RX = re.compile(r"<name(?:\s[^>]*)?>(.*?)</name\s*>", re.DOTALL)


def _scoped_problems(index: PackageIndex, pkg_dirs: list[str], scope: Iterable[str]) -> None:
    """``problems`` of the manifests ``_in_scope``, as the full build reports them."""
    first: dict[str, str] = {}
    for pkg_dir in _in_scope(index, pkg_dirs, scope):
        man = _read_manifest(index, pkg_dir)
        if man is None:
            continue
        name = man.name or posixpath.basename(pkg_dir)
        if name in first:
            index.problems.append(_duplicate(pkg_dir + "/package.xml", name, first[name]))
        else:
            first[name] = pkg_dir


def _in_scope(index: PackageIndex, pkg_dirs: list[str], scope: Iterable[str]) -> list[str]:
    """The package directories (in crawl order) whose manifests decide the problems of those
    holding a scope path: those, and every package whose name may equal one of theirs (the first
    of a name wins). Names are over-approximated from the text, without catkin_pkg."""
    dirs = set(pkg_dirs)
    held: set[str] = set()
    for path in scope:
        d = posixpath.dirname(_norm(path))
        while d and d not in dirs:
            parent = posixpath.dirname(d)
            d = "" if parent == d else parent
        if d:
            held.add(d)
    wanted: set[str] = set()
    for d in held:
        names = _possible_names(index, d)
        if names is None:
            return pkg_dirs  # a name we cannot bound: every package may collide with it
        wanted |= names
    out = []
    for d in pkg_dirs:
        names = set() if d in held else _possible_names(index, d)
        if d in held or names is None or names & wanted:
            out.append(d)
    return out


def _possible_names(index: PackageIndex, pkg_dir: str) -> set[str] | None:
    """Every name ``_read_package`` may give a package (catkin_pkg's <name>, the fallback regex,
    the directory name), or None when the text could hide it (entities, CDATA, markup)."""
    text = index.read_text(pkg_dir + "/package.xml")
    if text is None:
        return set()  # unreadable: not indexed under any name
    names = {posixpath.basename(pkg_dir)}
    fallback = _NAME_RX.search(text)
    if fallback:
        names.add(fallback.group(1))
    if "<![CDATA[" in text:
        return None
    for m in _NAME_ELEMENT_RX.finditer(_COMMENT_RX.sub("", text)):
        value = m.group(1)
        if "&" in value or "<" in value or "\r" in value:
            return None
        names.add(value.strip(" \n\r\t"))  # as catkin_pkg _get_node_value
    return names


def _read_manifest(index: PackageIndex, pkg_dir: str) -> ManifestInfo | None:
    xml_path = pkg_dir + "/package.xml"
    text = index.read_text(xml_path)
    if text is None:
        index.problems.append((xml_path, "package.xml is unreadable (binary, too large or not UTF-8)", 1))
        return None
    man = _parse_manifest(index, text, xml_path)
    if man.error is not None:
        index.problems.append((xml_path, man.error[0], man.error[1]))
    return man


# ---- what one build file says, from the disk cache when its text was seen before -----------------
# A cached value is a pure function of the key's text, path and options (the cache's code
# fingerprint covers these modules and catkin_pkg); a hit of the wrong shape is a miss.


def _parse_manifest(index: PackageIndex, text: str, xml_path: str) -> ManifestInfo:
    """``parse_manifest``: catkin_pkg's verdict and the dependency lines. A hit (a small
    dataclass) also saves importing catkin_pkg."""
    cache = index.cache
    if cache is None:
        return parse_manifest(text, xml_path, index.distro)
    key = cache.key("manifest", xml_path, text, index.distro)
    hit = cache.get(key)
    if type(hit) is ManifestInfo:
        return hit
    man = parse_manifest(text, xml_path, index.distro)
    cache.put(key, man)
    return man


def _digest(text: str | None) -> str | None:
    return None if text is None else hashlib.sha256(text.encode("utf-8", "surrogatepass")).hexdigest()


def _read_cmake(index: PackageIndex, pkg_dir: str, name: str, text: str | None) -> BuildInfo:
    """``read_cmake_package``. The value stored is (BuildInfo, digests of the other CMake files
    it read: ``add_subdirectory``), and a hit counts only while those files still read the same."""
    cache = index.cache
    if cache is None or text is None:
        return read_cmake_package(pkg_dir, name, text)
    key = cache.key("cmake-3", pkg_dir + "/CMakeLists.txt", text, name)  # 3: dependency macros
    hit = cache.get(key)
    if (isinstance(hit, tuple) and len(hit) == 2 and type(hit[0]) is BuildInfo
            and all(_digest(read_listfile(p)) == d for p, d in hit[1])):
        return hit[0]
    reads: list[tuple[str, str | None]] = []
    info = read_cmake_package(pkg_dir, name, text, reads)
    cache.put(key, (info, tuple((p, _digest(t)) for p, t in reads)))
    return info


def _read_package(index: PackageIndex, pkg_dir: str) -> WorkspacePackage | None:
    xml_path = pkg_dir + "/package.xml"
    man = _read_manifest(index, pkg_dir)
    if man is None:
        return None
    name = man.name or posixpath.basename(pkg_dir)
    tree = PackageTree(pkg_dir)
    files, dirs = tree.files, tree.dirs
    build_type = man.build_type
    if build_type is None:
        build_type = ("ament_python" if "setup.py" in files and "CMakeLists.txt" not in files
                      else "ament_cmake" if "CMakeLists.txt" in files else "unknown")
    if build_type == "ament_python":
        info = read_setup_py(pkg_dir, name, files, index.read_text(pkg_dir + "/setup.py")
                             if "setup.py" in files else None)
    elif build_type in ("ament_cmake", "cmake"):
        info = _read_cmake(index, pkg_dir, name, index.read_text(pkg_dir + "/CMakeLists.txt")
                           if "CMakeLists.txt" in files else None)
    else:
        info = BuildInfo(complete=False, executables_complete=False)
    index.notes.extend(info.problems)
    # install(DIRECTORY ... DESTINATION lib/<pkg> USE_SOURCE_PERMISSIONS): executable files in it
    lib_dest = f"lib/{name}"
    for rule in info.rules:
        if rule.kind == "directory" and rule.dest == lib_dest and rule.source and rule.contents_only:
            rel = rule.source[len(pkg_dir) + 1 :] if rule.source.startswith(pkg_dir + "/") else None
            if rel is None:
                continue
            for f in files:
                if (f.startswith(rel + "/") and "/" not in f[len(rel) + 1 :]
                        and os.access(pkg_dir + "/" + f, os.X_OK)):
                    info.executables.add(f[len(rel) + 1 :])
    return WorkspacePackage(
        name=name,
        path=pkg_dir,
        package_xml=xml_path,
        build_type=build_type,
        format=man.format,
        exec_depends=man.exec_depends,
        excluded_depends=man.excluded_depends,
        test_depends=man.test_depends,
        executables=frozenset(info.executables),
        executables_in_bin=frozenset(info.executables_in_bin),
        scripts_dir=info.scripts_dir,
        plugins=frozenset(info.plugins),
        install_rules=tuple(info.rules),
        parameter_yamls={k: tuple(v) for k, v in sorted(info.parameter_yamls.items())},
        parameter_modules=tuple(info.parameter_modules),
        sources={k: tuple(v) for k, v in sorted(info.sources.items())},
        library_sources={k: tuple(v) for k, v in sorted(info.library_sources.items())},
        source_roots={k: tuple(v) for k, v in sorted(info.source_roots.items())},
        files=files,
        dirs=dirs,
        install_complete=info.complete,
        executables_complete=info.executables_complete,
        registers_in_index=info.registers_in_index,
        valid=man.error is None,
        calls=frozenset(info.calls),
        found_packages=frozenset(info.found_packages),
        installers=frozenset(info.installers),
    )
