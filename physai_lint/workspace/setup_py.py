"""ament_python packages: ``setup.py`` is parsed with ``ast`` and partially evaluated -- never
executed. Module-level assignments, ``os.path.join``, ``+``, f-strings, ``%``/``.format``,
``glob(...)`` (against the package's file snapshot) and ``data_files.append/extend`` are understood;
anything else makes the affected value unknown (and the package's install rules incomplete)."""
from __future__ import annotations

import ast
import configparser
import os
import posixpath
from collections.abc import Collection

from physai_lint.pyast import ast_nodes

from ._glob import glob_files
from ._model import BuildInfo, InstallRule


class _Unknown(Exception):
    pass


class _Eval:
    def __init__(self, pkg_dir: str, files: Collection[str]) -> None:
        self.pkg_dir = pkg_dir
        self.files = files
        self.env: dict[str, object] = {}
        self.os_aliases = {"os"}
        self.path_aliases: set[str] = set()  # from os import path / import os.path as p
        self.join_aliases: set[str] = set()  # from os.path import join
        self.glob_aliases: set[str] = set()  # from glob import glob
        self.glob_modules: set[str] = set()  # import glob

    def value(self, node: ast.AST) -> object:
        if isinstance(node, ast.Constant):
            return node.value
        if isinstance(node, (ast.List, ast.Tuple)):
            out: list[object] = []
            for elt in node.elts:
                if isinstance(elt, ast.Starred):
                    v = self.value(elt.value)
                    if not isinstance(v, (list, tuple)):
                        raise _Unknown()
                    out.extend(v)
                else:
                    out.append(self.value(elt))
            return out if isinstance(node, ast.List) else tuple(out)
        if isinstance(node, ast.Dict):
            d: dict[object, object] = {}
            for k, v in zip(node.keys, node.values):
                if k is None:
                    raise _Unknown()
                d[self.value(k)] = self.value(v)
            return d
        if isinstance(node, ast.Name):
            if node.id in self.env:
                return self.env[node.id]
            raise _Unknown()
        if isinstance(node, ast.BinOp):
            left, right = self.value(node.left), self.value(node.right)
            if isinstance(node.op, ast.Add):
                if isinstance(left, str) and isinstance(right, str):
                    return left + right
                if isinstance(left, (list, tuple)) and isinstance(right, (list, tuple)):
                    return list(left) + list(right)
            if isinstance(node.op, ast.Mod) and isinstance(left, str):
                try:
                    return left % (tuple(right) if isinstance(right, (list, tuple)) else right)
                except (TypeError, ValueError):
                    raise _Unknown() from None
            raise _Unknown()
        if isinstance(node, ast.JoinedStr):
            parts: list[str] = []
            for v in node.values:
                if isinstance(v, ast.Constant):
                    parts.append(str(v.value))
                elif isinstance(v, ast.FormattedValue) and v.format_spec is None:
                    val = self.value(v.value)
                    if not isinstance(val, (str, int, float)):
                        raise _Unknown()
                    parts.append(str(val))
                else:
                    raise _Unknown()
            return "".join(parts)
        if isinstance(node, ast.Call):
            return self.call(node)
        if isinstance(node, ast.ListComp):
            return self.listcomp(node)
        raise _Unknown()

    def _qual(self, func: ast.AST) -> str:
        if isinstance(func, ast.Name):
            if func.id in self.join_aliases:
                return "os.path.join"
            if func.id in self.glob_aliases:
                return "glob.glob"
            return func.id
        if isinstance(func, ast.Attribute):
            base = func.value
            if (isinstance(base, ast.Attribute) and isinstance(base.value, ast.Name)
                    and base.value.id in self.os_aliases and base.attr == "path"):
                return "os.path." + func.attr
            if isinstance(base, ast.Name):
                if base.id in self.path_aliases:
                    return "os.path." + func.attr
                if base.id in self.glob_modules:
                    return "glob." + func.attr
        return ""

    def call(self, node: ast.Call) -> object:
        q = self._qual(node.func)
        if q == "os.path.join":
            parts = [self.value(a) for a in node.args]
            if not all(isinstance(p, str) for p in parts) or not parts:
                raise _Unknown()
            return posixpath.join(*[str(p) for p in parts])
        if q in ("glob.glob", "glob.iglob"):
            if not node.args:
                raise _Unknown()
            pat = self.value(node.args[0])
            recursive = False
            for kw in node.keywords:
                if kw.arg == "recursive":
                    recursive = bool(self.value(kw.value))
                elif kw.arg in ("root_dir", "dir_fd"):
                    raise _Unknown()
            if not isinstance(pat, str):
                raise _Unknown()
            if os.path.isabs(pat):
                rel = os.path.relpath(pat, self.pkg_dir).replace(os.sep, "/")
                if rel.startswith(".."):
                    raise _Unknown()
                return [self.pkg_dir + "/" + f for f in glob_files(rel, self.files, recursive)]
            return glob_files(pat, self.files, recursive)
        if q in ("os.path.dirname", "os.path.abspath", "os.path.realpath") and node.args:
            v = self.value(node.args[0])
            if isinstance(v, str) and q == "os.path.dirname":
                return posixpath.dirname(v)
            raise _Unknown()
        if isinstance(node.func, ast.Attribute) and node.func.attr == "format":
            base = self.value(node.func.value)
            if isinstance(base, str):
                args = [self.value(a) for a in node.args]
                kwargs = {kw.arg: self.value(kw.value) for kw in node.keywords if kw.arg}
                try:
                    return base.format(*args, **kwargs)
                except (IndexError, KeyError, ValueError):
                    raise _Unknown() from None
        if isinstance(node.func, ast.Name) and node.func.id in ("list", "sorted", "tuple") and len(node.args) == 1:
            v = self.value(node.args[0])
            if isinstance(v, (list, tuple)):
                return sorted(v, key=str) if node.func.id == "sorted" else list(v)
        raise _Unknown()

    def listcomp(self, node: ast.ListComp) -> object:
        if len(node.generators) != 1:
            raise _Unknown()
        gen = node.generators[0]
        if not isinstance(gen.target, ast.Name) or gen.ifs or gen.is_async:
            raise _Unknown()
        seq = self.value(gen.iter)
        if not isinstance(seq, (list, tuple)):
            raise _Unknown()
        out = []
        saved = self.env.get(gen.target.id, _MISSING)
        try:
            for item in seq:
                self.env[gen.target.id] = item
                out.append(self.value(node.elt))
        finally:
            if saved is _MISSING:
                self.env.pop(gen.target.id, None)
            else:
                self.env[gen.target.id] = saved
        return out


_MISSING = object()


def _ros2_branch(body: list[ast.stmt]) -> list[ast.stmt]:
    """``body`` with each module-level ``if ROS_VERSION == 2:`` (or ``int(os.environ['ROS_VERSION'])``,
    ``os.getenv('ROS_VERSION')``...) replaced by the branch colcon runs on ROS 2, as package.xml's
    ``condition="$ROS_VERSION == 2"`` is read: packages shared with ROS 1 (carla's) call setup()
    in both branches."""
    out: list[ast.stmt] = []
    for stmt in body:
        taken = _ros2_test(stmt.test) if isinstance(stmt, ast.If) else None
        if taken is None:
            out.append(stmt)
        else:
            out.extend(_ros2_branch(stmt.body if taken else stmt.orelse))
    return out


def _ros_version(node: ast.AST) -> bool:
    """Whether ``node`` reads ROS_VERSION: the name, ``os.environ['ROS_VERSION']``, ``.get(...)``,
    ``os.getenv(...)``, or ``int``/``str`` of one of those."""
    if isinstance(node, ast.Name):
        return node.id == "ROS_VERSION"
    if isinstance(node, ast.Subscript):
        return isinstance(node.slice, ast.Constant) and node.slice.value == "ROS_VERSION"
    if isinstance(node, ast.Call):
        if isinstance(node.func, ast.Name) and node.func.id in ("int", "str") and len(node.args) == 1:
            return _ros_version(node.args[0])
        return bool(node.args) and isinstance(node.args[0], ast.Constant) and node.args[0].value == "ROS_VERSION"
    return False


def _ros2_test(test: ast.AST) -> bool | None:
    """The value of an ``if`` test comparing ROS_VERSION with a constant, on ROS 2; None for any
    other test."""
    if not (isinstance(test, ast.Compare) and len(test.ops) == 1 and _ros_version(test.left)
            and isinstance(test.comparators[0], ast.Constant)):
        return None
    want = test.comparators[0].value
    have: object = 2 if isinstance(want, int) else "2"
    ops = {ast.Eq: lambda a, b: a == b, ast.NotEq: lambda a, b: a != b, ast.GtE: lambda a, b: a >= b,
           ast.Gt: lambda a, b: a > b, ast.LtE: lambda a, b: a <= b, ast.Lt: lambda a, b: a < b}
    fn = ops.get(type(test.ops[0]))
    try:
        return None if fn is None else bool(fn(have, want))
    except TypeError:
        return None


def _find_setup_call(nodes: list[ast.AST]) -> ast.Call | None:
    for node in nodes:
        if isinstance(node, ast.Call):
            f = node.func
            name = f.id if isinstance(f, ast.Name) else f.attr if isinstance(f, ast.Attribute) else ""
            if name == "setup" and any(kw.arg in ("name", "data_files", "entry_points", "packages") for kw in node.keywords):
                return node
    return None


def _script_dirs(pkg_dir: str) -> list[str]:
    """Where ``setup.cfg`` sends console scripts (``script_dir``, ``install_scripts``), as written;
    empty when there is no setup.cfg or it says nothing (they go to ``bin/``)."""
    path = pkg_dir + "/setup.cfg"
    if not os.path.isfile(path):
        return []
    cp = configparser.RawConfigParser()
    try:
        cp.read(path, encoding="utf-8")
    except (configparser.Error, OSError, UnicodeDecodeError):
        return []
    return [cp.get(section, key).strip().replace("\\", "/").rstrip("/")
            for section, key in (("develop", "script_dir"), ("develop", "script-dir"),
                                 ("install", "install_scripts"), ("install", "install-scripts"))
            if cp.has_option(section, key)]


def read_setup_py(pkg_dir: str, pkg_name: str, files: Collection[str], text: str | None) -> BuildInfo:
    info = BuildInfo()
    path = pkg_dir + "/setup.py"
    if text is None:
        info.complete = info.executables_complete = False
        info.problems.append((path, "ament_python package without setup.py", 1))
        return info
    try:
        tree = ast.parse(text, filename=path)
    except (SyntaxError, ValueError) as exc:
        info.complete = info.executables_complete = False
        info.problems.append((path, f"setup.py does not parse: {exc}", getattr(exc, "lineno", 1) or 1))
        return info
    ev = _Eval(pkg_dir, files)
    tree.body = _ros2_branch(tree.body)
    nodes = ast_nodes(tree)
    setup_call = _find_setup_call(nodes)
    data_files: list[object] | None = None
    data_files_var: str | None = None
    if setup_call is not None:
        for kw in setup_call.keywords:
            if kw.arg == "data_files" and isinstance(kw.value, ast.Name):
                data_files_var = kw.value.id
    # module-level statements, in order (setup() itself is usually last)
    for stmt in tree.body:
        if isinstance(stmt, ast.Import):
            for al in stmt.names:
                if al.name == "os":
                    ev.os_aliases.add(al.asname or "os")
                elif al.name == "os.path" and al.asname:
                    ev.path_aliases.add(al.asname)
                elif al.name == "glob":
                    ev.glob_modules.add(al.asname or "glob")
        elif isinstance(stmt, ast.ImportFrom):
            for al in stmt.names:
                if stmt.module == "glob" and al.name in ("glob", "iglob"):
                    ev.glob_aliases.add(al.asname or al.name)
                elif stmt.module == "os" and al.name == "path":
                    ev.path_aliases.add(al.asname or "path")
                elif stmt.module == "os.path" and al.name == "join":
                    ev.join_aliases.add(al.asname or "join")
        elif isinstance(stmt, ast.Assign) and len(stmt.targets) == 1 and isinstance(stmt.targets[0], ast.Name):
            name = stmt.targets[0].id
            try:
                ev.env[name] = ev.value(stmt.value)
            except _Unknown:
                ev.env.pop(name, None)
                if name == data_files_var:
                    info.complete = False
        elif isinstance(stmt, ast.AugAssign) and isinstance(stmt.target, ast.Name):
            name = stmt.target.id
            try:
                cur, add = ev.env[name], ev.value(stmt.value)
                if isinstance(stmt.op, ast.Add) and isinstance(cur, list) and isinstance(add, (list, tuple)):
                    ev.env[name] = cur + list(add)
                elif isinstance(stmt.op, ast.Add) and isinstance(cur, str) and isinstance(add, str):
                    ev.env[name] = cur + add
                else:
                    raise _Unknown()
            except (_Unknown, KeyError):
                ev.env.pop(name, None)
                if name == data_files_var:
                    info.complete = False
        elif isinstance(stmt, ast.Expr) and isinstance(stmt.value, ast.Call):
            call = stmt.value
            f = call.func
            if (isinstance(f, ast.Attribute) and isinstance(f.value, ast.Name)
                    and f.attr in ("append", "extend") and isinstance(ev.env.get(f.value.id), list)):
                try:
                    v = ev.value(call.args[0])
                    target = ev.env[f.value.id]
                    assert isinstance(target, list)
                    if f.attr == "append":
                        target.append(v)
                    elif isinstance(v, (list, tuple)):
                        target.extend(v)
                    else:
                        raise _Unknown()
                except (_Unknown, IndexError):
                    if f.value.id == data_files_var:
                        info.complete = False
        elif (isinstance(stmt, (ast.For, ast.While, ast.With, ast.FunctionDef, ast.If, ast.Try))
              and data_files_var
              and any(isinstance(n, ast.Name) and n.id == data_files_var for n in ast.walk(stmt))):
            # a loop or function may add data files we cannot see
            info.complete = False
    # generate_parameter_module(module_name, yaml_file) anywhere in the file
    for node in nodes:
        if isinstance(node, ast.Call):
            f = node.func
            fname = f.id if isinstance(f, ast.Name) else f.attr if isinstance(f, ast.Attribute) else ""
            if fname == "generate_parameter_module" and len(node.args) >= 2:
                try:
                    mod, yml = ev.value(node.args[0]), ev.value(node.args[1])
                except _Unknown:
                    continue
                if isinstance(mod, str) and isinstance(yml, str):
                    info.parameter_modules.append((mod, posixpath.normpath(posixpath.join(pkg_dir, yml))))
    if setup_call is None:
        info.complete = info.executables_complete = False
        info.problems.append((path, "no setup() call found in setup.py", 1))
        return info
    line = setup_call.lineno
    scripts: list[tuple[str, str]] = []
    plain_scripts: list[str] = []
    for kw in setup_call.keywords:
        if kw.arg is None:
            info.complete = info.executables_complete = False
            continue
        try:
            val = ev.value(kw.value)
        except _Unknown:
            if kw.arg == "data_files":
                info.complete = False
            elif kw.arg == "entry_points":
                info.executables_complete = False
                info.problems.append((path, "entry_points could not be read statically", kw.value.lineno))
            elif kw.arg == "scripts":
                info.executables_complete = False
            continue
        if kw.arg == "data_files":
            data_files = val if isinstance(val, (list, tuple)) else None  # type: ignore[assignment]
            if data_files is None:
                info.complete = False
            line = kw.value.lineno
        elif kw.arg == "entry_points":
            scripts.extend(_console_scripts(val))
        elif kw.arg == "scripts":
            # distutils scripts: copied, under their own file names, to where console scripts go
            # (install_scripts / script_dir: lib/<pkg> with the usual setup.cfg)
            if isinstance(val, (list, tuple)) and all(isinstance(x, str) for x in val):
                plain_scripts.extend(posixpath.normpath(x.replace("\\", "/")) for x in val)
            else:
                info.executables_complete = False
        elif kw.arg == "packages" and isinstance(val, (list, tuple)):
            info.python_packages.update(p for p in val if isinstance(p, str))
    # console scripts
    dirs = _script_dirs(pkg_dir)
    to_lib = any(d.endswith("lib/" + pkg_name) for d in dirs)
    if not to_lib and dirs:
        info.scripts_dir = dirs[0]
    script_targets: dict[str, str] = {}
    for exe, target in scripts:
        (info.executables if to_lib else info.executables_in_bin).add(exe)
        script_targets[exe] = target
    for script in plain_scripts:
        exe = posixpath.basename(script)
        (info.executables if to_lib else info.executables_in_bin).add(exe)
        if script in files and script.endswith(".py"):
            info.sources.setdefault(exe, [pkg_dir + "/" + script])  # its interface, node name
    # data files -> install rules
    registers = False
    for entry in data_files or []:
        if not (isinstance(entry, (list, tuple)) and len(entry) == 2):
            info.complete = False
            continue
        dest, srcs = entry
        if not isinstance(dest, str) or not isinstance(srcs, (list, tuple)):
            info.complete = False
            continue
        dest = posixpath.normpath(dest.replace("\\", "/")).lstrip("/")
        for s in srcs:
            if not isinstance(s, str):
                info.complete = False
                continue
            src = posixpath.normpath(s if os.path.isabs(s) else pkg_dir + "/" + s)
            info.rules.append(InstallRule("file", dest, src, line, path))
            if dest == "share/ament_index/resource_index/packages" and posixpath.basename(src) == pkg_name:
                registers = True
    info.registers_in_index = registers or not info.complete
    # link parameter modules to console scripts whose module mentions them
    for exe, target in sorted(script_targets.items()):
        mod = target.split(":")[0].strip()
        mod_path = pkg_dir + "/" + mod.replace(".", "/") + ".py"
        text_mod = None
        rel = mod_path[len(pkg_dir) + 1 :]
        if rel not in files:
            rel = mod.replace(".", "/") + "/__init__.py"
            mod_path = pkg_dir + "/" + rel
        if rel in files:
            info.sources[exe] = [mod_path]
            try:
                with open(mod_path, encoding="utf-8", errors="replace") as fh:
                    text_mod = fh.read(2_000_000)
            except OSError:
                text_mod = None
        for modname, yml in info.parameter_modules:
            short = modname.rsplit(".", 1)[-1]
            if text_mod is not None and short in text_mod:
                info.parameter_yamls.setdefault(exe, []).append(yml)
    return info


def setup_cfg_console_scripts(text: str) -> list[str] | None:
    """The console script names of a setup.cfg's ``[options.entry_points] console_scripts``; None
    when the text is not a readable setup.cfg."""
    cp = configparser.RawConfigParser()
    try:
        cp.read_string(text)
    except (configparser.Error, ValueError):
        return None
    if not cp.has_option("options.entry_points", "console_scripts"):
        return []
    return [exe for exe, _ in _console_scripts({"console_scripts": cp.get("options.entry_points",
                                                                          "console_scripts")})]


def _console_scripts(val: object) -> list[tuple[str, str]]:
    out: list[tuple[str, str]] = []
    if isinstance(val, dict):
        cs = val.get("console_scripts", [])
        if isinstance(cs, str):
            cs = [ln for ln in cs.splitlines() if ln.strip()]
        if isinstance(cs, (list, tuple)):
            for item in cs:
                if isinstance(item, str) and "=" in item:
                    exe, target = item.split("=", 1)
                    if exe.strip():
                        out.append((exe.strip(), target.strip()))
    return out
