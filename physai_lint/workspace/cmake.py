"""A small CMake reader: tokenises CMakeLists.txt (comments, quoted and bracket arguments, nested
parentheses) and interprets the handful of commands that decide what a package installs. Variables
are expanded from ``project()``, ``set()``, ``list(APPEND)`` and ``foreach()``; anything else is
"unknown" (``\\x00``), and rules built from unknown values cover their destination as unknown."""
from __future__ import annotations

import os
import re

from ._cmake_lex import Arg, Command, tokenize
from ._model import BuildInfo, InstallRule

__all__ = ["Arg", "Command", "read_cmake_package", "read_listfile", "tokenize"]

UNKNOWN = "\x00"
_PREFIX = "\x01PREFIX"
_MAX_SUBDIRS = 32


_VAR_RX = re.compile(r"\$\{([^${}]*)\}")
_ENV_RX = re.compile(r"\$ENV\{[^}]*\}")


class _Interp:
    def __init__(self, pkg_dir: str, pkg_name: str, info: BuildInfo) -> None:
        self.pkg_dir = pkg_dir
        self.pkg_name = pkg_name
        self.info = info
        self.vars: dict[str, str] = {
            "PROJECT_NAME": pkg_name,
            "CMAKE_INSTALL_PREFIX": _PREFIX,
            "CMAKE_INSTALL_BINDIR": "bin",
            "CMAKE_INSTALL_LIBDIR": "lib",
            "CMAKE_INSTALL_DATADIR": "share",
            "CMAKE_INSTALL_INCLUDEDIR": "include",
            "CMAKE_CURRENT_BINARY_DIR": UNKNOWN,
            "CMAKE_BINARY_DIR": UNKNOWN,
            "PROJECT_BINARY_DIR": UNKNOWN,
        }
        self.functions: dict[str, list[Command]] = {}
        self.exes: set[str] = set()
        self.libs: set[str] = set()
        self.auto_exes: set[str] = set()
        self.links: dict[str, set[str]] = {}
        self.param_libs: dict[str, str | None] = {}
        self.target_sources: dict[str, list[str]] = {}
        self.plugin_targets: dict[str, str] = {}
        self.exe_plugins: dict[str, str] = {}  # rclcpp_components_register_node EXECUTABLE -> PLUGIN
        self.output_names: dict[str, dict[str, str]] = {}  # target -> its _RENAMING properties
        self.installed_targets: set[str] = set()  # executable targets installed to lib/<pkg>
        self.subdirs = 0
        self.auto_package = False
        self.reads: list[tuple[str, str | None]] = []  # (path, text) of other files read

    def python_scripts(self, a: list[str]) -> None:
        """``ament_python_install_package(pkg ... SCRIPTS_DESTINATION dest [SETUP_CFG file])``
        (ament_cmake_python): the console scripts of the package's setup.cfg
        (``[options.entry_points]``, default ``CMAKE_CURRENT_LIST_DIR/setup.cfg``) are installed to
        ``dest`` (``setup.py install_scripts``); to ``lib/<pkg>`` they are executables
        (controller_manager's spawner). Unknown when the destination or the file is."""
        from physai_lint.workspace.setup_py import setup_cfg_console_scripts

        _, opts = _split_opts(a[1:], {"PACKAGE_DIR", "VERSION", "SETUP_CFG", "DESTINATION",
                                      "SCRIPTS_DESTINATION", "SKIP_COMPILE"})
        dest = opts.get("SCRIPTS_DESTINATION")
        if dest is None:
            return
        where = self.dest(dest[0]) if dest else None
        if where is None:
            self.info.executables_complete = False
            return
        if where != f"lib/{self.pkg_name}":
            return  # installed elsewhere: not what ros2 run or launch finds
        cfg = opts.get("SETUP_CFG")
        path = self.src_path(cfg[0] if cfg else "setup.cfg")
        text = read_listfile(path) if path is not None else None
        if path is not None:
            self.reads.append((path, text))
        scripts = setup_cfg_console_scripts(text) if text is not None else None
        if scripts is None:
            if cfg:  # named but unreadable; without one, ament installs no scripts
                self.info.executables_complete = False
            return
        self.info.executables.update(scripts)

    # -- values ---------------------------------------------------------------------------------

    def expand(self, s: str) -> str:
        if "$" not in s:
            return s
        s = _ENV_RX.sub(UNKNOWN, s)
        for _ in range(20):
            new = _VAR_RX.sub(lambda m: self.vars.get(m.group(1), UNKNOWN) if UNKNOWN not in m.group(1) else UNKNOWN, s)
            if new == s:
                break
            s = new
        if "$<" in s:
            s = UNKNOWN
        return s

    def args(self, cmd: Command) -> list[str]:
        out: list[str] = []
        for a in cmd.args:
            v = self.expand(a.value)
            if a.quoted:
                out.append(v)
            elif v == "":
                continue
            else:
                out.extend(p.replace("\\;", ";") for p in re.split(r"(?<!\\);", v) if p != "")
        return out

    def src_path(self, p: str) -> str | None:
        if UNKNOWN in p or _PREFIX in p:
            return None
        cur = self.vars["CMAKE_CURRENT_SOURCE_DIR"]
        path = p if os.path.isabs(p) else os.path.join(cur, p)
        trailing = p.endswith("/")
        norm = os.path.normpath(path).replace(os.sep, "/")
        return norm + ("/" if trailing else "")

    def dest(self, d: str) -> str | None:
        if UNKNOWN in d:
            return None
        if d.startswith(_PREFIX):
            d = d[len(_PREFIX) :].lstrip("/") or "."
        if _PREFIX in d or os.path.isabs(d):
            return None
        d = os.path.normpath(d).replace(os.sep, "/")
        return "" if d == "." else d

    # -- commands -------------------------------------------------------------------------------

    def run(self, cmds: list[Command], origin: str, depth: int = 0) -> None:
        i = 0
        while i < len(cmds):
            cmd = cmds[i]
            name = cmd.name
            if name in ("foreach", "function", "macro"):
                end = {"foreach": "endforeach", "function": "endfunction", "macro": "endmacro"}[name]
                body, i = _block(cmds, i, name, end)
                if name == "foreach":
                    self.foreach(cmd, body, origin, depth)
                else:
                    a = self.args(cmd)
                    if a:
                        self.functions[a[0].lower()] = body
                continue
            try:
                self.command(cmd, origin, depth)
            except Exception as exc:  # noqa: BLE001 - a reader bug must not hide the package
                self.info.complete = False
                self.info.problems.append((origin, f"could not read {name}(): {exc}", cmd.line))
            i += 1

    def foreach(self, head: Command, body: list[Command], origin: str, depth: int) -> None:
        a = self.args(head)
        if not a:
            return
        var, rest = a[0], a[1:]
        items: list[str] = []
        if rest and rest[0] == "RANGE":
            if any(c.name == "install" for c in body):
                self.info.complete = self.info.executables_complete = False
            return
        if rest and rest[0] == "IN":
            mode = None
            for tok in rest[1:]:
                if tok in ("LISTS", "ITEMS", "ZIP_LISTS"):
                    mode = tok
                elif mode == "LISTS":
                    val = self.vars.get(tok, "")
                    items.extend(p for p in val.split(";") if p)
                elif mode == "ITEMS":
                    items.append(tok)
        else:
            items = rest
        saved = self.vars.get(var)
        for item in items:
            self.vars[var] = item
            self.run(body, origin, depth)
        if saved is None:
            self.vars.pop(var, None)
        else:
            self.vars[var] = saved

    def command(self, cmd: Command, origin: str, depth: int) -> None:
        name = cmd.name
        if name == "project":
            a = self.args(cmd)
            if a and UNKNOWN not in a[0]:
                self.vars["PROJECT_NAME"] = a[0]
                self.info.project_name = a[0]
        elif name == "set":
            a = self.args(cmd)
            if not a:
                return
            vals = a[1:]
            for stop in ("CACHE", "PARENT_SCOPE"):
                if stop in vals:
                    vals = vals[: vals.index(stop)]
            self.vars[a[0]] = ";".join(vals)
        elif name == "list":
            a = self.args(cmd)
            if len(a) >= 2 and a[0] in ("APPEND", "PREPEND"):
                cur = [p for p in self.vars.get(a[1], "").split(";") if p]
                cur = cur + a[2:] if a[0] == "APPEND" else a[2:] + cur
                self.vars[a[1]] = ";".join(cur)
        elif name in ("add_executable", "ament_auto_add_executable"):
            a = self.args(cmd)
            if a and "IMPORTED" not in a and "ALIAS" not in a:
                self.exes.add(a[0])
                self.record_sources(a)
                if name == "ament_auto_add_executable":
                    self.auto_exes.add(a[0])
        elif name in ("add_library", "ament_auto_add_library"):
            a = self.args(cmd)
            if a:
                self.libs.add(a[0])
                self.record_sources(a)
        elif name == "target_sources":
            self.record_sources(self.args(cmd))
        elif name in _TEST_EXECUTABLES:
            a = self.args(cmd)
            if a:
                self.record_sources(a)  # (installed with install(TARGETS), a launch may run one)
        elif name == "set_target_properties":
            a = self.args(cmd)
            if "PROPERTIES" in a:
                k = a.index("PROPERTIES")
                props = a[k + 1:]
                for target in a[:k]:
                    for prop, value in zip(props[::2], props[1::2]):
                        self.target_property(target, prop, value)
        elif name == "set_property":
            a = self.args(cmd)
            if a and a[0] == "TARGET" and "PROPERTY" in a and len(a) > a.index("PROPERTY") + 1:
                k = a.index("PROPERTY")
                prop, values = a[k + 1], a[k + 2:]
                for target in a[1:k]:
                    if target in ("APPEND", "APPEND_STRING"):
                        continue
                    old = self.output_names.get(target, {}).get(prop)
                    if not values:  # no value: the property is unset
                        self.output_names.get(target, {}).pop(prop, None)
                    elif "APPEND_STRING" in a[1:k]:
                        self.target_property(target, prop, (old or "") + "".join(values))
                    elif len(values) > 1 or ("APPEND" in a[1:k] and old):
                        self.target_property(target, prop, UNKNOWN)  # a list is no file name
                    else:
                        self.target_property(target, prop, values[0])
        elif name == "target_link_libraries":
            a = self.args(cmd)
            if a:
                kw = {"PUBLIC", "PRIVATE", "INTERFACE", "LINK_PUBLIC", "LINK_PRIVATE", "LINK_INTERFACE_LIBRARIES", "debug", "optimized", "general"}
                self.links.setdefault(a[0], set()).update(x for x in a[1:] if x not in kw)
        elif name == "generate_parameter_library":
            a = self.args(cmd)
            if len(a) >= 2:
                p = self.src_path(a[1])
                self.param_libs[a[0]] = p.rstrip("/") if p else None
                self.libs.add(a[0])
        elif name == "rclcpp_components_register_node":
            a = self.args(cmd)
            if not a:
                return
            plugin = _kwarg(a, "PLUGIN")
            exe = _kwarg(a, "EXECUTABLE")
            if plugin and UNKNOWN not in plugin:
                self.info.plugins.add(plugin)
                self.plugin_targets[plugin] = a[0]
            if exe and UNKNOWN not in exe:
                self.installed_targets.add(exe)  # the macro adds and installs target ``exe``
                self.exes.add(exe)
                self.links.setdefault(exe, set()).add(a[0])
                if plugin and UNKNOWN not in plugin:
                    self.exe_plugins[exe] = plugin  # its generated main() runs that class alone
        elif name == "rclcpp_components_register_nodes":
            a = self.args(cmd)
            if a:
                for cls in a[1:]:
                    if cls == "RESOURCE_INDEX":
                        break
                    if UNKNOWN not in cls:
                        self.info.plugins.add(cls)
                        self.plugin_targets[cls] = a[0]
        elif name == "install":
            self.install(cmd, origin)
        elif name == "ament_python_install_package":
            a = self.args(cmd)
            if a:
                self.info.python_packages.add(a[0])
                self.python_scripts(a)
        elif name in ("ament_auto_package", "autoware_ament_auto_package"):
            # autoware_cmake's autoware_ament_auto_package re-implements ament_auto_package (it only
            # installs headers to include/ instead of include/<pkg>): same INSTALL_TO_SHARE result.
            self.auto_package = True
            a = self.args(cmd)
            if "INSTALL_TO_SHARE" in a:
                for d in a[a.index("INSTALL_TO_SHARE") + 1 :]:
                    if d.isupper() and d.replace("_", "").isalpha():
                        break
                    src = self.src_path(d)
                    self.add_rule("directory", f"share/{self.pkg_name}", src, cmd.line, origin,
                                  contents_only=False)
            self.ament_package(cmd, origin)
        elif name == "ament_package":
            self.ament_package(cmd, origin)
        elif name == "add_subdirectory":
            a = self.args(cmd)
            if not a or depth > 4 or self.subdirs >= _MAX_SUBDIRS:
                return
            sub = self.src_path(a[0])
            if sub is None:
                self.info.complete = False
                return
            sub = sub.rstrip("/")
            path = os.path.join(sub, "CMakeLists.txt")
            text = read_listfile(path)
            self.reads.append((path, text))
            if text is None:
                return
            self.subdirs += 1
            # A subdirectory runs in a copy of the parent's variable scope: its set() and project()
            # (PROJECT_NAME!) do not come back (set(... PARENT_SCOPE) aside, which we do not model).
            saved_vars = dict(self.vars)
            self.vars["CMAKE_CURRENT_SOURCE_DIR"] = sub
            self.vars["CMAKE_CURRENT_LIST_DIR"] = sub
            self.run(tokenize(text), path.replace(os.sep, "/"), depth + 1)
            self.vars = saved_vars
        elif name in self.functions:
            if any(c.name == "install" for c in self.functions[name]):
                self.info.complete = False
                self.info.executables_complete = False
        elif name == "find_package":
            a = self.args(cmd)
            if a and UNKNOWN not in a[0]:
                self.info.found_packages.add(a[0])
        else:
            # Not read here: a command of CMake or of a dependency. A dependency's own macro may
            # install files (``PackageIndex._installs_through_dependency``).
            self.info.calls.add(name)

    def ament_package(self, cmd: Command, origin: str) -> None:
        self.add_rule("file", f"share/{self.pkg_name}", self.pkg_dir + "/package.xml", cmd.line, origin)
        # CONFIG_EXTRAS: CMake files that every package finding this one runs; the macros they
        # define that install something install into the *calling* package's share directory
        # (ros2_canopen's lely_core_libraries: generate_dcf(robot) installs config/robot/).
        _, opts = _split_opts(self.args(cmd), {"CONFIG_EXTRAS", "CONFIG_EXTRAS_POST", "INSTALL_TO_SHARE"})
        for extra in opts.get("CONFIG_EXTRAS", []) + opts.get("CONFIG_EXTRAS_POST", []):
            path = self.src_path(extra) if ".cmake" in extra else None
            if path is None:
                continue
            text = read_listfile(path)
            self.reads.append((path, text))
            if text is not None:
                self.info.installers.update(_installing_definitions(tokenize(text)))

    def add_rule(self, kind: str, dest: str | None, source: str | None, line: int, origin: str,
                 **kw: object) -> None:
        if dest is None:
            self.info.complete = False
            return
        contents_only = bool(kw.pop("contents_only", False))
        if source is not None and kind == "directory":
            contents_only = contents_only or source.endswith("/")
            source = source.rstrip("/")
        self.info.rules.append(InstallRule(kind=kind, dest=dest, source=source, line=line,  # type: ignore[arg-type]
                                           origin=origin, contents_only=contents_only, **kw))  # type: ignore[arg-type]

    def target_property(self, target: str, prop: str, value: str) -> None:
        """The properties that rename what a target installs (``OUTPUT_NAME``: teleop_twist_joy
        builds target ``teleop_twist_joy_node`` into the executable ``teleop_node``)."""
        if prop not in _RENAMING:
            return
        if UNKNOWN in target:
            self.info.executables_complete = False  # some target is renamed, which one is unknown
            return
        self.output_names.setdefault(target, {})[prop] = value

    def file_name(self, target: str) -> str:
        """The file an executable target builds: the first of ``RUNTIME_OUTPUT_NAME`` and
        ``OUTPUT_NAME`` that is set (an empty one means the target's name), between ``PREFIX`` and
        ``SUFFIX`` (both empty by default on Linux)."""
        props = self.output_names.get(target, {})
        base = next((props[p] for p in ("RUNTIME_OUTPUT_NAME", "OUTPUT_NAME") if p in props), "") or target
        return props.get("PREFIX", "") + base + props.get("SUFFIX", "")

    def install(self, cmd: Command, origin: str) -> None:
        a = self.args(cmd)
        if not a:
            return
        mode = a[0]
        lib_dest = f"lib/{self.pkg_name}"
        if mode == "TARGETS":
            kws = {"EXPORT", "ARCHIVE", "LIBRARY", "RUNTIME", "OBJECTS", "FRAMEWORK", "BUNDLE",
                   "PRIVATE_HEADER", "PUBLIC_HEADER", "RESOURCE", "DESTINATION", "INCLUDES",
                   "PERMISSIONS", "CONFIGURATIONS", "COMPONENT", "OPTIONAL", "NAMELINK_ONLY",
                   "NAMELINK_SKIP", "FILE_SET", "CXX_MODULES_BMI", "EXCLUDE_FROM_ALL"}
            targets: list[str] = []
            k = 1
            while k < len(a) and a[k] not in kws:
                targets.append(a[k])
                k += 1
            runtime_to_lib = False
            section = None
            while k < len(a):
                tok = a[k]
                if tok in ("ARCHIVE", "LIBRARY", "RUNTIME", "OBJECTS", "FRAMEWORK", "BUNDLE",
                           "PRIVATE_HEADER", "PUBLIC_HEADER", "RESOURCE", "INCLUDES"):
                    section = tok
                elif tok == "DESTINATION" and k + 1 < len(a):
                    d = self.dest(a[k + 1])
                    if d == lib_dest and section in (None, "RUNTIME"):
                        runtime_to_lib = True
                    k += 1
                k += 1
            if runtime_to_lib:
                for t in targets:
                    if UNKNOWN in t:
                        self.info.executables_complete = False
                    elif t not in self.libs:
                        self.installed_targets.add(t)
        elif mode in ("PROGRAMS", "FILES"):
            files, opts = _split_opts(a[1:], {"DESTINATION", "TYPE", "PERMISSIONS", "CONFIGURATIONS",
                                              "COMPONENT", "RENAME", "OPTIONAL", "EXCLUDE_FROM_ALL"})
            dest = self.dest(opts["DESTINATION"][0]) if opts.get("DESTINATION") else None
            if dest is None and opts.get("TYPE"):
                dest = {"BIN": "bin", "DATA": "share", "SYSCONF": "etc", "LIB": "lib"}.get(opts["TYPE"][0])
            rename = opts["RENAME"][0] if opts.get("RENAME") else None
            # install(FILES ... PERMISSIONS OWNER_EXECUTE ...) installs a program too
            runnable = mode == "PROGRAMS" or any(p.endswith("_EXECUTE") for p in opts.get("PERMISSIONS", ()))
            for f in files:
                src = self.src_path(f)
                self.add_rule("file", dest, src, cmd.line, origin, rename=rename)
                if runnable and dest == lib_dest:
                    exe = rename or os.path.basename(f)
                    if UNKNOWN in exe:
                        self.info.executables_complete = False
                    else:
                        self.info.executables.add(exe)
                        if src is not None and (src.endswith(".py") or "." not in os.path.basename(src)):
                            # a Python node installed as a program (``nodes/run_demo`` too, when its
                            # first line says python: the interface store reads it): its code is
                            # its interface
                            self.info.sources.setdefault(exe, [src])
        elif mode == "DIRECTORY":
            dirs: list[str] = []
            k = 1
            stop = {"DESTINATION", "TYPE", "FILE_PERMISSIONS", "DIRECTORY_PERMISSIONS",
                    "USE_SOURCE_PERMISSIONS", "OPTIONAL", "MESSAGE_NEVER", "CONFIGURATIONS",
                    "COMPONENT", "EXCLUDE_FROM_ALL", "FILES_MATCHING", "PATTERN", "REGEX"}
            while k < len(a) and a[k] not in stop:
                dirs.append(a[k])
                k += 1
            dir_dest: str | None = None
            files_matching = False
            patterns: list[str] = []
            excludes: list[str] = []
            has_regex = False
            while k < len(a):
                tok = a[k]
                if tok == "DESTINATION" and k + 1 < len(a):
                    dir_dest = self.dest(a[k + 1])
                    k += 1
                elif tok == "FILES_MATCHING":
                    files_matching = True
                elif tok in ("PATTERN", "REGEX") and k + 1 < len(a):
                    pat = a[k + 1]
                    excl = k + 2 < len(a) and a[k + 2] == "EXCLUDE"
                    if tok == "REGEX":
                        has_regex = True
                    elif excl:
                        excludes.append(pat)
                    else:
                        patterns.append(pat)
                    k += 2 if excl else 1
                k += 1
            if has_regex:
                self.info.complete = False
            for d in dirs:
                self.add_rule("directory", dir_dest, self.src_path(d), cmd.line, origin,
                              files_matching=files_matching, patterns=tuple(patterns),
                              excludes=tuple(excludes))

    def record_sources(self, a: list[str]) -> None:
        """C/C++ sources named in ``add_executable``/``add_library``/``target_sources``."""
        out = self.target_sources.setdefault(a[0], [])
        for x in a[1:]:
            for item in x.split(";"):
                if item.endswith((".cpp", ".cc", ".cxx", ".c++", ".hpp", ".h", ".hh")):
                    p = self.src_path(item)
                    if p and p not in out:
                        out.append(p)

    def finish(self) -> None:
        if self.auto_package:
            self.installed_targets.update(self.auto_exes)
        # an installed target is the file its properties name; its sources are still the target's
        target_of = {exe: exe for exe in (self.exes - self.installed_targets) | self.info.executables}
        for target in sorted(self.installed_targets):
            name = self.file_name(target)
            if UNKNOWN in name:
                self.info.executables_complete = False
                continue
            self.info.executables.add(name)
            target_of[name] = target
        # parameter libraries reachable from each executable / plugin target, transitively
        def reach(target: str) -> list[str]:
            out: list[str] = []
            seen: set[str] = set()
            stack = [target]
            while stack:
                t = stack.pop()
                if t in seen:
                    continue
                seen.add(t)
                if t in self.param_libs and t != target:
                    p = self.param_libs[t]
                    if p:
                        out.append(p)
                stack.extend(sorted(self.links.get(t, ())))
            return sorted(set(out))

        def sources(target: str) -> list[str]:
            out: list[str] = []
            seen: set[str] = set()
            stack = [target]
            while stack:
                t = stack.pop()
                if t in seen:
                    continue
                seen.add(t)
                out.extend(p for p in self.target_sources.get(t, ()) if p not in out)
                stack.extend(sorted(x for x in self.links.get(t, ()) if x in self.libs))
            return out

        # A library may hold several node classes; only those an executable's own code names (or
        # the plugin class a component runs) are its own: interfaces/linked.py sorts them out.
        for exe, target in sorted(target_of.items()):
            srcs = sources(target)
            if srcs:
                self.info.sources[exe] = srcs
                own_srcs = self.target_sources.get(target, [])
                linked = [p for p in srcs if p not in own_srcs]
                if linked:
                    self.info.library_sources[exe] = linked
                if target in self.exe_plugins:
                    self.info.source_roots[exe] = [self.exe_plugins[target]]
        for plugin, target in sorted(self.plugin_targets.items()):
            srcs = sources(target)
            if srcs:
                self.info.sources[plugin] = srcs
                self.info.library_sources[plugin] = list(srcs)
                self.info.source_roots[plugin] = [plugin]
        for exe, target in sorted(target_of.items()):
            ys = reach(target)
            if ys:
                self.info.parameter_yamls[exe] = ys
        for plugin, target in self.plugin_targets.items():
            own = self.param_libs.get(target)
            ys = reach(target) + ([own] if own else [])
            if ys:
                self.info.parameter_yamls[plugin] = sorted({y for y in ys if y})


# ament_cmake_gtest / ament_cmake_gmock commands that add an executable target from sources.
_TEST_EXECUTABLES = frozenset({"ament_add_gtest", "ament_add_gtest_executable", "ament_add_gmock",
                               "ament_add_gmock_executable"})
# Target properties that name the file an executable target builds.
_RENAMING = ("OUTPUT_NAME", "RUNTIME_OUTPUT_NAME", "PREFIX", "SUFFIX")


def _block(cmds: list[Command], i: int, start: str, end: str) -> tuple[list[Command], int]:
    depth = 0
    body: list[Command] = []
    j = i + 1
    while j < len(cmds):
        c = cmds[j]
        if c.name == start:
            depth += 1
        elif c.name == end:
            if depth == 0:
                return body, j + 1
            depth -= 1
        body.append(c)
        j += 1
    return body, j


def _installing_definitions(cmds: list[Command]) -> set[str]:
    """The (lower-case) names of the functions and macros ``cmds`` define whose bodies install
    something, directly or through another such definition of the same file."""
    bodies: dict[str, list[Command]] = {}
    i = 0
    while i < len(cmds):
        cmd = cmds[i]
        if cmd.name in ("function", "macro"):
            body, i = _block(cmds, i, cmd.name, "end" + cmd.name)
            first = next((a.value for a in cmd.args), None)
            if first:
                bodies[first.lower()] = body
            continue
        i += 1
    found = {n for n, body in bodies.items() if any(c.name == "install" for c in body)}
    grew = True
    while grew:
        grew = False
        for n, body in bodies.items():
            if n not in found and any(c.name in found for c in body):
                found.add(n)
                grew = True
    return found


def _kwarg(a: list[str], key: str) -> str | None:
    if key in a:
        k = a.index(key)
        if k + 1 < len(a):
            return a[k + 1]
    return None


def _split_opts(a: list[str], keys: set[str]) -> tuple[list[str], dict[str, list[str]]]:
    items: list[str] = []
    opts: dict[str, list[str]] = {}
    cur: str | None = None
    for tok in a:
        if tok in keys:
            cur = tok
            opts.setdefault(tok, [])
        elif cur is None:
            items.append(tok)
        else:
            opts[cur].append(tok)
    return items, opts


def read_listfile(path: str) -> str | None:
    """A CMake file's text as the reader reads it (``read_cmake_package(reads=...)`` names them)."""
    try:
        with open(path, encoding="utf-8", errors="replace") as fh:
            return fh.read()
    except OSError:
        return None


def read_cmake_package(pkg_dir: str, pkg_name: str, text: str | None = None,
                       reads: list[tuple[str, str | None]] | None = None) -> BuildInfo:
    """Read ``<pkg_dir>/CMakeLists.txt`` statically into a ``BuildInfo``. The result is a pure
    function of the arguments and of the files appended to ``reads`` (``(path, text or None)``,
    as ``read_listfile`` reads them: the ``add_subdirectory`` files)."""
    info = BuildInfo()
    path = pkg_dir + "/CMakeLists.txt"
    if text is None:
        text = read_listfile(path)
    if text is None:
        info.complete = info.executables_complete = False
        info.problems.append((path, "CMakeLists.txt not found", 1))
        return info
    interp = _Interp(pkg_dir, pkg_name, info)
    interp.vars.update(CMAKE_CURRENT_SOURCE_DIR=pkg_dir, PROJECT_SOURCE_DIR=pkg_dir,
                       CMAKE_SOURCE_DIR=pkg_dir, CMAKE_CURRENT_LIST_DIR=pkg_dir)
    interp.run(tokenize(text), path)
    interp.finish()
    if reads is not None:
        reads.extend(interp.reads)
    return info
