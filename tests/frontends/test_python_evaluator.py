"""Python launch frontend: the partial evaluator, unknowns, facts, robustness and timing."""
from __future__ import annotations

import time

from test_python_constructs import PATH, actions, lit, parse

from physai_lint.model import launch as L
from physai_lint.model import values as V


def test_helper_loop_creates_namespaced_groups_with_unique_ids():
    acts = actions("""
        from launch import LaunchDescription
        from launch.actions import GroupAction
        from launch_ros.actions import Node, PushRosNamespace

        ROBOTS = ['r1', 'r2', 'r3']

        def robot(name, *, sim=False, extra=None):
            nodes = [PushRosNamespace(name)]
            nodes.append(Node(package='base', executable='drive', name=f'{name}_drive',
                              parameters=[{'sim': sim, 'idx': ROBOTS.index(name)}]))
            if extra:
                nodes += extra
            return GroupAction(nodes)

        def generate_launch_description():
            ld = LaunchDescription()
            for i, r in enumerate(ROBOTS):
                if i == 2:
                    continue
                ld.add_action(robot(r, sim=(i % 2 == 0)))
            return ld
    """)
    assert len(acts) == 2
    g1, g2 = acts
    assert [lit(g.actions[0].namespace) for g in acts] == ["r1", "r2"]
    assert lit(g2.actions[1].name) == "r2_drive"
    params = {e.name: e.value.value for e in g2.actions[1].parameters[0].entries}
    assert params == {"sim": False, "idx": 1}
    ids = [g1.id, g2.id, g1.actions[1].id, g2.actions[1].id]
    assert len(set(ids)) == 4 and g1.id.endswith("#1") and g2.id.endswith("#2")


def test_comprehensions_dicts_zip_strings_and_yaml_config():
    files = {"/ws/src/pkg/config/robots.yaml": "robots:\n  - {name: a, x: 1}\n  - {name: b, x: 2}\n"}
    acts = actions("""
        import os
        import yaml
        from launch_ros.actions import Node

        HERE = os.path.dirname(__file__)

        def generate_launch_description():
            with open(os.path.join(HERE, '..', 'config', 'robots.yaml')) as f:
                cfg = yaml.safe_load(f)
            names = [r['name'].upper() for r in cfg['robots'] if r['x'] > 0]
            table = dict(zip(names, range(len(names))))
            return [Node(package='p', executable='e', name='n_{}'.format(k.lower()), namespace='%s_ns' % k,
                         arguments=[str(v), '-' + k * 2]) for k, v in table.items()]
    """, files)
    assert [lit(a.name) for a in acts] == ["n_a", "n_b"]
    assert [lit(a.namespace) for a in acts] == ["A_ns", "B_ns"]
    assert [[lit(x) for x in a.arguments] for a in acts] == [["0", "-AA"], ["1", "-BB"]]
    r = parse("""
        import os, yaml
        def generate_launch_description():
            return []
        yaml.safe_load(open(os.path.join(os.path.dirname(__file__), 'x.yaml')))
    """)
    assert r.launch.actions == ()


def test_sibling_helper_module():
    files = {"/ws/src/pkg/launch/common.py": (
        "from launch_ros.actions import Node\n"
        "def make(name):\n"
        "    return Node(package='p', executable='e', name=name)\n")}
    acts = actions("""
        from common import make
        def generate_launch_description():
            return [make('a'), make('b')]
    """, files)
    assert [lit(a.name) for a in acts] == ["a", "b"]
    assert acts[0].span.file == "/ws/src/pkg/launch/common.py"
    assert acts[0].id != acts[1].id
    assert parse("from common import make\ndef generate_launch_description():\n    return [make('a')]\n",
                 files).launch.read_files == ("/ws/src/pkg/launch/common.py",)


def test_package_share_directory_and_path_join():
    (node,) = actions("""
        import os
        from pathlib import Path
        from ament_index_python.packages import get_package_share_directory
        from launch_ros.actions import Node

        def generate_launch_description():
            share = get_package_share_directory('pkg')
            return [Node(package='p', executable='e', parameters=[os.path.join(share, 'config', 'a.yaml'),
                                                                  str(Path(share) / 'b.yaml')])]
    """)
    (pj,) = node.parameters[0].path
    assert isinstance(pj, V.PathJoin)
    fp = pj.parts[0][0]
    assert isinstance(fp, V.FindPackage) and fp.eager and lit(fp.package) == "pkg"
    assert [lit(p) for p in pj.parts[1:]] == ["config", "a.yaml"]
    assert isinstance(node.parameters[1].path[0], V.PathJoin)


def test_opaque_function_with_context():
    (op,) = actions("""
        from launch import LaunchDescription
        from launch.actions import OpaqueFunction
        from launch.substitutions import LaunchConfiguration
        from launch_ros.actions import Node

        def setup(context, prefix):
            robot = LaunchConfiguration('robot').perform(context)
            mode = context.launch_configurations.get('mode', 'fast')
            nodes = [Node(package='p', executable='e', name=prefix + robot)]
            if mode == 'slow':
                nodes.append(Node(package='p', executable='slow'))
            else:
                nodes.append(Node(package='p', executable='fast'))
            return nodes

        def generate_launch_description():
            return LaunchDescription([OpaqueFunction(function=setup, args=['x_'])])
    """)
    assert isinstance(op, L.OpaqueAction) and op.reason == ""
    n, slow, fast = op.actions
    name = n.name
    assert lit(name[:1]) == "x_" and isinstance(name[1], V.LaunchConfig) and lit(name[1].name) == "robot"
    assert isinstance(slow, L.Group) and not slow.scoped and slow.condition.kind == "if"
    cmp = slow.condition.value[0]
    assert isinstance(cmp, V.Compare) and lit(cmp.right) == "slow" and lit(cmp.left[0].default) == "fast"
    assert lit(slow.actions[0].executable) == "slow"
    assert fast.condition.kind == "unless" and lit(fast.actions[0].executable) == "fast"


def test_opaque_function_branch_returns_and_failure():
    (op, bad) = actions("""
        from launch.actions import OpaqueFunction
        from launch_ros.actions import Node

        def setup(context):
            if context.launch_configurations['sim'] == 'true':
                return [Node(package='sim', executable='e')]
            return [Node(package='real', executable='e')]

        def generate_launch_description():
            return [OpaqueFunction(function=setup), OpaqueFunction(function=imported_elsewhere)]
    """)
    assert [g.condition.kind for g in op.actions] == ["if", "unless"]
    assert isinstance(bad, L.OpaqueAction) and bad.reason and bad.actions == ()


def test_launch_descriptions_returned_early_each_keep_their_branch():
    # an early `return LaunchDescription(...)` under an undecided if, then another at the end (and a
    # second early return in between): every description is kept, each under the conditions that
    # lead to it, rather than the whole file becoming unknown
    acts = actions("""
        import os
        from launch import LaunchDescription
        from launch_ros.actions import Node

        def generate_launch_description():
            if os.environ.get('SIM'):
                return LaunchDescription([Node(package='p', executable='sim')])
            if os.environ.get('REPLAY'):
                return LaunchDescription([Node(package='p', executable='replay')])
            return LaunchDescription([Node(package='p', executable='real')])
    """)
    def under(acts, kinds=()):
        for a in acts:
            if isinstance(a, L.Group):
                yield from under(a.actions, kinds + (a.condition.kind if a.condition else None,))
            else:
                yield kinds, lit(a.executable)

    assert list(under(acts)) == [(("if",), "sim"), (("unless", "if"), "replay"), (("unless", "unless"), "real")]


def test_object_made_in_both_branches_keeps_each_under_its_branch():
    # zed-ros2-wrapper's pattern: one variable, a different object per branch, used after the if
    (stereo, mono, load) = actions("""
        import os
        from launch_ros.actions import LoadComposableNodes, Node
        from launch_ros.descriptions import ComposableNode

        def generate_launch_description():
            if os.environ.get('MODEL') in ('a', 'b'):
                comp = ComposableNode(package='p', plugin='p::Stereo', name='cam')
                node = Node(package='p', executable='stereo')
            else:
                comp = ComposableNode(package='p', plugin='p::Mono', name='cam')
                node = Node(package='p', executable='mono')
            return [node, LoadComposableNodes(target_container='c', composable_node_descriptions=[comp])]
    """)
    # each action under its branch's condition, as if it had been returned from there
    assert [(g.condition.kind, lit(g.actions[0].executable)) for g in (stereo, mono)] == \
        [("if", "stereo"), ("unless", "mono")]
    assert [(lit(c.plugin), c.branch.kind, c.condition) for c in load.nodes] == \
        [("p::Stereo", "if", None), ("p::Mono", "unless", None)]


def test_object_made_before_the_branch_stays_unknown():
    # made before the if, replaced in one branch only: which one runs is not a branch's condition
    (opaque,) = actions("""
        import os
        from launch_ros.actions import Node

        def generate_launch_description():
            node = Node(package='p', executable='default')
            if os.environ.get('MODEL'):
                node = Node(package='p', executable='other')
            return [node]
    """)
    assert isinstance(opaque, L.OpaqueAction) and "condition known only at launch time" in opaque.reason


def _shown(acts):
    """(condition kind or None, executable) of each action: what a branch's condition marked."""
    return [(a.condition.kind if isinstance(a, L.Group) else None,
             lit((a.actions[0] if isinstance(a, L.Group) else a).executable)) for a in acts]


def test_made_before_added_in_a_branch_is_under_the_branch():
    # a node made before an undecided if and added in one branch runs only under that branch
    acts = actions("""
        import os
        from launch import LaunchDescription
        from launch_ros.actions import Node

        def generate_launch_description():
            ld = LaunchDescription()
            rviz = Node(package='rviz2', executable='rviz2')
            extra = [Node(package='p', executable='always')]
            if os.environ.get('RVIZ') == 'true':
                ld.add_action(rviz)
                extra.append(Node(package='p', executable='made_inside'))
            else:
                extra.append(rviz)
            for a in extra:
                ld.add_action(a)
            return ld
    """)
    shown = _shown(acts)
    assert shown == [("if", "rviz2"), (None, "always"), ("if", "made_inside"), ("unless", "rviz2")]


def test_an_item_a_branch_removes_stays_under_the_other_branch():
    acts = actions("""
        import os
        from launch_ros.actions import Node

        def generate_launch_description():
            nodes = [Node(package='p', executable='a'), Node(package='p', executable='b')]
            if os.environ.get('X'):
                nodes.pop()
                nodes.append(Node(package='p', executable='c'))
            return nodes
    """)
    # "b" is launched only when the body is not taken, "c" only when it is
    shown = _shown(acts)
    assert shown == [(None, "a"), ("unless", "b"), ("if", "c")]


def test_each_branch_starts_from_the_list_as_it_was():
    acts = actions("""
        import os
        from launch_ros.actions import Node

        def generate_launch_description():
            nodes = [Node(package='p', executable='a')]
            if os.environ.get('X'):
                nodes.remove(nodes[0])
            else:
                nodes.append(Node(package='p', executable=str(len(nodes))))
            return nodes
    """)
    shown = _shown(acts)
    assert shown == [("unless", "a"), ("unless", "1")]


def test_lists_of_enclosing_scopes_and_inside_dicts_are_followed_per_branch():
    # a module-level list a helper appends to, and a list kept in a dict: an object made before the
    # undecided if and added in one branch is launched under that branch's condition only
    acts = actions("""
        import os
        from launch_ros.actions import Node

        NODES = []

        def add(node):
            if os.environ.get('SIM'):
                NODES.append(node)

        def generate_launch_description():
            add(Node(package='p', executable='sim_only'))
            debug = Node(package='p', executable='debug')
            groups = {'extra': [Node(package='p', executable='always')]}
            if os.environ.get('DEBUG'):
                groups['extra'].append(debug)
            return NODES + groups['extra']
    """)
    assert _shown(acts) == [("if", "sim_only"), (None, "always"), ("if", "debug")]


def test_unknown_values_stay_unknown():
    acts = actions("""
        import os
        from launch_ros.actions import Node
        from some_pkg import helper

        def generate_launch_description():
            nodes = [Node(package='p', executable='e', name=os.environ.get('NAME'), parameters=helper())]
            if os.environ.get('EXTRA'):
                nodes.append(Node(package='x', executable='x'))
            for n in helper():
                nodes.append(Node(package='y', executable='y'))
            return nodes + [helper()]
    """)
    n, extra, loop, opaque = acts
    assert isinstance(n.name[0], V.Unknown) and isinstance(n.parameters[0], L.ParamsUnknown)
    # a Python `if` / `for` on a run-time value keeps what it creates, under an unknown condition
    for group, pkg in ((extra, "x"), (loop, "y")):
        assert isinstance(group, L.Group) and not group.scoped
        assert group.condition.kind == "if" and isinstance(group.condition.value[0], V.Unknown)
        assert "cannot be evaluated statically" in group.condition.value[0].reason
        (inner,) = group.actions
        assert isinstance(inner, L.NodeAction) and inner.package[0].text == pkg
    assert isinstance(opaque, L.OpaqueAction) and "some_pkg.helper" in opaque.reason
    assert len({a.id for a in acts}) == 4


def test_syntax_error_reports_x001():
    r = parse("from launch import LaunchDescription\n\ndef generate_launch_description(:\n    return []\n")
    assert r.launch is None
    (d,) = r.diagnostics
    assert d.code == "X001" and d.span.line == 3 and d.message.startswith("python syntax error:") and d.help


def test_missing_generate_launch_description():
    r = parse("from launch_ros.actions import Node\nNODE = Node(package='p', executable='e')\n")
    assert r.launch.python.has_generate_launch_description is False and r.launch.actions == ()


def test_robustness_deep_nesting_huge_literal_recursion():
    deep = "x = " + "[" * 90 + "]" * 90 + "\ndef generate_launch_description():\n    return []\n"
    assert parse(deep).launch is not None
    deeper = "x = " + "(" * 5000 + ")" * 5000 + "\n"
    assert parse(deeper).diagnostics[0].code == "X001"
    huge = "BIG = [" + ", ".join(str(i) for i in range(200_000)) + "]\ndef generate_launch_description():\n    return []\n"
    assert parse(huge).launch is not None
    r = parse("""
        from launch_ros.actions import Node
        def rec(n):
            return rec(n + 1)
        def spin():
            while True:
                pass
        def generate_launch_description():
            rec(0)
            spin()
            x = 'a' * 10 ** 9
            return [Node(package='p', executable='e')]
    """)
    assert len(r.launch.actions) == 1 and isinstance(r.launch.actions[0], L.NodeAction)
    r = parse("def f(n):\n    return [f(n + 1)]\ndef generate_launch_description():\n    return f(0)\n")
    assert isinstance(r.launch.actions[0], L.OpaqueAction)


def test_call_facts():
    r = parse("""
        import launch_ros.actions as ra
        from launch.actions import DeclareLaunchArgument
        def generate_launch_description():
            return [ra.Node(package='p', node_executable='e', parameters=[{}]), DeclareLaunchArgument('a')]
    """)
    node, decl = r.launch.python.calls
    assert node.qualname == "launch_ros.actions.Node" and decl.qualname == "launch.actions.DeclareLaunchArgument"
    assert [k for k, _ in node.kwargs] == ["package", "node_executable", "parameters"]
    sp = dict(node.kwargs)["node_executable"]
    assert (sp.line, sp.col, sp.end_col) == (5, 34, 49)
    assert dict(node.value_kinds) == {"package": "str", "node_executable": "str", "parameters": "list"}
    assert decl.positional == 1


def test_undefined_names_respect_scopes():
    r = parse("""
        import os
        from launch import LaunchDescription
        G = 1
        class K:
            attr = 1
            def m(self):
                return attr
        def helper(a, *args, b=G, **kw):
            global LATER
            LATER = 2
            y = [z for z in args if z]
            f = lambda q: q + a + y + missing_in_lambda
            try:
                pass
            except Exception as exc:
                print(exc)
            return {k: v for k, v in kw.items()}, f, os, b, z
        def generate_launch_description():
            return LaunchDescription([undefined_thing, LATER, __file__])
    """)
    names = [(n.name, n.span.line) for n in r.launch.python.undefined_names]
    assert names == [("attr", 8), ("missing_in_lambda", 13), ("z", 18), ("undefined_thing", 20)]
    r = parse("from my_helpers import *\ndef generate_launch_description():\n    return [Foo()]\n")
    assert r.launch.python.undefined_names == ()  # any name may come from it
    r = parse("from launch.actions import *\ndef generate_launch_description():\n    return [Foo()]\n")
    assert [n.name for n in r.launch.python.undefined_names] == ["Foo"]  # not a launch.actions name


def test_concat_facts():
    r = parse("""
        import os
        from launch.substitutions import LaunchConfiguration
        from launch_ros.substitutions import FindPackageShare
        from ament_index_python.packages import get_package_share_directory
        def generate_launch_description():
            lc = LaunchConfiguration('x')
            a = 'pre_' + lc
            b = os.path.join(FindPackageShare('p'), 'x')
            c = f'{lc}/y'
            d = str(lc)
            e = '{}'.format(lc)
            f = '%s' % lc
            ok = os.path.join(get_package_share_directory('p'), 'x') + '/ok'
            return []
    """)
    hows = [(c.how, c.span.line) for c in r.launch.python.concatenations]
    assert hows == [("plus", 8), ("os.path.join", 9), ("f-string", 10), ("str", 11), ("format", 12), ("percent", 13)]


def test_non_ascii_columns():
    (node,) = actions("""
        from launch_ros.actions import Node
        def generate_launch_description():
            return [Node(name='ß', package='pkg', executable='e')]
    """)
    sp = node.span_of("package")
    assert (sp.col, sp.end_col) == (36, 41)


def test_timing_300_line_file():
    lines = ["from launch import LaunchDescription", "from launch.actions import DeclareLaunchArgument, GroupAction",
             "from launch.substitutions import LaunchConfiguration, PathJoinSubstitution",
             "from launch_ros.actions import Node, PushRosNamespace", "from launch_ros.substitutions import FindPackageShare",
             "", "def generate_launch_description():", "    ld = LaunchDescription()"]
    i = 0
    while len(lines) < 300:
        lines += [
            f"    ld.add_action(DeclareLaunchArgument('arg{i}', default_value='v{i}'))",
            f"    ld.add_action(GroupAction([PushRosNamespace('ns{i}'), Node(",
            f"        package='pkg{i}', executable='exe', name='node{i}',",
            f"        parameters=[PathJoinSubstitution([FindPackageShare('pkg{i}'), 'config', 'p.yaml']),",
            f"                    {{'rate': {i}.0, 'use_sim_time': LaunchConfiguration('arg{i}')}}],",
            f"        remappings=[('in', 'in{i}')])]))",
        ]
        i += 1
    lines.append("    return ld")
    src = "\n".join(lines) + "\n"
    from physai_lint.frontends.python import parse_python_launch

    t0 = time.perf_counter()
    for _ in range(10):
        r = parse_python_launch(PATH, src, None)
    ms = (time.perf_counter() - t0) / 10 * 1000
    print(f"\npython frontend: {len(lines)}-line file parse+evaluate {ms:.1f} ms")
    assert len(r.launch.actions) == 2 * i


def test_a_list_a_branch_reorders_keeps_each_item_once():
    acts = actions("""
        import os
        from launch_ros.actions import Node

        def generate_launch_description():
            nodes = [Node(package='p', executable='a'), Node(package='p', executable='b')]
            if os.environ.get('X'):
                nodes.reverse()
            return nodes
    """)
    assert sorted(_shown(acts)) == [(None, "a"), (None, "b")]


def test_an_item_removed_by_a_nested_undecided_if_is_there_once():
    acts = actions("""
        import os
        from launch_ros.actions import Node

        def generate_launch_description():
            nodes = [Node(package='p', executable='a'), Node(package='p', executable='b')]
            if os.environ.get('X'):
                if os.environ.get('Y'):
                    nodes.pop()
            return nodes
    """)
    assert [exe for _, exe in _shown(acts)] == ["a", "b"]


def test_appending_under_an_undecided_if_matches_only_what_differs(monkeypatch):
    # The list's common ends are not matched: an append-only branch leaves nothing to match, so a
    # loop of such ifs does not pay the matcher's quadratic cost on a growing list.
    from physai_lint.frontends.python import evaluator

    matched = []

    class Recording(evaluator.SequenceMatcher):  # type: ignore[misc]
        def __init__(self, junk, a, b, autojunk=True):
            matched.append(len(a) + len(b))
            super().__init__(junk, a, b, autojunk=autojunk)

    monkeypatch.setattr(evaluator, "SequenceMatcher", Recording)
    acts = actions("""
        import os
        from launch_ros.actions import Node

        def generate_launch_description():
            nodes = []
            for i in range(300):
                if os.environ.get('X'):
                    nodes.append(Node(package='p', executable='a'))
            return nodes
    """)
    assert len(acts) == 300
    assert max(matched) <= 1
