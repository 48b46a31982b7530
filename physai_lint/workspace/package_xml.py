"""package.xml through catkin_pkg: it implements REP 127/140/149 (formats 1-3, ``condition``
evaluation, group deps, build_type export validation), which a hand-written parser would only
approximate; we add what it lacks: the line of every dependency, for messages."""
from __future__ import annotations

import operator
import re
import sys
import types
import warnings
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

_DEP_RX = re.compile(r"<(depend|exec_depend|run_depend)\b[^>]*>\s*([^<\s]+)\s*</\1\s*>", re.DOTALL)
_NAME_RX = re.compile(r"<name>\s*([^<\s]+)\s*</name>")
_BUILD_TYPE_RX = re.compile(r"<build_type\b[^>]*>\s*([^<\s]+)\s*</build_type>")
_LINE_RX = re.compile(r"line (\d+)")


@dataclass
class ManifestInfo:
    name: str | None
    build_type: str | None
    format: int
    exec_depends: dict[str, int] = field(default_factory=dict)
    error: tuple[str, int] | None = None  # (message, line) when catkin_pkg rejected it
    # run dependencies whose condition is false here (``$ROS_DISTRO != 'humble'``): -> condition
    excluded_depends: dict[str, str] = field(default_factory=dict)
    # <test_depend> (and <depend>) names: what the package's tests may use besides its run
    # dependencies (launch_testing files under test/)
    test_depends: frozenset[str] = frozenset()


def _line_of(text: str, pos: int) -> int:
    return text.count("\n", 0, pos) + 1


def dependency_lines(text: str) -> dict[str, int]:
    lines: dict[str, int] = {}
    for m in _DEP_RX.finditer(text):
        lines.setdefault(m.group(2), _line_of(text, m.start(2)))
    return lines


def parse_manifest(text: str, filename: str, distro: str) -> ManifestInfo:
    # catkin_pkg.condition builds its pyparsing grammar with deprecated names: keep output clean
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return _parse_manifest(text, filename, distro)


def _evaluate_condition(condition: str | None, context: dict[str, str]) -> bool:
    if condition is None:
        return True
    value = simple_condition(condition, context)
    if value is not None:
        return value
    from catkin_pkg.condition import evaluate_condition  # type: ignore[import-untyped]

    return bool(evaluate_condition(condition, context))


# A REP 149 condition with no quotes and no parentheses: comparisons of ``$VARIABLE``s and bare
# words joined by ``and``/``or`` (``$ROS_VERSION == 2``, ``$ROS_DISTRO != humble and ...``), the
# only forms real manifests use. Anything else goes to catkin_pkg's pyparsing grammar.
_TERM = r"(\$[A-Za-z0-9_]+|[A-Za-z0-9_-]+)"
_COMPARISON = _TERM + r"\s*(==|!=|>=|>|<=|<)\s*" + _TERM
_SIMPLE_RX = re.compile(r"\s*" + _COMPARISON + r"(?:\s+(?:and|or)\s+" + _COMPARISON + r")*\s*", re.ASCII)
_PART_RX = re.compile(_COMPARISON + r"|(and|or)", re.ASCII)
_CONDITION_VAR_RX = re.compile(r"\$([A-Za-z0-9_]+)")
_COMPARE = {"==": str.__eq__, "!=": str.__ne__, ">=": str.__ge__, ">": str.__gt__, "<=": str.__le__,
            "<": str.__lt__}


def simple_condition(condition: str, context: dict[str, str]) -> bool | None:
    """What ``catkin_pkg.condition.evaluate_condition`` returns for a simple condition, without
    importing it (it imports pyparsing: ~65 ms, the largest import of a run whose workspace has
    one conditional dependency); None when the condition is not of the simple form.

    catkin_pkg's semantics: a ``$NAME`` is ``str(context.get(NAME, ""))``, a bare word itself,
    every comparison is between strings, ``and`` binds tighter than ``or``."""
    return _simple_value(condition, lambda name: str(context.get(name, "")))


def can_hold(condition: str | None, context: dict[str, str]) -> bool:
    """Whether a dependency's condition can be true on a machine building for ``context``. A
    ``$VARIABLE`` other than those of ``context`` (``$HUSARION_ROS_BUILD_TYPE == simulation``) is
    set by whoever builds, so a comparison with it is taken as able to go either way.

    (``_parse_manifest`` asks only about conditions catkin_pkg found false with ``context``.)"""
    if condition is None:
        return True
    if not set(_CONDITION_VAR_RX.findall(condition)) - context.keys():
        try:
            return _evaluate_condition(condition, context)
        except Exception:  # noqa: BLE001 - unparsable: keep the dependency
            return True
    value = _simple_value(condition, context.get)
    return value is None or value  # not the simple form (parentheses, quotes): it may hold


def _simple_value(condition: str, lookup: Callable[[str], str | None]) -> bool | None:
    """A simple condition (``_SIMPLE_RX``) with ``$NAME`` looked up (None: could be anything),
    three-valued: None when the unknown variables decide it; also None for any other form."""
    if _SIMPLE_RX.fullmatch(condition) is None:
        return None

    def compare(left: str, op: str, right: str) -> bool | None:
        terms = []
        for token in (left, right):
            term = lookup(token[1:]) if token.startswith("$") else token
            if term is None:
                return None
            terms.append(str(term))
        return _COMPARE[op](*terms)

    disjuncts: list[bool | None] = []
    conj: bool | None = True  # of the current ``and`` run
    for m in _PART_RX.finditer(condition):
        left, op, right, joiner = m.groups()
        if joiner == "or":
            disjuncts.append(conj)
            conj = True
        elif joiner is None:
            value = compare(left, op, right)
            conj = False if conj is False or value is False else (None if value is None or conj is None else True)
    disjuncts.append(conj)
    return True if True in disjuncts else (None if None in disjuncts else False)


def _catkin_parser() -> Any:
    """``catkin_pkg.package.parse_package_string``, imported without pyparsing.

    ``catkin_pkg.package`` and its group modules import ``catkin_pkg.condition`` for
    ``evaluate_condition`` only, and that module imports pyparsing (~25 ms, more than the rest of
    catkin_pkg) although a manifest without ``condition`` attributes never parses a condition. They
    are imported against a stand-in that answers ``None`` conditions and imports the real module on
    the first actual condition, so every result is still catkin_pkg's own.
    """
    if "catkin_pkg.package" not in sys.modules and "catkin_pkg.condition" not in sys.modules:
        stand_in = types.ModuleType("catkin_pkg.condition")
        stand_in.evaluate_condition = _evaluate_condition  # type: ignore[attr-defined]
        sys.modules["catkin_pkg.condition"] = stand_in
        try:
            import catkin_pkg.group_dependency  # type: ignore[import-untyped]
            import catkin_pkg.group_membership  # type: ignore[import-untyped]
            import catkin_pkg.package  # type: ignore[import-untyped]  # noqa: F401
        finally:
            del sys.modules["catkin_pkg.condition"]
    import catkin_pkg.package as package

    if package.deepcopy is not _copy_dependency:
        _COPY.update(deepcopy=package.deepcopy, Dependency=package.Dependency)
        package.deepcopy = _copy_dependency
        dependency = package.Dependency
        fields = operator.attrgetter(*[s for s in dependency.__slots__ if s != "evaluated_condition"])

        def equal(self: Any, other: Any) -> bool:
            # catkin_pkg's own __eq__ (the same comparison through a generator of getattr calls)
            # runs for every pair of <depend> and specific dependency: 28,000 times for Autoware.
            return isinstance(other, dependency) and fields(self) == fields(other)

        dependency.__eq__ = equal
    return package.parse_package_string


_COPY: dict[str, Any] = {}


def _copy_dependency(obj: Any, memo: Any = None) -> Any:
    """What ``deepcopy`` makes of a catkin_pkg ``Dependency`` (its slots hold strings and None),
    without deepcopy's generic machinery: catkin_pkg copies every ``<depend>`` three times, which
    was half of its time parsing a manifest. Anything else is deep-copied as before."""
    cls = _COPY["Dependency"]
    if type(obj) is not cls:
        return _COPY["deepcopy"](obj, memo)
    new = object.__new__(cls)
    for slot in cls.__slots__:
        value = getattr(obj, slot)
        if value is not None and type(value) not in (str, bool, int):
            return _COPY["deepcopy"](obj, memo)
        setattr(new, slot, value)
    return new


def _parse_manifest(text: str, filename: str, distro: str) -> ManifestInfo:
    parse_package_string = _catkin_parser()
    lines = dependency_lines(text)
    try:
        pkg_warnings: list[str] = []
        pkg = parse_package_string(text, filename=filename, warnings=pkg_warnings)
    except Exception as exc:  # noqa: BLE001 - InvalidPackage, AssertionError on unknown format, ValueError ...
        msg = " ".join(str(exc).split()) or type(exc).__name__
        line = 1
        m = _LINE_RX.search(str(exc))
        if m:
            line = int(m.group(1))
        nm = _NAME_RX.search(text)
        bt = _BUILD_TYPE_RX.search(text)
        return ManifestInfo(
            name=nm.group(1) if nm else None,
            build_type=bt.group(1) if bt else None,
            format=0,
            exec_depends=lines,
            error=(msg, line),
        )
    context = {"ROS_VERSION": "2", "ROS_DISTRO": distro, "ROS_PYTHON_VERSION": "3"}
    try:
        pkg.evaluate_conditions(context)
    except Exception:  # noqa: BLE001, S110 - an unparsable condition keeps the dependency
        pass
    deps: dict[str, int] = {}
    excluded: dict[str, str] = {}
    # catkin_pkg's run_depends is computed on every access as deep copies of exec_depends +
    # build_export_depends (format 1 <run_depend> fills both): read those directly, same names
    # and conditions without the copies.
    for dep in list(pkg.exec_depends) + list(pkg.build_export_depends):
        if getattr(dep, "evaluated_condition", None) is False and not can_hold(dep.condition, context):
            excluded.setdefault(dep.name, str(dep.condition))
            continue
        deps.setdefault(dep.name, lines.get(dep.name, 1))
    try:
        build_type = pkg.get_build_type()
    except Exception:  # noqa: BLE001 - InvalidPackage for several unconditional build types
        bt = _BUILD_TYPE_RX.search(text)
        build_type = bt.group(1) if bt else "catkin"
    tests = frozenset(d.name for d in pkg.test_depends if getattr(d, "evaluated_condition", None) is not False)
    return ManifestInfo(
        name=pkg.name, build_type=build_type, format=int(pkg.package_format), exec_depends=deps,
        excluded_depends={n: c for n, c in excluded.items() if n not in deps}, test_depends=tests,
    )
