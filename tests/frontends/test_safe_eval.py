"""PythonExpression / $(eval) strings are interpreted, never executed, and always bounded."""
from __future__ import annotations

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[2]))  # tests run without an install

import math  # noqa: E402

import pytest  # noqa: E402

from physai_lint.resolve.safe_eval import SafeEvalError, SafeEvalUnknown, safe_eval  # noqa: E402


@pytest.mark.parametrize("expr, expected", [
    ("1 + 2 * 3", 7), ("7 // 2", 3), ("7 % 4", 3), ("2 ** 10", 1024), ("-3 + +1", -2),
    ("'true' == 'true'", True), ("1 < 2 < 3", True), ("1 < 3 < 2", False),
    ("'a' in 'abc'", True), ("'x' not in ['a', 'b']", True),
    ("True and not False", True), ("0 or 'x'", "x"), ("'a' if 1 > 2 else 'b'", "b"),
    ("'Sim'.lower()", "sim"), ("' x '.strip()", "x"), ("'a_b'.split('_')", ["a", "b"]),
    ("'/'.join(['a', 'b'])", "a/b"), ("'{}-{}'.format('a', 2)", "a-2"),
    ("'abc'.startswith('a')", True), ("'abc'.replace('b', 'x')", "axc"),
    ("len('abcd')", 4), ("int('3') + float('0.5')", 3.5), ("str(5)", "5"), ("bool(0)", False),
    ("abs(-2)", 2), ("min(3, 1)", 1), ("max([1, 9])", 9), ("round(2.567, 2)", 2.57),
    ("math.pi", math.pi), ("math.sqrt(16)", 4.0), ("sqrt(9)", 3.0), ("pi / 2", math.pi / 2),
    ("[1, 2][1]", 2), ("(1, 2)", (1, 2)), ("{'a': 1}['a']", 1), ("'abc'[1:]", "bc"),
    ("None", None),
])
def test_evaluates(expr: str, expected: object) -> None:
    assert safe_eval(expr) == expected


@pytest.mark.parametrize("expr", [
    "__import__('os').system('true')", "open('/etc/passwd')", "(1).__class__",
    "[x for x in 'ab']", "lambda: 1", "exec('1')", "'{0.__class__}'.format(1)",
    "undefined_name", "os.getcwd()", "'%s' % 1", "1/0", "1 +",
])
def test_refuses(expr: str) -> None:
    assert isinstance(safe_eval(expr), SafeEvalUnknown)


@pytest.mark.parametrize("expr", [
    "9 ** 9 ** 9", "'a' * 10 ** 7", "[0] * 10 ** 7", "10 ** 600000 * 10 ** 600000",
    "str([[1] * 10 ** 6] * 10 ** 6)", "('x' * 10 ** 6).replace('x', 'xx')",
    "'{:>99999999}'.format(1)", "-" * 200 + "1", "(" * 500 + "1" + ")" * 500,
    "1 + " * 5000 + "1",
])
def test_bounded(expr: str) -> None:
    assert isinstance(safe_eval(expr), SafeEvalUnknown)


@pytest.mark.parametrize("expr, expected", [
    # Autoware's pose_twist_estimator.launch.xml: the pose sources named in pose_source
    ("list(set('ndt_yabloc'.split('_')).intersection(['ndt', 'yabloc', 'eagleye']))", ["ndt", "yabloc"]),
    ("len(list(set('ndt'.split('_')).intersection(['ndt', 'artag']))) > 1", False),
    ("sorted(set([3, 1, 2]).union([0]), reverse=True)", [3, 2, 1, 0]),
    ("tuple(set('ba'))", ("a", "b")), ("set('ab').issubset('abc')", True), ("list('ab')", ["a", "b"]),
])
def test_sets_evaluate_in_one_order(expr: str, expected: object) -> None:
    # a set's order is the hash seed's in Python: here always sorted, so the output never varies
    assert safe_eval(expr) == expected


@pytest.mark.parametrize("expr", ["str(set('ab'))", "set([[1]])", "sorted(set([1, 'a']))", "set('a').pop()",
                                  "'a'.intersection('b')", "list(set('ab'), key=len)"])
def test_sets_refused_where_their_order_or_type_shows(expr: str) -> None:
    assert isinstance(safe_eval(expr), SafeEvalUnknown)


def test_math_module_needed_for_math_names() -> None:
    assert isinstance(safe_eval("math.pi", modules=()), SafeEvalUnknown)
    assert isinstance(safe_eval("sqrt(4)", modules=("os",)), SafeEvalUnknown)


@pytest.mark.parametrize("expr, error", [
    ("not false", "NameError: name 'false' is not defined"),
    ("mapping == 'mapping'", "NameError: name 'mapping' is not defined"),
    ("True and undefined_call(1)", "NameError: name 'undefined_call' is not defined"),
    ("1 +", "SyntaxError"),
])
def test_errors_eval_raises_whatever_the_unknowns(expr: str, error: str) -> None:
    result = safe_eval(expr)
    assert isinstance(result, SafeEvalError) and result.reason.startswith(error)


@pytest.mark.parametrize("expr", [
    "False and false",  # short-circuit: never evaluated
    "True or nope",
    "sorted([2, 1])",  # a builtin the interpreter does not model: unknown, not an error
    "floor(2.5) + e",  # math's names (humble's locals)
    "numpy.pi",  # a module the expression imports (later distros' python_modules)
])
def test_what_eval_finds_is_no_error(expr: str) -> None:
    assert not isinstance(safe_eval(expr, modules=("math", "numpy")), SafeEvalError)


def test_math_names_are_unknown_without_math() -> None:
    assert isinstance(safe_eval("floor(2.5)", modules=("os",)), SafeEvalError)


def test_a_parser_out_of_stack_says_nothing_of_eval(monkeypatch: pytest.MonkeyPatch) -> None:
    import physai_lint.resolve.safe_eval as se

    def deep(*_: object, **__: object) -> None:
        raise RecursionError("maximum recursion depth exceeded")

    monkeypatch.setattr(se.ast, "parse", deep)
    se._parse.cache_clear()
    try:
        result = safe_eval("1 + 2 + 3")
    finally:
        se._parse.cache_clear()
    assert isinstance(result, SafeEvalUnknown) and not isinstance(result, SafeEvalError)


def test_modules_not_known_leave_names_unknown() -> None:
    assert isinstance(safe_eval("pi > 3", modules=None), SafeEvalUnknown)
    assert not isinstance(safe_eval("pi > 3", modules=None), SafeEvalError)
