"""The Python launch frontend: ``parse_python_launch(path, text, read_file) -> FrontendResult``.

The file is never imported or executed. It is parsed and partially evaluated by our own
interpreter (``evaluator.py`` + ``calls.py``) over known data; launch/launch_ros objects become
IR actions (``convert_actions.py``), everything else ``Unknown``/``OpaqueAction`` with a reason.

Parser choice (measured on a 300-line generated launch file, shared dev machine, Python 3.11):
stdlib ``ast.parse`` 4-6 ms; ``libcst.parse_module`` 70-100 ms; libcst ``MetadataWrapper`` with
``PositionProvider`` another 110-180 ms; this whole frontend (parse + evaluate + facts) 40-55 ms.
``benchmarks/python_frontend.py`` (a hand-written 305-line fleet bring-up, 54 nodes): parse +
evaluate about 17-30 ms, with resolution of it and its include about 21-50 ms (2 busy shared CPUs).
``ast`` gives every position we need (``lineno``/``col_offset`` incl.
end positions, keyword nodes), so the evaluator runs on ``ast`` nodes and libcst is not needed
here: no rule needs concrete syntax (comments, whitespace) from this frontend. UTF-8 byte columns
are converted to 1-based character columns in ``positions.py``.
"""
from __future__ import annotations

import ast
from collections.abc import Callable
from typing import Any

from physai_lint.frontends import FrontendResult
from physai_lint.model.findings import Diagnostic
from physai_lint.model.launch import LaunchFile, OpaqueAction, PythonFacts
from physai_lint.model.span import Span
from physai_lint.pyast import ast_nodes

from . import convert_values
from .calls import call_user, late_bindings
from .convert_actions import ActionBuilder
from .core import Signal
from .evaluator import Abort, Evaluator
from .facts import call_facts, launch_imports, undefined_names
from .runtime import Alternatives, LObj, Opaque, Partial, UserFunc

__all__ = ["parse_python_launch", "specialize"]


def _syntax_error(path: str, text: str, err: BaseException) -> FrontendResult:
    if isinstance(err, SyntaxError):
        line = err.lineno or 1
        col = err.offset or 1
        lines = text.splitlines()
        if 0 < line <= len(lines) and not lines[line - 1].isascii():
            pass  # SyntaxError.offset is already in characters for str input
        msg = err.msg or "invalid syntax"
    else:
        line, col, msg = 1, 1, "the file is too deeply nested to parse"
    diag = Diagnostic(
        code="X001", span=Span.point(path, line, max(col, 1)),
        message=f'python syntax error: "{msg}"',
        help="fix the syntax error; ros2 launch fails to load this file (InvalidLaunchFileError)",
        key=msg)
    return FrontendResult(launch=None, diagnostics=[diag])


def parse_python_launch(path: str, text: str, read_file: Callable[[str], str | None] | None = None,
                        distro: str | None = None, known: dict[Any, str] | None = None,
                        facts: bool = True) -> FrontendResult:
    """Parse and statically evaluate a ``.launch.py`` file into the launch IR.

    ``distro`` is what ``os.environ['ROS_DISTRO']``/``os.getenv('ROS_DISTRO')`` read; without it
    they are unknown like every other environment variable. ``known``: what substitutions the
    OpaqueFunctions perform give (``specialize``); without it they stay symbolic. ``facts=False``
    leaves out what the rules read of the source itself (``PythonFacts``' calls, undefined names
    and imports): the same for any ``known``, so a second evaluation needs only the actions."""
    try:
        tree = ast.parse(text, filename=path)
    except (SyntaxError, ValueError, RecursionError, MemoryError) as err:
        return _syntax_error(path, text, err)
    ev = Evaluator(path, text, read_file, distro)
    ev.known = known or {}
    convert_values.set_recorder(ev)
    spans = ev.main.spans
    result: Any = None
    defined = _module_functions(tree.body)
    has_gld = "generate_launch_description" in defined or ("*" in defined and "generate_test_description" not in defined)
    # launch_testing's entry point when there is no generate_launch_description: `launch_test`
    # calls it and starts the description it returns (alone, or first of a (description, dict))
    has_gtd = not has_gld and "generate_test_description" in defined
    try:
        ev.exec_block(tree.body, ev.main.scope)
    except Abort as e:
        result = Opaque(e.reason, Span.whole_file(path))
    except RecursionError:
        result = Opaque("the file is too deeply nested to evaluate", Span.whole_file(path))
    except Signal:  # stray return/break/raise at module level ends the module
        pass
    entry = "generate_test_description" if has_gtd else "generate_launch_description"
    gld = ev.main.scope.vars.get(entry)
    runs = has_gld or has_gtd
    bound: tuple[list[Any], dict[str, Any]] = ([], {})
    if isinstance(gld, Partial):  # generate_launch_description = partial(make, 'front')
        gld, bound = gld.func, (gld.args, gld.kwargs)
    if runs and result is None:
        if isinstance(gld, UserFunc):
            gld_span = spans.of(gld.node)
            # an old-style generate_test_description(ready_fn) gets a callable it cannot know
            required = gld.node.args.args[:len(gld.node.args.args) - len(gld.node.args.defaults)]
            given = [Opaque(f"{a.arg}, given by launch_testing", gld_span) for a in required] if has_gtd else []
            try:
                result = call_user(ev, gld, [*bound[0], *given], dict(bound[1]), gld_span)
                late_bindings(ev)  # what launch calls later sees the variables as they are now
            except RecursionError:
                result = Opaque("the file is too deeply nested to evaluate", gld_span)
            if has_gtd and isinstance(result, tuple) and len(result) == 2:
                # (LaunchDescription, the tests' context: a dict, often locals()); launch_testing's
                # loader takes the first of any tuple (loader.py: _normalize_ld)
                result = result[0]
        else:  # a decorator that cannot be followed (launch_testing.parametrize), an assignment
            why = f" ({gld.reason})" if isinstance(gld, Opaque) and gld.reason else ""
            result = Opaque(f"{entry} cannot be evaluated statically{why}", Span.whole_file(path))
    actions: tuple[Any, ...] = ()
    if runs:
        builder = ActionBuilder(ev)
        if isinstance(result, (LObj, list, tuple, Alternatives)):  # Alternatives before Opaque, its base
            try:
                actions = builder.actions(result, Span.whole_file(path))
            except RecursionError:
                actions = (OpaqueAction("opaque@gld", Span.whole_file(path), None, "too deeply nested"),)
        elif isinstance(result, Opaque):
            actions = (OpaqueAction("opaque@gld", result.span or Span.whole_file(path), None, result.reason),)
        else:
            actions = (OpaqueAction("opaque@gld", Span.whole_file(path), None,
                                    f"{entry} does not return a LaunchDescription"),)
    calls: tuple[Any, ...] = ()
    names: tuple[Any, ...] = ()
    imports: tuple[Any, ...] = ()
    if facts:
        try:
            nodes = ast_nodes(tree)
            dead = ev.dead_lines(nodes)
            calls = tuple(c for c in call_facts(nodes, spans, ev.kw_kinds) if not _within(c.span, dead))
            names = tuple(n for n in undefined_names(tree, nodes, spans, text) if not _within(n.span, dead))
            imports = tuple(i for i in launch_imports(tree, spans) if not _within(i[2], dead))
        except RecursionError:
            calls, names, imports = (), (), ()
    concats = tuple(sorted(ev.concats.values(), key=lambda c: (c.span.line, c.span.col, c.how)))
    # launch_testing files (`launch_test FILE`) define generate_test_description instead, and
    # launch_pytest modules (run by pytest) give their descriptions through @launch_pytest.fixture.
    is_test = "generate_test_description" in defined or any(
                  isinstance(n, ast.Import) and any(a.name.split(".")[0] == "launch_pytest" for a in n.names)
                  or isinstance(n, ast.ImportFrom) and (n.module or "").split(".")[0] == "launch_pytest"
                  for n in tree.body)
    wrong = tuple(sorted(ev.wrong_types.values(), key=lambda f: (f.span.line, f.span.col, f.call)))
    tested = tuple(sorted(ev.tests.values(), key=lambda c: (c.span.line, c.span.col, c.how)))
    refused = tuple(sorted(ev.call_errors.values(), key=lambda c: (c.span.line, c.span.col)))
    facts = PythonFacts(calls, names, concats, has_gld, is_test, wrong, tuple(sorted(ev.escaped)), tested,
                        refused, tuple(ev.lookups), imports, tuple(ev.opens),
                        tuple(sorted(ev.late_bound.values(), key=lambda f: (f.span.line, f.span.col, f.name))))
    launch = LaunchFile(path, "python", actions, python=facts, read_files=tuple(ev.read_files))
    convert_values.set_recorder(None)
    return FrontendResult(launch=launch, diagnostics=[])


def _module_functions(body: list[ast.stmt]) -> set[str]:
    """The names a module binds to what may be a function, also inside its module-level
    ``if``/``try``/``with``/loop blocks (``try: ... def generate_test_description(): ... except
    ImportError: ...``): launch only asks ``hasattr(module, 'generate_launch_description')``, so an
    assignment (``generate_launch_description = partial(make, 'front')``) or an import from a
    shared module counts as much as a ``def``. A ``*`` import from a module that is not launch's
    may bind anything (``"*"``). Not the names of classes or functions."""
    out: set[str] = set()
    stack = list(body)
    while stack:
        n = stack.pop()
        if isinstance(n, (ast.FunctionDef, ast.AsyncFunctionDef)):
            out.add(n.name)
        elif isinstance(n, (ast.Assign, ast.AnnAssign)):
            for target in n.targets if isinstance(n, ast.Assign) else [n.target]:
                out.update(t.id for t in ast.walk(target) if isinstance(t, ast.Name))
        elif isinstance(n, (ast.Import, ast.ImportFrom)):
            for alias in n.names:
                if alias.name != "*":
                    out.add(alias.asname or alias.name.split(".")[0])
                elif isinstance(n, ast.ImportFrom) and (n.level or (n.module or "").split(".")[0]
                                                        not in ("launch", "launch_ros")):
                    out.add("*")
        elif isinstance(n, (ast.If, ast.For, ast.AsyncFor, ast.While, ast.With, ast.AsyncWith)):
            stack.extend([*n.body, *getattr(n, "orelse", ())])
        elif isinstance(n, ast.Try) or type(n).__name__ == "TryStar":
            stack.extend([*n.body, *n.orelse, *n.finalbody])  # type: ignore[attr-defined]
            for h in n.handlers:  # type: ignore[attr-defined]
                stack.extend(h.body)
        elif type(n).__name__ == "Match":
            for case in n.cases:  # type: ignore[attr-defined]
                stack.extend(case.body)
    return out


def _within(span: Span, ranges: list[tuple[int, int]]) -> bool:
    """``span`` starts on a line of one of ``ranges`` (code the evaluation never ran)."""
    return any(a <= span.line <= b for a, b in ranges)


def specialize(path: str, text: str, read_file: Callable[[str], str | None] | None, distro: str | None,
               known: tuple[tuple[Any, str], ...], action: OpaqueAction) -> OpaqueAction | None:
    """The OpaqueFunction ``action`` of this file (an ``OpaqueAction`` whose body the evaluator lost
    track of) evaluated again, its performed substitutions (``action.other``) given the strings in
    ``known``: what ``launch`` itself does when the function runs, with the launch configurations
    of that moment (``OpaqueFunction.execute``: ``self.__function(context, ...)``), here those the
    resolver found. A loop over a list read from a launch argument (Autoware's
    ``camera_namespaces:=[camera6, camera7]``) or from a file it names then unrolls.

    Returns the action evaluated (``reason`` empty), or None when it still cannot be, or is not
    found again at the same place (the id and the span of the call both match)."""
    if not known:
        return None
    res = parse_python_launch(path, text, read_file, distro, known=dict(known), facts=False)
    if res.launch is None:
        return None
    found = _find(res.launch.actions, action.id, 0)
    if isinstance(found, OpaqueAction) and not found.reason and found.span == action.span:
        return found
    return None


def _find(actions: tuple[Any, ...], action_id: str, depth: int) -> Any:
    """The action of id ``action_id`` among ``actions`` and the actions nested in them."""
    if depth > 64:
        return None
    for a in actions:
        if a.id == action_id:
            return a
        nested = getattr(a, "actions", None)
        if isinstance(nested, tuple) and nested:
            found = _find(nested, action_id, depth + 1)
            if found is not None:
                return found
    return None
