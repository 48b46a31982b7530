"""``pyast.ast_nodes`` gives exactly ``ast.walk``'s nodes, in its order."""
from __future__ import annotations

import ast
from pathlib import Path

import pytest

from physai_lint.pyast import ast_nodes

SOURCES = sorted((Path(__file__).parents[1] / "physai_lint").rglob("*.py"))


@pytest.mark.parametrize("path", SOURCES[::7], ids=lambda p: p.name)
def test_same_nodes_in_the_same_order_as_ast_walk(path):
    tree = ast.parse(path.read_text(encoding="utf-8"))
    assert [id(n) for n in ast_nodes(tree)] == [id(n) for n in ast.walk(tree)]


def test_every_kind_of_child_field():
    # lists with None holes (dict ** unpacking), optional children, nested comprehensions, match
    text = ("d = {**a, 'k': [x for y in z if y for x in y]}\n"
            "match d:\n    case {'k': [*rest]} if rest: pass\n    case _: pass\n"
            "def f(a, /, b=1, *c, d, **e) -> int:\n    return lambda q=2: q\n")
    tree = ast.parse(text)
    assert [id(n) for n in ast_nodes(tree)] == [id(n) for n in ast.walk(tree)]
