"""The loader follows rcl's parameter selection without replaying every op; the "never got a
value" P104 must come out exactly as a full replay into ``RclParams`` gives it."""
from physai_lint.params import load_param_file
from physai_lint.params.rcl import RclParams


def load(text):
    return load_param_file("/ws/p.yaml", text)


def unset(m):
    return [(d.span.line, d.key) for d in m.diagnostics if "empty array" in d.message]


def test_nested_maps_are_not_unset():
    m = load("n:\n  ros__parameters:\n    layer:\n      scan:\n        topic: /scan\n"
             "        rate: 5\n      depth: {topic: /d}\n")
    assert m.ok and m.diagnostics == []
    assert [p.name for b in m.blocks for p in b.params] == [
        "layer.scan.topic", "layer.scan.rate", "layer.depth.topic"]


def test_empty_array_and_empty_map_are_unset():
    m = load("n:\n  ros__parameters:\n    a: []\n    c: 1\n    b: {}\n")
    assert unset(m) == [(1, "b"), (3, "a")]  # {} has no FileParam: the whole file


def test_rename_onto_an_existing_name_selects_the_first():
    # "a.b" exists; the nested map renames a new entry to "a.b" too, and the deeper map then
    # looks "a.b" up: rcl finds the first one, so the second never gets a value.
    m = load("n:\n  ros__parameters:\n    a.b: 1\n    a:\n      b:\n        c: 2\n")
    full = RclParams()
    full.apply(m.ops, m.path)
    names = [(e.name, e.read() is None) for e in full.nodes["n"].entries]
    assert names == [("a.b.c", False), ("a.b", True)]
    assert unset(m) == [(1, "a.b")]


def test_same_key_in_two_blocks_of_one_node():
    m = load("n:\n  ros__parameters:\n    x: []\nn:\n  ros__parameters:\n    x: 3\n")
    assert unset(m) == []  # the second block gives the same entry a value


def test_find_parameter_after_renames():
    r = RclParams()
    r.find_node("n")
    r.find_parameter("a")
    r.rename("x")
    r.find_parameter("b")
    r.rename("x")  # two entries named "x": lookups select the first
    r.find_parameter("x")
    assert r.current() is r.nodes["n"].entries[0]
    r.rename("y")
    r.find_parameter("x")
    assert r.current() is r.nodes["n"].entries[1]
    r.find_parameter("a")
    assert [e.name for e in r.nodes["n"].entries] == ["y", "x", "a"]
