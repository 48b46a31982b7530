"""Calls, attributes, subscripts and imports for the evaluator.

Only pure operations on known data run for real (str/list/dict methods on concrete values);
everything touching the machine (environment, files outside ``read_file``, processes) is Opaque.
"""
from __future__ import annotations

import ast
import dataclasses
import json
import posixpath
from typing import TYPE_CHECKING, Any

import yaml

from physai_lint.model.launch import EVERY_CONFIGURATION, ConcatFact, LateFact
from physai_lint.model.span import Span
from physai_lint.model.values import FindPackage, LaunchConfig, StrMethod, Text, Unknown, Value

from . import api, bounds, builtin_calls, classes, symbolic
from .convert_values import span_at, to_value
from .runtime import (
    BoundMethod,
    BoundUser,
    ClassValue,
    ContextSym,
    Decorator,
    FileHandle,
    Instance,
    KPath,
    LaunchConfigsSym,
    LObj,
    ModuleValue,
    Opaque,
    Partial,
    Ref,
    SuperProxy,
    SymStr,
    UserFunc,
)

if TYPE_CHECKING:
    from .evaluator import Evaluator, Scope

_STR_METHODS = frozenset(
    ["capitalize", "casefold", "center", "count", "endswith", "expandtabs", "find", "index", "isalnum", "isalpha", "isascii", "isdecimal", "isdigit", "isidentifier", "islower", "isnumeric", "isspace", "istitle", "isupper", "ljust", "lower", "lstrip", "partition", "removeprefix", "removesuffix", "replace", "rfind", "rindex", "rjust", "rpartition", "rsplit", "rstrip", "split", "splitlines", "startswith", "strip", "swapcase", "title", "upper", "zfill"])
_LIST_METHODS = frozenset(["append", "extend", "insert", "pop", "index", "count", "copy", "remove", "reverse", "clear"])
_GROWING = frozenset(["append", "extend", "insert", "update", "setdefault"])
_DICT_METHODS = frozenset(["items", "keys", "values", "get", "update", "copy", "pop", "setdefault"])
_KNOWN_MODULES = frozenset(["os", "os.path", "sys", "json", "yaml", "pathlib", "math", "re", "typing", "functools", "itertools", "ament_index_python", "tempfile", "xacro", "subprocess", "shutil", "glob", "collections", "dataclasses", "launch_ros", "launch", "launch_xml", "launch_yaml", "ament_index_python.packages"])


def iterate(ev: Evaluator, v: Any) -> list[Any] | None:
    """The items of a known iterable, else None."""
    if isinstance(v, LaunchConfigsSym):
        ev.escaped.add(EVERY_CONFIGURATION)  # iterating the mapping reads every configuration
        return None
    if isinstance(v, dict):
        return list(v.keys())
    if isinstance(v, (list, tuple, str, set, frozenset, range)):
        if isinstance(v, (set, frozenset)):
            try:
                return sorted(v)
            except TypeError:
                return list(v)
        return list(v)
    return None


def get_attr(ev: Evaluator, obj: Any, attr: str, span: Span) -> Any:
    if isinstance(obj, Opaque):
        return Opaque(obj.reason, span)
    if isinstance(obj, Ref):
        return Ref(f"{obj.qual}.{attr}")
    if isinstance(obj, ModuleValue):
        return obj.globals.get(attr, Opaque(f'"{attr}" not found in module "{obj.name}"', span))
    if isinstance(obj, (ClassValue, Instance, SuperProxy)):
        return classes.get_attr(ev, obj, attr, span)
    if isinstance(obj, ContextSym) and attr == "launch_configurations":
        return LaunchConfigsSym()
    if isinstance(obj, KPath):
        if attr == "parent":
            return KPath(posixpath.dirname(obj.path)) if isinstance(obj.path, str) else Opaque("path", span)
        if attr in ("name", "stem", "suffix") and isinstance(obj.path, str):
            name = posixpath.basename(obj.path)
            return {"name": name, "stem": posixpath.splitext(name)[0], "suffix": posixpath.splitext(name)[1]}[attr]
    if isinstance(obj, LObj) and attr == "name" and obj.qual == "launch.actions.DeclareLaunchArgument":
        name = obj.arg(0, "name")  # ``{a.name: LaunchConfiguration(a.name) for a in args}``
        if isinstance(name, str):
            return name
    if isinstance(obj, (LObj, ContextSym, LaunchConfigsSym, SymStr, KPath, FileHandle, str, list, dict, tuple)):
        return BoundMethod(obj, attr)
    return Opaque(f'attribute "{attr}" cannot be evaluated statically', span)


def env_read(ev: Evaluator, name: Any, span: Span) -> Any:
    """An environment variable read at description time: ``ROS_DISTRO`` is the ``--distro`` being
    checked (the distro sourced before ``ros2 launch``); every other variable is unknown."""
    if isinstance(name, str) and name in ev.env:
        return ev.env[name]
    shown = f' "{name}"' if isinstance(name, str) else ""
    return Opaque(f"depends on the environment variable{shown}", span)


def contains(ev: Evaluator, obj: Any, key: Any, span: Span) -> Any:
    """``key in obj`` for what launch files test at description time: ``name in os.environ`` (true
    for the variables the check knows), and ``name in context.launch_configurations``, a read of
    the name (L102), true where the resolver found it set (``specialize``). Else known only at
    launch time; None: not one of these tests."""
    if isinstance(obj, Ref) and obj.qual == "os.environ":
        return True if isinstance(key, str) and key in ev.env else Opaque("depends on the environment", span)
    if not isinstance(obj, LaunchConfigsSym):
        return None
    if not isinstance(key, str):
        ev.escaped.add(EVERY_CONFIGURATION)
        return Opaque("a test of a launch configuration named at launch time", span)
    unset = (Unknown("None: the launch configuration is not set", span),)
    found = _peeked(ev, (LaunchConfig((Text(key, span),), unset, span),))
    if isinstance(found, str):
        return True
    return Opaque(f'whether launch configuration "{key}" is set is known only at launch time', span)


def subscript(ev: Evaluator, obj: Any, key: Any, span: Span) -> Any:
    if isinstance(obj, Ref) and obj.qual == "os.environ":
        return env_read(ev, key, span)
    if isinstance(obj, LaunchConfigsSym):
        if isinstance(key, str):
            return _peeked(ev, (LaunchConfig((Text(str(key), span),), None, span),))
        ev.escaped.add(EVERY_CONFIGURATION)  # a name known only at launch time: any of them
    if isinstance(obj, (dict, list, tuple, str)) and not isinstance(key, Opaque):
        try:
            result = obj[key]
        except Exception:  # noqa: BLE001 - e.g. a missing key: unknown, not a crash
            return Opaque("subscript fails statically", span)
        if isinstance(obj, (list, tuple)) and isinstance(key, slice):
            return result
        return result
    reason = obj.reason if isinstance(obj, Opaque) else (key.reason if isinstance(key, Opaque) else "subscript of an unknown value")
    return Opaque(reason, span)


def import_module(ev: Evaluator, name: str, level: int, scope: Scope) -> Any:
    top = name.split(".")[0]
    if level == 0 and (top in api.ROOTS or name in _KNOWN_MODULES or top in _KNOWN_MODULES):
        return Ref(name)
    loaded = _load_sibling(ev, name, level, scope)
    return loaded if loaded is not None else Ref(name)


def _load_sibling(ev: Evaluator, name: str, level: int, scope: Scope) -> ModuleValue | None:
    if ev.read_file is None or not name:
        return None
    from .core import Abort, ModuleCtx, Signal
    from .positions import SpanMaker

    base = posixpath.dirname((scope.module or ev.main).path)
    for _ in range(max(level - 1, 0)):
        base = posixpath.dirname(base)
    rel = name.replace(".", "/")
    for cand in (f"{base}/{rel}.py", f"{base}/{rel}/__init__.py"):
        if cand in ev.modules:
            cached = ev.modules[cand]
            return cached if isinstance(cached, ModuleValue) else None
        text = ev.read_file(cand)
        if text is None:
            continue
        ev.modules[cand] = None  # cycle guard
        try:
            tree = ast.parse(text, cand)
        except (SyntaxError, ValueError, RecursionError, MemoryError):
            return None
        ev.read_files.append(cand)
        ctx = ModuleCtx(cand, SpanMaker(cand, text), posixpath.basename(cand) + ":")
        try:
            ev.exec_block(tree.body, ctx.scope)
        except (Signal, Abort, RecursionError):  # a helper module we cannot follow is partly unknown
            pass
        mod = ModuleValue(name, ctx.scope.vars)
        ev.modules[cand] = mod
        return mod
    return None


def call(ev: Evaluator, func: Any, args: list[Any], kwargs: dict[str, Any], node: ast.Call,
         scope: Scope, arg_spans: list[Span], kw_spans: dict[str, Span]) -> Any:
    span = ev.span(node, scope)
    if isinstance(func, UserFunc):
        return call_user(ev, func, args, kwargs, span, written=True)
    if isinstance(func, Ref):
        qual = api.canonical(func.qual)
        if qual is not None and qual not in api.FUNCTIONS:
            return make_lobj(ev, qual, args, kwargs, node, scope, arg_spans, kw_spans)
        return call_ref(ev, qual or func.qual, args, kwargs, span)
    if isinstance(func, Partial):
        return call_user(ev, func.func, *func.bind(args, kwargs), span, written=True)
    if isinstance(func, BoundMethod):
        return call_method(ev, func.obj, func.name, args, kwargs, span)
    if isinstance(func, BoundUser):
        return call_user(ev, func.func, [func.obj, *args], kwargs, span, written=True)
    if isinstance(func, ClassValue):
        return classes.instantiate(ev, func, args, kwargs, span, written=True)
    if isinstance(func, Decorator) and func.kind == "cache" and len(args) == 1 and isinstance(args[0], UserFunc):
        return classes.cached(args[0], func.maxsize)
    ev.escape([*args, *kwargs.values()])
    if isinstance(func, Opaque):
        return Opaque(func.reason, span)
    return Opaque("call of a value that cannot be evaluated statically", span)


def call_user(ev: Evaluator, f: UserFunc, args: list[Any], kwargs: dict[str, Any], span: Span,
              written: bool = False) -> Any:
    """Run user function ``f``; ``written``: a call the file writes, whose arguments are all known
    (no unknown ``*args``/``**kwargs``), so one its signature refuses is noted (TypeError)."""
    from .evaluator import MAX_DEPTH, Abort, Scope

    refused = refused_arguments(f.node, len(f.defaults), set(f.kw_defaults), len(args), list(kwargs)) \
        if written else None
    if refused is not None:  # Python raises here: nothing the body builds exists
        ev.call_errors.setdefault(span, ConcatFact("call", span, refused))  # type: ignore[arg-type]
        return Opaque(f"raises TypeError: {refused}", span)
    if ev.depth >= MAX_DEPTH:
        return Opaque("call depth limit reached (recursive helper?)", span)
    if any(isinstance(v, Opaque) for v in [*args, *kwargs.values()]) and \
            any(g.node is f.node for g, _ in ev.frames):
        # a recursive helper walking data not known statically (flatten(yaml.safe_load(f))): each
        # level tries every branch of its unknown tests, so the walk grows exponentially
        return Opaque(f'recursive call of "{getattr(f.node, "name", "lambda")}" on a value not known '
                      "statically", span)
    if f.memo is not None:
        return _call_cached(ev, f, args, kwargs, span)
    a = f.node.args
    fscope = Scope(f.closure, f.module)
    positional = [p.arg for p in a.posonlyargs + a.args]
    defaults = dict(zip(positional[len(positional) - len(f.defaults):], f.defaults))
    for i, name in enumerate(positional):
        if i < len(args):
            fscope.vars[name] = args[i]
        elif name in kwargs:
            fscope.vars[name] = kwargs.pop(name)
        elif name in defaults:
            fscope.vars[name] = defaults[name]
        else:
            fscope.vars[name] = Opaque(f'missing argument "{name}"', span)
    if a.vararg is not None:
        fscope.vars[a.vararg.arg] = tuple(args[len(positional):])
    for kw in a.kwonlyargs:
        fscope.vars[kw.arg] = kwargs.pop(kw.arg, f.kw_defaults.get(kw.arg, Opaque(f'missing argument "{kw.arg}"', span)))
    if a.kwarg is not None:
        fscope.vars[a.kwarg.arg] = {k: v for k, v in kwargs.items() if k not in positional}
    ev.depth += 1
    ev.frames.append((f, fscope))
    try:
        if isinstance(f.node, ast.Lambda):
            return ev.ev(f.node.body, fscope)
        return ev.run_function(f.node.body, fscope)
    except Abort as e:
        return Opaque(e.reason, span)
    except RecursionError:
        return Opaque("too deeply nested to evaluate", span)
    finally:
        ev.frames.pop()
        ev.depth -= 1


def refused_arguments(node: ast.FunctionDef | ast.AsyncFunctionDef | ast.Lambda, defaults: int,
                      kw_defaults: set[str], given: int, keywords: list[str]) -> str | None:
    """The TypeError Python raises when a function of signature ``node`` (its last ``defaults``
    positional parameters and the keyword-only ones in ``kw_defaults`` have defaults) is called
    with ``given`` positional arguments and the keyword arguments ``keywords``, in the order
    CPython checks them (``initialize_locals``: keywords, then the positional count, then
    what is missing); None when it accepts them."""
    a = node.args
    name = f"{getattr(node, 'name', '<lambda>')}()"
    positional = [p.arg for p in a.posonlyargs + a.args]
    posonly = {p.arg for p in a.posonlyargs}
    named = set(positional) | {k.arg for k in a.kwonlyargs}
    for k in keywords:
        if k in posonly and a.kwarg is None:
            return f"{name} got some positional-only arguments passed as keyword arguments: '{k}'"
        if k not in named and a.kwarg is None:
            return f"{name} got an unexpected keyword argument '{k}'"
        if k in positional and k not in posonly and positional.index(k) < given:
            return f"{name} got multiple values for argument '{k}'"
    if given > len(positional) and a.vararg is None:
        takes = len(positional)
        least = takes - defaults
        counted = f"from {least} to {takes}" if defaults else str(takes)
        return (f"{name} takes {counted} positional argument{'s' if takes != 1 or defaults else ''} "
                f"but {given} {'was' if given == 1 else 'were'} given")
    filled = set(positional[:given]) | (set(keywords) - posonly)  # f(a, /, **kw): f(a=1) fills kw
    missing = [p for p in positional[:len(positional) - defaults] if p not in filled]
    kind = "positional"
    if not missing:
        missing = [k.arg for k in a.kwonlyargs if k.arg not in kw_defaults and k.arg not in filled]
        kind = "keyword-only"
    if not missing:
        return None
    listed = [f"'{m}'" for m in missing]
    shown = listed[0] if len(listed) == 1 else ", ".join(listed[:-1]) + ("," if len(listed) > 2 else "") + \
        f" and {listed[-1]}"
    return f"{name} missing {len(missing)} required {kind} argument{'s' if len(missing) > 1 else ''}: {shown}"


def _call_cached(ev: Evaluator, f: UserFunc, args: list[Any], kwargs: dict[str, Any], span: Span) -> Any:
    """A ``functools.cache``/``lru_cache`` function: the same object for the same arguments, as Python
    gives (a cached Node added twice is one action). Unknown arguments are not cached."""
    from .evaluator import is_concrete

    plain = UserFunc(f.node, f.closure, f.module, f.defaults, f.kw_defaults)
    memo = f.memo
    assert memo is not None
    try:
        key = classes.memo_key(args, kwargs)
    except TypeError:
        return Opaque("lru_cache of an unhashable argument", span)
    if not all(is_concrete(a) or isinstance(a, LObj) for a in [*args, *kwargs.values()]):
        return call_user(ev, plain, args, kwargs, span)
    if key in memo:
        memo[key] = memo.pop(key)  # most recently used
        return memo[key]
    result = call_user(ev, plain, args, dict(kwargs), span)
    if f.memo_size != 0:
        memo[key] = result
        if f.memo_size is not None and len(memo) > f.memo_size:
            del memo[next(iter(memo))]
    return result


_MULTI_ROBOT_POSE = ("nav2_common.launch.ParseMultiRobotPose",
                     "nav2_common.launch.parse_multirobot_pose.ParseMultiRobotPose")


# moveit_configs_utils' builder: its constructor (ParameterBuilder.__init__) looks its package up
# with get_package_share_directory, ``package_name`` or else ``robot_name + "_moveit_config"``.
_MOVEIT_BUILDER = ("moveit_configs_utils.MoveItConfigsBuilder",
                   "moveit_configs_utils.moveit_configs_builder.MoveItConfigsBuilder")


def call_ref(ev: Evaluator, qual: str, args: list[Any], kwargs: dict[str, Any], span: Span) -> Any:
    if qual.startswith("builtins."):
        return builtin_calls.call_builtin(ev, qual[9:], args, kwargs, span)
    known = classes.decorator_call(qual, args, kwargs, span)
    if known is not None:
        return known
    if qual == "functools.partial" and args and isinstance(args[0], (UserFunc, Partial)):
        inner = args[0]
        if isinstance(inner, Partial):
            return Partial(inner.func, *inner.bind(list(args[1:]), dict(kwargs)))
        return Partial(inner, list(args[1:]), dict(kwargs))
    if qual in ("ament_index_python.packages.get_package_share_directory", "ament_index_python.packages.get_package_prefix"):
        pkg = args[0] if args else kwargs.get("package_name")
        kind = "share" if qual.endswith("share_directory") else "prefix"
        if symbolic.is_subst(pkg):  # the object, not its value: ament_index raises TypeError
            ev.concat(f"get_package_{kind}", span, symbolic.shown_subst(pkg))
            ev.escape([pkg])  # meant as a read of the configuration: no "declared but never read"
            return Opaque(f"{qual.rsplit('.', 1)[-1]}() of a substitution raises TypeError", span)
        found = FindPackage(to_value(pkg, span), kind, span, eager=True)  # type: ignore[arg-type]
        ev.lookup(found)
        return SymStr((found,))
    if qual == "launch.utilities.perform_substitutions" and len(args) >= 2:
        return _performed(ev, args[1], span)
    if qual in _MULTI_ROBOT_POSE:
        # nav2_common's ParseMultiRobotPose(name) takes ``name:=...`` from the command line
        # (sys.argv) itself: the argument is read, with a value the linter cannot know.
        name = args[0] if args else kwargs.get("target_argument")
        if isinstance(name, str):
            ev.escaped.add(name)
        else:  # newer nav2_common: a substitution (LaunchConfiguration("robots")) performed later
            ev.escape([*args, *kwargs.values()])
        return Opaque(f"{qual.rsplit('.', 1)[-1]} reads the command line", span)
    if qual in _MOVEIT_BUILDER:
        _moveit_package(ev, args, kwargs, span)  # then the builder itself, like any unknown call
    if qual == "os.path.join":
        subst = next((a for a in args if symbolic.is_subst(a)), None)
        if subst is not None:
            ev.concat("os.path.join", span, symbolic.shown_subst(subst))
        return symbolic.path_join(list(args), span) if args else Opaque("os.path.join()", span)
    if qual in ("os.path.dirname", "os.path.basename", "os.path.abspath", "os.path.normpath", "os.path.realpath",
                "os.path.expanduser", "os.path.splitext", "os.path.split"):
        if len(args) == 1 and isinstance(args[0], str) and (qual[8:] not in ("abspath", "realpath") or args[0].startswith("/")):
            return getattr(posixpath, qual[8:])(str(args[0]))
        return Opaque(f"{qual} of a value that cannot be evaluated statically", span)
    if qual in ("pathlib.Path", "pathlib.PurePath", "pathlib.PosixPath"):
        if args and all(isinstance(a, (str, KPath)) for a in args):
            return KPath(posixpath.join(*[a.path if isinstance(a, KPath) else str(a) for a in args]))
        if len(args) == 1 and isinstance(args[0], SymStr):
            return KPath(args[0])  # type: ignore[arg-type]
        if args and isinstance(args[0], (SymStr, KPath)) and all(isinstance(a, (str, SymStr, KPath)) for a in args):
            # Path(get_package_share_directory('p'), 'launch', 'x.py'): a join, like Path(a) / b / c
            return symbolic.path_join([KPath(args[0]) if isinstance(args[0], SymStr) else args[0], *args[1:]], span)
        return Opaque("Path of a value that cannot be evaluated statically", span)
    if qual in ("yaml.safe_load", "yaml.load", "yaml.full_load", "json.load", "json.loads"):
        return load_data(ev, qual, args[0] if args else kwargs.get("stream"), span)
    if qual in ("itertools.chain", "itertools.chain.from_iterable") and not kwargs:
        return _chain(ev, args if qual == "itertools.chain" else iterate(ev, args[0]) if len(args) == 1 else None,
                      span)
    if qual in ("os.getenv", "os.environ.get"):
        return env_read(ev, args[0] if args else kwargs.get("key"), span)
    if qual.startswith("os.environ") or qual == "os.getcwd":
        return Opaque("depends on the environment", span)
    ev.escape([*args, *kwargs.values()])
    return Opaque(f'call of "{qual}" cannot be evaluated statically', span)


def _moveit_package(ev: Evaluator, args: list[Any], kwargs: dict[str, Any], span: Span) -> None:
    """``MoveItConfigsBuilder(robot_name, robot_description="robot_description", package_name=None)``
    finds its package when it is made (moveit_configs_builder.py :: MoveItConfigsBuilder.__init__,
    ParameterBuilder.__init__): a lookup, as get_package_share_directory makes."""
    pkg = kwargs["package_name"] if "package_name" in kwargs else args[2] if len(args) > 2 else None
    if pkg is None:
        robot = args[0] if args else kwargs.get("robot_name")
        pkg = f"{robot}_moveit_config" if isinstance(robot, str) else None
    if isinstance(pkg, (str, SymStr)) and pkg:
        ev.lookup(FindPackage(to_value(pkg, span), "share", span, eager=True))  # type: ignore[arg-type]


def read_text(ev: Evaluator, path: Any, span: Span) -> Any:
    if isinstance(path, KPath):
        path = path.path
    if not isinstance(path, str) or not path.startswith("/") or ev.read_file is None:
        return Opaque("reads a file that cannot be located statically", span)
    path = posixpath.normpath(str(path))
    text = ev.read_file(path)
    if text is None:
        return Opaque(f'file "{path}" cannot be read', span)
    if path not in ev.read_files:
        ev.read_files.append(path)
    return text


def load_data(ev: Evaluator, qual: str, src: Any, span: Span) -> Any:
    if isinstance(src, FileHandle):
        src = read_text(ev, src.path, span)
    if isinstance(src, Opaque) or not isinstance(src, str):
        return Opaque(src.reason if isinstance(src, Opaque) else "loads data from an unknown source", span)
    try:
        if qual.startswith("json"):
            return json.loads(str(src))
        return yaml.safe_load(str(src))
    except Exception:  # noqa: BLE001 - a malformed file is unknown here; other tools report it
        return Opaque("the file could not be parsed", span)


# str methods of a launch-time string that stay a launch-time string (the resolver applies them).
_SYM_STR_METHODS = frozenset({"lower", "upper", "casefold", "strip", "lstrip", "rstrip"})


def _performed(ev: Evaluator, subst: Any, span: Span) -> SymStr | str:
    """What substituting ``subst`` now gives (``lc.perform(context)``), noted as performed: the
    OpaqueFunction running this reads its launch configurations wherever the result goes."""
    value = to_value(subst, span)
    ev.performed.append(value)
    return _known_or_symbolic(ev, value)


def _peeked(ev: Evaluator, value: Value) -> SymStr | str:
    """``context.launch_configurations.get(name)`` / ``[name]``: like ``_performed``, but noted
    apart (``Recorder.peeked``): an unset name gives None or a KeyError there, not the failure
    of a substitution, so the read is not one that must find the configuration set."""
    ev.peeked.append(value)
    return _known_or_symbolic(ev, value)


def _known_or_symbolic(ev: Evaluator, value: Value) -> SymStr | str:
    """The string the resolver found for ``value`` where the function is evaluated again with
    the launch configurations of one include (``specialize``); else the value, symbolically."""
    if ev.known:
        try:
            text = ev.known.get(value)
        except TypeError:  # an unhashable part: not looked up
            text = None
        if text is not None:
            return text
    return SymStr(value)


_FIND_PACKAGE = {"launch_ros.substitutions.FindPackageShare": "share",
                 "launch_ros.substitutions.FindPackagePrefix": "prefix"}


def call_method(ev: Evaluator, obj: Any, name: str, args: list[Any], kwargs: dict[str, Any], span: Span) -> Any:
    if isinstance(obj, LObj):
        if name in ("add_action", "add_entity") and "entities" in obj.extra and args:
            obj.extra["entities"].append(args[0])
            return None
        if name == "perform" and symbolic.is_subst(obj):
            return _performed(ev, obj, span)
        if name == "find" and obj.qual in _FIND_PACKAGE and (args or "package_name" in kwargs):
            # FindPackageShare(...).find(pkg): ament_index's directory of pkg, found right away
            pkg = args[0] if args else kwargs["package_name"]
            found = FindPackage(to_value(pkg, span), _FIND_PACKAGE[obj.qual], span, eager=True)  # type: ignore[arg-type]
            ev.lookup(found)
            return SymStr((found,))
        # an unknown method (IfCondition(...).evaluate(context), a helper object's own method)
        # may use what the object holds as well as its arguments
        ev.escape([obj, *args, *kwargs.values()])
        return Opaque(f"method {name} of {api.short(obj.qual)}", span)
    if isinstance(obj, ContextSym):
        if name == "perform_substitution" and args:
            return _performed(ev, args[0], span)
        return Opaque(f"context.{name}", span)
    if isinstance(obj, LaunchConfigsSym):
        if name == "get" and args and isinstance(args[0], str):
            # ``.get(name)`` gives None when nothing set the name (no failure, unlike ``[name]``):
            # a default of unknown value, so that a read of an unset name is no error (L101).
            default = to_value(args[1], span) if len(args) > 1 and args[1] is not None else \
                (Unknown("None: the launch configuration is not set", span),)
            return _peeked(ev, (LaunchConfig((Text(str(args[0]), span),), default, span),))
        ev.escaped.add(EVERY_CONFIGURATION)  # items(), values(), copy(), get(name unknown): any
        return Opaque(f"launch_configurations.{name}", span)
    if isinstance(obj, FileHandle):
        if name == "read":
            return read_text(ev, obj.path, span)
        return Opaque(f"file.{name}", span)
    if isinstance(obj, SymStr) and name in _SYM_STR_METHODS and not args and not kwargs:
        return SymStr((StrMethod(name, obj.value, span),))  # type: ignore[arg-type]
    if isinstance(obj, KPath):
        if name in ("read_text", "read_bytes", "open") and not (name == "open" and (args or kwargs)):
            ev.opened(obj, span)
        if name == "read_text":
            return read_text(ev, obj.path, span)
        if name == "joinpath":
            return symbolic.path_join([obj, *args], span)
        if name in ("resolve", "absolute", "expanduser") and isinstance(obj.path, str) and obj.path.startswith("/"):
            return KPath(posixpath.normpath(obj.path))
        if name == "as_posix":
            return obj.path
        return Opaque(f"Path.{name}", span)
    from .evaluator import is_concrete

    if isinstance(obj, str) and name in ("format", "join"):
        return builtin_calls.str_format_join(ev, obj, name, args, kwargs, span)
    if isinstance(obj, str) and name in _STR_METHODS and is_concrete(list(args)) and is_concrete(kwargs):
        if bounds.str_method_too_big(str(obj), name, list(args)):
            return Opaque(f"str.{name} result too large", span)
        return _safe(getattr(str(obj), name), args, kwargs, span)
    if isinstance(obj, (list, dict)) and name in _GROWING and \
            len(obj) + sum(ev.bounds.weight(a) for a in [*args, *kwargs.values()]) > bounds.MAX_WEIGHT:
        return Opaque(f"{name} makes the value too large to analyse", span)
    if isinstance(obj, list) and name in _LIST_METHODS:
        if name == "extend" and args and not isinstance(args[0], (list, tuple, dict, str)):
            obj.append(Opaque("extend with an unknown iterable", span))
            return None
        return _safe(getattr(obj, name), args, kwargs, span)
    if isinstance(obj, dict) and name in _DICT_METHODS:
        result = _safe(getattr(obj, name), args, kwargs, span)
        if name in ("items", "keys", "values"):
            result = list(result)
            spans = ev.item_spans(obj)
            if name == "items" and isinstance(spans, dict):
                ev.register(result, [spans.get(k, (span, span))[0] for k, _ in result])
        return result
    if isinstance(obj, Opaque):
        ev.escape([*args, *kwargs.values()])
        return Opaque(obj.reason, span)
    return Opaque(f'method "{name}" cannot be evaluated statically', span)


def _chain(ev: Evaluator, parts: list[Any] | None, span: Span) -> Any:
    """``itertools.chain(*parts)`` of known iterables, as a list (what the file iterates or
    ``list()``s); unknown if any part is."""
    out: list[Any] = []
    for part in parts if parts is not None else [Opaque("chain of an unknown iterable", span)]:
        items = iterate(ev, part)
        if items is None:
            ev.escape([part])
            return Opaque(part.reason if isinstance(part, Opaque) else "chain of an unknown iterable", span)
        out.extend(items)
        if len(out) > bounds.MAX_WEIGHT:
            return Opaque("chain makes the value too large to analyse", span)
    return out


def _safe(fn: Any, args: list[Any], kwargs: dict[str, Any], span: Span) -> Any:
    try:
        return fn(*args, **kwargs)
    except Exception:  # noqa: BLE001 - a failing pure operation is an unknown value
        return Opaque("operation fails statically", span)


# Substitutions whose constructor runs normalize_to_list_of_substitutions over a list argument:
# each item must be a str or a Substitution, else it raises TypeError when the description is built
# (launch.utilities.normalize_to_list_of_substitutions, humble to rolling). Not PathJoinSubstitution:
# since ros2/launch#838 (kilted, backported in 2025) each of its items may be a list to concatenate.
_SUBSTITUTION_LISTS = {"Command": "command", "PythonExpression": "expression", "FindExecutable": "name",
                       "EnvironmentVariable": "name", "LaunchConfiguration": "variable_name"}


def _check_parts(ev: Evaluator, obj: LObj, short: str) -> None:
    name = _SUBSTITUTION_LISTS[short]
    items = obj.arg(0, name)
    if not isinstance(items, (list, tuple)):
        return
    span = obj.arg_span(0, name)
    for k, item in enumerate(items):
        if isinstance(item, (list, tuple, dict)) or type(item) in (int, float, bool):
            ev.wrong_type("part", f"{short}({name}=[...])", item, span_at(items, k, span))


def make_lobj(ev: Evaluator, qual: str, args: list[Any], kwargs: dict[str, Any], node: ast.Call,
              scope: Scope, arg_spans: list[Span], kw_spans: dict[str, Span]) -> Any:
    mod = scope.module or ev.main
    span = mod.spans.of(node)
    site = (mod.prefix, span.line, span.col)
    index = ev.site_counts.get(site, 0) + 1
    ev.site_counts[site] = index
    obj = LObj(qual, args, kwargs, node, span, arg_spans, kw_spans, tuple(ev.cond_stack), {}, index)
    obj.extra["prefix"] = mod.prefix
    for k, v in kwargs.items():
        if isinstance(v, (dict, list, tuple)):
            ev.kw_kinds[(id(node), k)] = type(v).__name__
    if kwargs and qual.startswith(("launch.actions.", "launch_ros.")):
        from .signatures import accepted_keywords

        accepted = accepted_keywords(qual)
        if accepted is not None and not accepted.issuperset(kwargs):  # L001: what they hold is lost
            ev.escape([v for k, v in kwargs.items() if k not in accepted])
    short = api.short(qual)
    if short in _SUBSTITUTION_LISTS and api.is_substitution(qual):
        _check_parts(ev, obj, short)
    elif short == "PathJoinSubstitution" and isinstance(text := obj.arg(0, "substitutions"), str) and len(text) > 1:
        # since ros2/launch#838 (humble's 2025 sync on) each item of the iterable is a component,
        # and a string's items are its characters
        ev.wrong_type("path-string", "PathJoinSubstitution(substitutions=...)", text, obj.arg_span(0, "substitutions"))
    if qual == "launch.LaunchDescription":
        init = obj.arg(0, "initial_entities")
        obj.extra["entities"] = list(init) if isinstance(init, (list, tuple)) else ([] if init is None else [init])
    elif short == "OpaqueFunction":
        fn = obj.arg(0, "function")
        fargs = obj.arg(1, "args") or []
        fkwargs = obj.arg(2, "kwargs") or {}
        # launch calls function(context, *args, **kwargs); a partial's own positional arguments
        # come before the context (OpaqueFunction(function=partial(setup, robot='a')))
        bound: tuple[list[Any], dict[str, Any]] = ([], {})
        if isinstance(fn, Partial):
            fn, bound = fn.func, (fn.args, fn.kwargs)
        if isinstance(fn, UserFunc) and isinstance(fargs, (list, tuple)) and isinstance(fkwargs, dict):
            def run_opaque(fn: UserFunc = fn) -> None:
                start, peeks, undecided, sets = len(ev.performed), len(ev.peeked), ev.undecided, len(ev.config_sets)
                obj.extra["result"] = _call_later(ev, obj, fn, [*bound[0], ContextSym(), *fargs],
                                                  {**bound[1], **fkwargs}, span)
                obj.extra["performed"] = tuple(ev.performed[start:])
                obj.extra["peeked"] = tuple(ev.peeked[peeks:])
                obj.extra["undecided"] = ev.undecided > undecided
                obj.extra["sets"] = tuple(ev.config_sets[sets:])

            _bind_late(ev, obj, fn, run_opaque)
            run_opaque()
        else:
            obj.extra["result"] = Opaque("OpaqueFunction with a function that cannot be evaluated statically", span)
    elif short in _HANDLER_KEYS:
        for key in _HANDLER_KEYS[short]:
            fn = kwargs.get(key)
            if isinstance(fn, UserFunc):
                def run_handler(fn: UserFunc = fn) -> None:
                    nargs = len(fn.node.args.posonlyargs) + len(fn.node.args.args)
                    fake = [Opaque("the event is known only at launch time", span), ContextSym()][:nargs]
                    obj.extra["entities_result"] = _call_later(ev, obj, fn, fake, {}, span)

                _bind_late(ev, obj, fn, run_handler)
                run_handler()
                break
    ev.objects.append(obj)
    return obj


_HANDLER_KEYS = {
    "OnProcessStart": ("on_start",), "OnProcessExit": ("on_exit",), "OnExecutionComplete": ("on_completion",),
    "OnShutdown": ("on_shutdown",), "OnStateTransition": ("entities",), "OnProcessIO": ("on_stdout", "on_stderr"),
    "OnIncludeLaunchDescription": ("entities",),
    # a process action's on_exit= function gets the same (event, context) (launch ExecuteLocal)
    "ExecuteProcess": ("on_exit",), "Node": ("on_exit",), "LifecycleNode": ("on_exit",),
    "ComposableNodeContainer": ("on_exit",),
}


def _bind_late(ev: Evaluator, obj: LObj, fn: UserFunc, run: Any) -> None:
    """Note a function that launch calls later (an OpaqueFunction's, an event handler's) and whose
    body reads variables of an enclosing function (``late_calls``). Python looks those up when the
    body runs, not when the function is made: after ``generate_launch_description`` has returned.
    So ``for robot in robots: OpaqueFunction(function=lambda context: setup(context, robot))``
    runs every function with the last robot; ``late_bindings`` runs the body again then."""
    if fn.closure is None or fn.closure.parent is None:  # defined at module level
        return
    names = _enclosing_reads(fn)
    if names:
        ev.late_calls.append((obj, fn, names, run, ev.late_owner))


def _call_later(ev: Evaluator, obj: LObj, fn: UserFunc, args: list[Any], kwargs: dict[str, Any],
                span: Span) -> Any:
    """Run ``fn``, the function launch calls when ``obj`` executes or its event comes, if it does
    (``guarded``): one more run of it (``late_runs``), the owner of the functions its body makes
    (``late_owner``: (id, run))."""
    runs = ev.late_runs[id(obj)] = ev.late_runs.get(id(obj), 0) + 1
    before, ev.late_owner = ev.late_owner, (id(obj), runs)
    ev.guarded += 1
    try:
        return call_user(ev, fn, args, kwargs, span)
    finally:
        ev.guarded -= 1
        ev.late_owner = before


def _enclosing_reads(fn: UserFunc, depth: int = 0) -> list[tuple[Any, str, Any]]:
    """(scope, name, value now) for each variable of an enclosing function scope that ``fn``'s body
    reads, also through the nested functions it reads (two levels). A name the body reads that no
    enclosing function binds yet is noted as ``_UNBOUND`` in each of them (it may be assigned later,
    after the function was made, and launch then sees it). Names the body binds itself are its own."""
    node = fn.node
    own = {p.arg for p in [*node.args.posonlyargs, *node.args.args, *node.args.kwonlyargs]}
    own.update(p.arg for p in (node.args.vararg, node.args.kwarg) if p is not None)
    body = [node.body] if isinstance(node, ast.Lambda) else node.body
    names: list[ast.Name] = []
    for part in body:
        for n in ast.walk(part):
            if isinstance(n, ast.Name):
                names.append(n)
                if not isinstance(n.ctx, ast.Load):
                    own.add(n.id)
            # any other name the body binds, in it or in a scope nested in it: its own (or
            # shadowing the enclosing one where it is read)
            elif isinstance(n, ast.arg) or (isinstance(n, ast.ExceptHandler) and n.name):
                own.add(n.arg if isinstance(n, ast.arg) else n.name)  # type: ignore[arg-type]
            elif isinstance(n, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
                own.add(n.name)
            elif isinstance(n, (ast.Import, ast.ImportFrom)):
                own.update(a.asname or a.name.split(".")[0] for a in n.names)
    out: list[tuple[Any, str, Any]] = []
    for name in sorted({n.id for n in names} - own):
        scope, chain = fn.closure, []
        while scope is not None and scope.parent is not None:  # not the module's scope
            if name in scope.vars:
                value = scope.vars[name]
                out.append((scope, name, value))
                if isinstance(value, UserFunc) and value is not fn and depth < 2:
                    out.extend(_enclosing_reads(value, depth + 1))
                break
            chain.append(scope)
            scope = scope.parent
        else:
            out.extend((s, name, _UNBOUND) for s in chain)
    return out


_UNBOUND = object()


def _same(a: Any, b: Any, depth: int = 0) -> bool:
    """Whether two values of a variable are the same value: equal plain data, or launch objects
    made at one call site with the same arguments (a loop that makes an equal value each time
    has not changed what the function reads)."""
    if a is b:
        return True
    if isinstance(a, str) and isinstance(b, str):  # a literal (SStr) or a computed string
        return str(a) == str(b)
    if type(a) is not type(b) or depth > 8 or a is _UNBOUND or b is _UNBOUND:
        return False
    if isinstance(a, LObj):
        return a.qual == b.qual and a.node is b.node and len(a.args) == len(b.args) \
            and all(_same(x, y, depth + 1) for x, y in zip(a.args, b.args)) \
            and a.kwargs.keys() == b.kwargs.keys() \
            and all(_same(a.kwargs[k], b.kwargs[k], depth + 1) for k in a.kwargs)
    if isinstance(a, (list, tuple)):
        return len(a) == len(b) and all(_same(x, y, depth + 1) for x, y in zip(a, b))
    if isinstance(a, dict):
        return a.keys() == b.keys() and all(_same(a[k], b[k], depth + 1) for k in a)
    if dataclasses.is_dataclass(a) and a.__dataclass_params__.eq is False:  # type: ignore[attr-defined]
        # the evaluator's own values compare by identity (SymStr of get_package_share_directory)
        return all(_same(getattr(a, f.name), getattr(b, f.name), depth + 1) for f in dataclasses.fields(a))
    try:
        return bool(a == b)
    except Exception:  # noqa: BLE001 - a value whose comparison fails is another value
        return False


def _late_shown(value: Any) -> str:
    """A variable's value for L013's message as the file writes it (``symbolic.shown_value``),
    or "" when it is not plain data."""
    text = symbolic.shown_value(value)
    if "..." in text:
        return ""
    return text if len(text) <= 40 else text[:37] + "..."


def late_bindings(ev: Evaluator) -> None:
    """Run again the functions ``_bind_late`` noted whose enclosing variables have been rebound since
    they were made (a loop moved on): launch calls them after ``generate_launch_description`` has
    returned, with the variables as they are then. A function run again may note others."""
    for _ in range(4):
        pending, ev.late_calls = ev.late_calls, []
        for obj, fn, names, run, owner in pending:
            if owner is not None and ev.late_runs.get(owner[0]) != owner[1]:
                # made by a run of an enclosing function that has been run again since: that run
                # made its own copy; this one, and what it made, launch never sees
                ev.late_runs[id(obj)] = ev.late_runs.get(id(obj), 0) + 1
                continue
            moved = [(name, value, now) for scope, name, value in names
                     if not _same(now := scope.vars.get(name, _UNBOUND), value)]
            if moved:
                span = fn.module.spans.of(fn.node) if fn.module is not None else obj.span
                caller = api.short(obj.qual)
                for name, made, now in moved:
                    # a variable assigned only after the function was made, or a function redefined,
                    # is how the file means it
                    if made is not _UNBOUND and not isinstance(made, (UserFunc, Partial)):
                        ev.late_bound.setdefault((span, name), LateFact(
                            caller, name, _late_shown(made), _late_shown(now), span))
                saved, ev.cond_stack = ev.cond_stack, list(obj.tags)
                try:
                    run()
                finally:
                    ev.cond_stack = saved
        if not ev.late_calls:
            return
