"""The $(...) grammar: nesting, quoting, escapes, exact spans and L007 errors."""
from __future__ import annotations

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[2]))  # tests run without an install

import pytest  # noqa: E402

from physai_lint.frontends.substitutions import (  # noqa: E402
    DISTRO_ONLY_SUBSTITUTIONS, parse_substitutions,
)
from physai_lint.model.span import Span  # noqa: E402
from physai_lint.model.values import (  # noqa: E402
    Anon, BoolOp, Command, Compare, EnvVar, ExecInPackage, FileContent, FindExecutable,
    FindPackage, IfElse, LaunchConfig, ParamRef, PythonExpr, Text, ThisFile, ThisFileDir, Unknown,
    literal_of,
)

F = "/ws/a.launch.xml"


def parse(text: str, line: int = 1, col: int = 1):  # type: ignore[no-untyped-def]
    return parse_substitutions(text, Span(F, line, col, line, col + len(text)))


def test_plain_text_is_one_text_part() -> None:
    value, diags = parse("hello world")
    assert value == (Text("hello world", Span(F, 1, 1, 1, 12)),) and diags == []


@pytest.mark.parametrize("text", ["a", "hello world", "  padded  ", "tab\there", "ünïcode", "(x)", "'q'"])
def test_plain_one_line_text_is_what_the_general_path_makes(text: str) -> None:
    # a value without "$", "\\" or a newline takes a short cut; given its positions explicitly,
    # the same value goes the general way
    from physai_lint.frontends.substitutions import positions_from

    span = Span(F, 3, 7, 3, 7 + len(text))
    assert parse_substitutions(text, span) == parse_substitutions(text, span, positions_from(text, 3, 7))


def test_empty_value() -> None:
    value, diags = parse("")
    assert literal_of(value) == "" and diags == []


def test_var_with_default_and_spans() -> None:
    value, diags = parse("ns/$(var robot r1)", line=3, col=10)
    assert diags == []
    assert value[0] == Text("ns/", Span(F, 3, 10, 3, 13))
    sub = value[1]
    assert isinstance(sub, LaunchConfig)
    assert sub.span == Span(F, 3, 13, 3, 28)
    assert literal_of(sub.name) == "robot" and literal_of(sub.default) == "r1"
    assert sub.name[0].span == Span(F, 3, 19, 3, 24)


def test_nesting() -> None:
    value, diags = parse("$(find-pkg-share $(var pkg))/config/a.yaml")
    assert diags == []
    share = value[0]
    assert isinstance(share, FindPackage) and share.kind == "share"
    inner = share.package[0]
    assert isinstance(inner, LaunchConfig) and literal_of(inner.name) == "pkg"
    assert inner.span is not None and inner.span.col == 18
    assert literal_of(value[1:]) == "/config/a.yaml"


def test_quoted_argument_keeps_spaces_and_nested_substitution() -> None:
    value, diags = parse("$(eval '$(var speed) * 2 > 1')")
    assert diags == []
    expr = value[0]
    assert isinstance(expr, PythonExpr) and expr.modules == ("math",)
    assert isinstance(expr.expression[0], LaunchConfig)
    assert expr.expression[1] == Text(" * 2 > 1", Span(F, 1, 21, 1, 29))


def test_double_quoted_argument() -> None:
    value, diags = parse('$(var "a b")')
    assert diags == [] and isinstance(value[0], LaunchConfig)
    assert literal_of(value[0].name) == "a b"


def test_eval_modules_argument() -> None:
    value, _ = parse("$(eval 'math.pi' 'math,os')")
    assert isinstance(value[0], PythonExpr) and value[0].modules == ("math", "os")


def test_escaped_dollar_is_text() -> None:
    value, diags = parse(r"cost \$(var x)")
    assert diags == [] and literal_of(value) == "cost $(var x)"


@pytest.mark.parametrize("text, expected", [
    ("price $5", "price $5"), ("regex .*xacro)$", "regex .*xacro)$"), ("$", "$"),
    ("$(env HOME a$b)", None), ("$(eval \"'a$' + 'b'\")", None)])
def test_a_dollar_not_followed_by_a_parenthesis_is_text(text: str, expected: str | None) -> None:
    # launch's grammar.lark: every string token takes \$(?!\() (launch #461)
    value, diags = parse(text)
    assert diags == []
    assert literal_of(value) == expected if expected is not None else not any(isinstance(p, Unknown) for p in value)


@pytest.mark.parametrize("text, cls", [
    ("$(env HOME)", EnvVar), ("$(find-pkg-prefix p)", FindPackage),
    ("$(find-exec ls)", FindExecutable), ("$(exec-in-pkg talker demo)", ExecInPackage),
    ("$(dirname)", ThisFileDir), ("$(filename)", ThisFile), ("$(anon n)", Anon),
    ("$(command 'ls -l')", Command), ("$(command ls warn)", Command), ("$(not a)", BoolOp),
    ("$(and a b)", BoolOp), ("$(or a b)", BoolOp), ("$(any a b c)", BoolOp), ("$(all a)", BoolOp),
    ("$(equals a b)", Compare), ("$(not-equals a b)", Compare), ("$(if c a b)", IfElse), ("$(if c a)", IfElse),
    ("$(param p)", ParamRef), ("$(param p d)", ParamRef), ("$(file-content f)", FileContent), ("$(log_dir)", Unknown),
    ("$(launch_log_dir)", Unknown),
])
def test_every_substitution(text: str, cls: type) -> None:
    value, diags = parse(text)
    assert diags == [] and len(value) == 1 and isinstance(value[0], cls)
    assert value[0].span == Span(F, 1, 1, 1, len(text) + 1)


def test_if_without_else_value_is_valid() -> None:
    # launch's IfElseSubstitution.parse takes 2 or 3 arguments; else_value defaults to ''
    value, diags = parse("$(if $(var on) $(var frame_id))")
    assert diags == []
    sub = value[0]
    assert isinstance(sub, IfElse) and sub.else_value == ()
    assert isinstance(sub.if_value[0], LaunchConfig)


def test_param_with_default_is_valid() -> None:
    # launch_ros Parameter.parse takes a default as second argument since jazzy
    value, diags = parse("$(param rate 10)")
    assert diags == [] and isinstance(value[0], ParamRef)
    assert literal_of(value[0].name) == "rate" and literal_of(value[0].default) == "10"


def test_if_without_else_value_evaluates_to_empty_when_false(demo_graph) -> None:  # type: ignore[no-untyped-def]
    files = {"launch/a.launch.xml": """<launch>
  <arg name="suffix" default="false"/>
  <node pkg="demo" exec="talker" name="talker$(if $(var suffix) _on)"/>
</launch>
"""}
    assert set(demo_graph(files, "launch/a.launch.xml")) == {"talker"}
    assert set(demo_graph(files, "launch/a.launch.xml", suffix="true")) == {"talker_on"}


@pytest.mark.parametrize("text, instead", [("$(optenv X /tmp)", "$(env NAME DEFAULT)"),
                                           ("$(arg robot)", "$(var NAME)"), ("$(find pkg)", "$(find-pkg-share PKG)")])
def test_ros1_substitutions_are_unknown_with_the_ros2_spelling(text: str, instead: str) -> None:
    # ros2/launch exposes no optenv/arg/find: launch fails with "Unknown substitution"
    value, diags = parse(text)
    assert [d.code for d in diags] == ["L007"] and isinstance(value[0], Unknown)
    assert "ROS 1" in (diags[0].help or "") and instead in (diags[0].help or "")


def test_unknown_substitution_with_did_you_mean() -> None:
    value, diags = parse("a $(vra robot)", line=2, col=5)
    assert [d.code for d in diags] == ["L007"]
    d = diags[0]
    assert d.message == 'unknown substitution "$(vra robot)"'
    assert d.span == Span(F, 2, 7, 2, 19)
    assert d.help is not None and '"var"' in d.help
    assert isinstance(value[1], Unknown)


@pytest.mark.parametrize("text", ["$(eval 10 * 3)", "$(var)", "$(var a b c)", "$(dirname x)",
                                  "$(if a)", "$(if a b c d)", "$(param a b c)", "$(exec-in-pkg x)"])
def test_wrong_arity(text: str) -> None:
    value, diags = parse(text)
    assert [d.code for d in diags] == ["L007"] and "expects" in diags[0].message
    assert isinstance(value[0], Unknown)


@pytest.mark.parametrize("text, col", [("x $(var a", 3), ("$(var  a)", 7), ("$(var a )", 9),
                                       ("$( var a)", 3), ("$(var 'a)", 7)])
def test_malformed_positions(text: str, col: int) -> None:
    value, diags = parse(text)
    assert [d.code for d in diags] == ["L007"], diags
    assert diags[0].span.col == col
    assert any(isinstance(p, Unknown) for p in value)


def test_recovers_after_malformed() -> None:
    value, diags = parse("$(var  a)/$(var b)")
    assert len(diags) == 1
    assert isinstance(value[-1], LaunchConfig)


def test_multiline_value_columns() -> None:
    text = "first\n  $(var a)\n    x $(env B)"
    value, diags = parse(text, line=4, col=20)
    assert diags == []
    var, env = value[1], value[3]
    assert var.span == Span(F, 5, 3, 5, 11)
    assert env.span == Span(F, 6, 7, 6, 15)


def test_explicit_positions_are_used() -> None:
    positions = [(9, c) for c in range(40, 49)]
    value, _ = parse_substitutions("$(var a)", Span(F, 1, 1, 1, 9), positions)
    assert value[0].span == Span(F, 9, 40, 9, 48)


def test_distro_table() -> None:
    assert set(DISTRO_ONLY_SUBSTITUTIONS) == {"any", "all", "equals", "not-equals", "if",
                                              "file-content", "launch_log_dir"}
    _, diags = parse("$(equals a b)")
    assert diags == []  # reported by a rule that knows the distro
