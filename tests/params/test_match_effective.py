import pytest

from physai_lint.model.span import Span
from physai_lint.params import (
    composable_key_matches, effective_parameters, explain_no_match, file_binds, key_matches,
    load_param_file, matching_keys,
)
from physai_lint.resolve.model import (
    ResolvedParam, ResolvedParamDict, ResolvedParamFile, UnknownParams,
)

S = Span("/ws/launch.py", 1, 1, 1, 2)


@pytest.mark.parametrize("key,fqn,ok", [
    ("/**", "/a", True), ("/**", "/ns/deep/a", True), ("**", "/x/y", True),
    ("/*", "/a", True), ("/*", "/ns/a", False),
    ("/**/n", "/n", True), ("/**/n", "/r1/n", True), ("/**/n", "/r1/x/n", True),
    ("/**/n", "/r1/m", False),
    ("/ns/**", "/ns", True), ("/ns/**", "/ns/a", True), ("/ns/**", "/ns/a/b", True),
    ("/ns/**", "/other/a", False),
    ("ns/*", "/ns/a", True), ("ns/*", "/ns/a/b", False), ("ns/*", "/ns", False),
    ("teleop_node", "/teleop_node", True), ("teleop_node", "/robot1/teleop_node", False),
    ("/robot1/teleop_node", "/robot1/teleop_node", True), ("robot1/teleop_node", "/robot1/teleop_node", True),
    ("/**/teleop", "/robot1/teleop", True), ("/**/teleop", "/robot2/teleop", True),
])
def test_key_matches(key, fqn, ok):
    assert key_matches(key, fqn) is ok


@pytest.mark.parametrize("key,fqn,ok", [
    ("/**", "/front/rectify", True), ("**", "/a", True), ("/front/rectify", "/front/rectify", True),
    ("front/rectify", "/front/rectify", True), ("/**/rectify", "/front/rectify", False),
    ("/front/*", "/front/rectify", False), ("rectify", "/front/rectify", False),
])
def test_composable_key_matches(key, fqn, ok):
    assert composable_key_matches(key, fqn) is ok


@pytest.mark.parametrize("key,fqn,ok", [
    # launch_ros __normalize_parameters_dict joins nested keys with "/", each lstripped of "/"
    ("robot/talker", "/robot/talker", True), ("/robot/talker", "/robot/talker", True),
    ("/robot//talker", "/robot/talker", True),  # {/robot: {/talker: ...}}
    ("robot/**", "/robot/talker", False), ("robot/talker", "/talker", False),
])
def test_nested_composable_keys_are_joined_as_launch_ros_joins_them(key, fqn, ok):
    assert composable_key_matches(key, fqn, nested=True) is ok


def test_p103_on_a_component_suggests_only_keys_launch_ros_honours(demo_findings):
    launch = (
        "from launch import LaunchDescription\n"
        "from launch.substitutions import PathJoinSubstitution\n"
        "from launch_ros.actions import ComposableNodeContainer\n"
        "from launch_ros.descriptions import ComposableNode\n"
        "from launch_ros.substitutions import FindPackageShare\n\n\n"
        "def generate_launch_description():\n"
        "    params = PathJoinSubstitution([FindPackageShare('demo'), 'config', 'p.yaml'])\n"
        "    return LaunchDescription([ComposableNodeContainer(\n"
        "        name='c', namespace='', package='rclcpp_components', executable='component_container',\n"
        "        composable_node_descriptions=[ComposableNode(\n"
        "            package='composition', plugin='composition::Talker', name='talker', namespace='robot',\n"
        "            parameters=[params])])])\n")
    files = {"config/p.yaml": "talker:\n  ros__parameters:\n    rate: 1.0\n", "launch/a.launch.py": launch}
    ((_, message),) = demo_findings(files, "launch/a.launch.py", "P103")
    assert '"/**/talker"' not in message and "composable nodes ignore other wildcards" in message
    nested = {**files, "config/p.yaml": "robot:\n  talker:\n    ros__parameters:\n      rate: 1.0\n"}
    assert demo_findings(nested, "launch/a.launch.py", "P103") == []


def test_explain():
    msg = explain_no_match("teleop_node", "/robot1/teleop_node")
    assert msg == ('key "teleop_node" matches /teleop_node only; the node is /robot1/teleop_node '
                   '(use "robot1/teleop_node" or "/**/teleop_node")')
    assert "root namespace" in explain_no_match("/*", "/r/n")


def _file(path, text):
    return load_param_file(path, text)


def _src(path):
    return ResolvedParamFile(path, path, "ok", S, "node")


def test_later_wildcard_does_not_beat_earlier_specific_key():
    # /** was first inserted by the earlier file: the later file's /** overwrites in place, so the
    # specific key (inserted after it) still comes last in resolution and wins.
    files = {
        "/a.yaml": _file("/a.yaml", "/**:\n  ros__parameters:\n    use_sim_time: false\n"
                         "/robot1/controller:\n  ros__parameters:\n    rate: 10\n"),
        "/b.yaml": _file("/b.yaml", "/**:\n  ros__parameters:\n    rate: 20\n"),
    }
    eff = effective_parameters("/robot1/controller", [_src("/a.yaml"), _src("/b.yaml")], files)
    assert eff["rate"].value == 10
    assert [(b.value, b.overridden) for b in eff["rate"].chain] == [(20, True), (10, False)]
    assert eff["rate"].origin.file == "/a.yaml"


def test_insertion_order_decides_between_keys():
    files = {
        "/a.yaml": _file("/a.yaml", "/robot1/controller:\n  ros__parameters:\n    rate: 10\n"),
        "/b.yaml": _file("/b.yaml", "/**:\n  ros__parameters:\n    rate: 20\n"),
    }
    # specific key inserted first, /** after: the wildcard is resolved later and wins
    eff = effective_parameters("/robot1/controller", [_src("/a.yaml"), _src("/b.yaml")], files)
    assert eff["rate"].value == 20
    # the reverse order: the specific key is inserted after the wildcard and wins
    eff = effective_parameters("/robot1/controller", [_src("/b.yaml"), _src("/a.yaml")], files)
    assert eff["rate"].value == 10
    eff = effective_parameters("/robot2/controller", [_src("/b.yaml"), _src("/a.yaml")], files)
    assert eff["rate"].value == 20


def test_wildcard_first_then_specific_in_one_file():
    f = _file("/p.yaml", "/**:\n  ros__parameters:\n    r: 1\n    s: 5\nnode:\n  ros__parameters:\n    r: 2\n")
    eff = effective_parameters("/node", [_src("/p.yaml")], {"/p.yaml": f})
    assert eff["r"].value == 2 and eff["s"].value == 5
    f2 = _file("/q.yaml", "node:\n  ros__parameters:\n    r: 2\n'/**':\n  ros__parameters:\n    r: 1\n")
    eff = effective_parameters("/node", [_src("/q.yaml")], {"/q.yaml": f2})
    assert eff["r"].value == 1


def test_type_changing_redefinition():
    files = {
        "/a.yaml": _file("/a.yaml", "n:\n  ros__parameters:\n    x: text\n"),
        "/b.yaml": _file("/b.yaml", "n:\n  ros__parameters:\n    x: 5\n"),
    }
    eff = effective_parameters("/n", [_src("/a.yaml"), _src("/b.yaml")], files)
    assert (eff["x"].kind, eff["x"].value) == ("integer", 5)
    eff = effective_parameters("/n", [_src("/b.yaml"), _src("/a.yaml")], files)
    assert (eff["x"].kind, eff["x"].value) == ("integer", 5)  # int slot still read first


def test_dict_sources_and_unknowns():
    f = _file("/a.yaml", "/**:\n  ros__parameters:\n    rate: 10\n")
    d = ResolvedParamDict((ResolvedParam("rate", "1e3", S, raw="1e3", typed_by="yaml"),
                           ResolvedParam("flag", True, S)), S, "node", key="/n")
    eff = effective_parameters("/n", [_src("/a.yaml"), d], {"/a.yaml": f})
    # different node keys: "/n" (from the dict) is resolved after "/**" and wins; the str "1e3"
    # is dumped plain by launch and re-read by rcl as a double
    assert eff["rate"].kind == "double" and eff["rate"].value == 1000.0
    assert eff["flag"].value is True and eff["rate"].certain
    eff = effective_parameters("/n", [_src("/a.yaml"), UnknownParams("x", S)], {"/a.yaml": f})
    assert not eff["rate"].certain
    # unknown node name: only universal keys count, specific keys make their names uncertain
    g = _file("/g.yaml", "/**:\n  ros__parameters:\n    a: 1\nn:\n  ros__parameters:\n    a: 2\n")
    eff = effective_parameters(None, [_src("/g.yaml")], {"/g.yaml": g})
    assert eff["a"].value == 1 and not eff["a"].certain
    # missing files are dropped by launch
    eff = effective_parameters("/n", [ResolvedParamFile(None, None, "missing", S, "node")], {})
    assert eff == {}


def test_empty_array_not_set():
    f = _file("/a.yaml", "n:\n  ros__parameters:\n    x: []\n")
    eff = effective_parameters("/n", [_src("/a.yaml")], {"/a.yaml": f})
    assert eff["x"].kind == "not_set"


def test_composable_rules():
    f = _file("/c.yaml",
              "front/rectify:\n  ros__parameters:\n    q: 2\n"
              "/**:\n  ros__parameters:\n    q: 1\n    e: 1e3\n"
              "/**/rectify:\n  ros__parameters:\n    w: 9\n")
    eff = effective_parameters("/front/rectify", [_src("/c.yaml")], {"/c.yaml": f}, composable=True)
    assert eff["q"].value == 2  # exact beats ** within a file whatever the order
    assert eff["e"].value == "1e3" and eff["e"].kind == "string"  # PyYAML typing
    assert "w" not in eff  # /**/name ignored for components
    assert file_binds("/front/rectify", f, composable=True)
    assert [b.key for b in matching_keys("/front/rectify", f)] == ["front/rectify", "/**", "/**/rectify"]
    g = _file("/g.yaml", "/**:\n  ros__parameters:\n    q: 3\n")
    eff = effective_parameters("/front/rectify", [_src("/c.yaml"), _src("/g.yaml")],
                               {"/c.yaml": f, "/g.yaml": g}, composable=True)
    assert eff["q"].value == 3  # last one wins across sources


_MANY_KEYS = """\
/**:
  ros__parameters:
    use_sim_time: false
    rate: 1
/ns/node:
  ros__parameters:
    rate: 2
    gains: [1, 2.5]
node:
  ros__parameters:
    rate: 3
/ns/*:
  ros__parameters:
    mode: "a"
/**/node:
  ros__parameters:
    rate: 4
    mode: b
/ns/node:
  ros__parameters:
    extra: true
/other:
  ros__parameters:
    rate: 5
"""


@pytest.mark.parametrize("fqn", ["/ns/node", "/node", "/other", "/ns/x", "/deep/ns/node", None])
def test_replaying_only_matching_keys_equals_replaying_the_whole_file(fqn, monkeypatch):
    import physai_lint.params.effective as eff

    files = {"/a.yaml": _file("/a.yaml", _MANY_KEYS), "/b.yaml": _file("/b.yaml", _MANY_KEYS.replace("rate: 2", "rate: 7"))}
    dict_src = ResolvedParamDict((ResolvedParam("rate", 9, S),), S, "node")
    sources = [_src("/a.yaml"), dict_src, _src("/b.yaml")]
    got = effective_parameters(fqn, sources, files)
    # The whole file replayed: one segment under a key every node matches.
    monkeypatch.setattr(eff, "_ops_by_node_key", lambda model: [("/**", model.ops)])
    assert got == effective_parameters(fqn, sources, files)
    assert got  # the fixture sets something for every node
