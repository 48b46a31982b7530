"""The class whose code holds each item extraction finds: class bodies, member functions defined
outside their class (with their heads and constructor initialisers), nothing for free functions."""
from __future__ import annotations

import pytest

from physai_lint.interfaces.cpp_scopes import CppFacts
from physai_lint.interfaces.extract_cpp import _extract_from, _Windows

PUB = 'create_publisher<std_msgs::msg::String>("{}", 1)'


def _owners(text: str) -> dict[str, str | None]:
    """topic -> the class holding its publisher."""
    view = _Windows.of(text)
    assert view is not None
    facts = CppFacts()
    _extract_from("src/a.cpp", view, facts)
    return {e.name: owner for _, e, owner in facts.endpoints}


@pytest.mark.parametrize("text, owners", [
    # out-of-class definitions, in namespaces, a template's, a destructor's
    ("namespace a { namespace b {\nFoo::Foo() : Node(\"x\") { p = " + PUB.format("ctor") + "; }\n"
     "void Foo::run() const { p = " + PUB.format("run") + "; }\n} }\n"
     "template <typename T>\nvoid Bar<T>::go(std::vector<int> v) { p = " + PUB.format("tmpl") + "; }\n"
     "Baz::~Baz() { p = " + PUB.format("dtor") + "; }\n",
     {"ctor": "Foo", "run": "Foo", "tmpl": "Bar", "dtor": "Baz"}),
    # a class body: inline member functions, with attribute macros, bases, final
    ("class DEMO_PUBLIC Node1 final : public rclcpp::Node, public Base<int> {\n public:\n"
     "  Node1() : rclcpp::Node(\"n\") { p = " + PUB.format("inline") + "; }\n"
     "  struct Inner { void f() { p = " + PUB.format("inner") + "; } };\n};\n",
     {"inline": "Node1", "inner": "Node1"}),
    # free functions, main, a gtest body, a lambda at namespace level, extern "C"
    ("static void helper(rclcpp::Node & n, const rclcpp::QoS & q = rclcpp::QoS(1)) {\n"
     "  n." + PUB.format("free") + "; }\n"
     "int main() { n->" + PUB.format("main") + "; }\n"
     "TEST_F(Fixture, works) { n->" + PUB.format("test") + "; }\n"
     "extern \"C\" { void c_api() { n->" + PUB.format("extern") + "; } }\n"
     "auto make = [](auto n) { return n->" + PUB.format("lambda") + "; };\n",
     {"free": None, "main": None, "test": None, "extern": None, "lambda": None}),
    # initialisers: braced members, a lambda in a call, a comment before the body
    ("Foo::Foo(rclcpp::Node::SharedPtr node)\n: a_{1}, b_(make([this]() { return 1; })),\n"
     "  c_(node->" + PUB.format("init") + ") // the body\n{\n  p = " + PUB.format("body") + ";\n}\n"
     "enum class Mode { A, B };\nint count = 0;\n"
     "void Foo::later() { p = " + PUB.format("later") + "; }\n",
     {"init": "Foo", "body": "Foo", "later": "Foo"}),
    # a brace in a comment, a string or a preprocessor line counts for nothing
    ("// }\n#define OPEN {\nconst char * s = \"}\";\nvoid Foo::a() { p = " + PUB.format("a") + "; }\n"
     "void helper() { p = " + PUB.format("b") + "; }\n",
     {"a": "Foo", "b": None}),
], ids=["out-of-class", "class-body", "free", "initialisers", "skimmed-braces"])
def test_items_are_tagged_with_the_class_whose_code_holds_them(text: str,
                                                               owners: dict[str, str | None]) -> None:
    assert _owners(text) == owners


def test_a_lifecycle_base_belongs_to_its_class() -> None:
    view = _Windows.of("class Talker : public rclcpp_lifecycle::LifecycleNode {\n  Talker();\n};\n")
    assert view is not None
    facts = CppFacts()
    _extract_from("src/a.cpp", view, facts)
    assert facts.lifecycle == ["Talker"]
    assert [c for c, _, _ in facts.classes] == ["Talker"]
