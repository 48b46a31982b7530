"""Python launch frontend: ROS_DISTRO reads, match statements, decorated helpers and simple classes.

Each construct has a case that resolves over known values and one that stays unknown."""
from __future__ import annotations

import textwrap

from test_python_constructs import PATH, lit

from physai_lint.frontends.python import parse_python_launch
from physai_lint.model import launch as L
from physai_lint.model import values as V


def actions(src: str, distro: str | None = None) -> tuple[L.Action, ...]:
    r = parse_python_launch(PATH, textwrap.dedent(src), None, distro)
    assert r.launch is not None, r.diagnostics
    return r.launch.actions


def executables(acts: tuple[L.Action, ...]) -> list[str]:
    return [lit(a.executable) for a in acts if isinstance(a, L.NodeAction)]


DISTRO_SRC = """
    import os
    from os import environ, getenv
    from launch import LaunchDescription
    from launch_ros.actions import Node

    def generate_launch_description():
        nodes = []
        if os.getenv('ROS_DISTRO') == 'humble':
            nodes.append(Node(package='p', executable='old'))
        else:
            nodes.append(Node(package='p', executable='new'))
        if environ.get('ROS_DISTRO') in ['humble', 'iron']:
            nodes.append(Node(package='p', executable='in_list'))
        if os.environ['ROS_DISTRO'] >= 'jazzy' and 'ROS_DISTRO' in os.environ:
            nodes.append(Node(package='p', executable='ge_jazzy'))
        nodes.append(Node(package='p', executable=f"drv_{getenv('ROS_DISTRO', 'x')}"))
        return LaunchDescription(nodes)
"""


def test_ros_distro_is_the_checked_distro():
    assert executables(actions(DISTRO_SRC, "humble")) == ["old", "in_list", "drv_humble"]
    assert executables(actions(DISTRO_SRC, "jazzy")) == ["new", "ge_jazzy", "drv_jazzy"]


def test_ros_distro_without_a_distro_and_other_variables_stay_unknown():
    acts = actions(DISTRO_SRC)
    # the first `if` keeps both branches under an unknown condition naming the variable
    first = acts[0]
    assert isinstance(first, L.Group) and isinstance(first.condition.value[0], V.Unknown)
    assert '"ROS_DISTRO"' in first.condition.value[0].reason
    (node,) = actions("""
        import os
        from launch_ros.actions import Node

        def generate_launch_description():
            return [Node(package='p', executable='e', name=os.getenv('ROBOT_NAME', 'r'),
                         namespace=os.environ['HOME'])]
    """, "jazzy")
    assert isinstance(node.name[0], V.Unknown) and "ROBOT_NAME" in node.name[0].reason
    assert isinstance(node.namespace[0], V.Unknown)


def test_distro_reaches_python_files_through_the_file_store_and_its_cache(tmp_path):
    from physai_lint.cache import ParseCache
    from physai_lint.files import FileStore

    path = tmp_path / "d.launch.py"
    path.write_text(textwrap.dedent(DISTRO_SRC))
    cache = ParseCache(str(tmp_path / "cache"))
    seen = []
    for distro in ("humble", "jazzy", "humble"):
        store = FileStore(cache=cache)
        store.preload([str(path)], [], distro, 1)
        seen.append(executables(store.launches[str(path)].actions)[0])
        store = FileStore(cache=cache, distro=distro)  # the lazy path (files reached by includes)
        assert executables(store.launch(str(path)).actions)[0] == seen[-1]
    assert seen == ["old", "new", "old"] and cache.hits >= 3


def test_match_over_known_values_and_launch_time_strings():
    acts = actions("""
        import os
        from launch.actions import OpaqueFunction
        from launch.substitutions import LaunchConfiguration
        from launch_ros.actions import Node

        CFG = {'kind': 'diff', 'wheels': [1, 2, 3]}

        def setup(context):
            match LaunchConfiguration('mode').perform(context):
                case 'sim' | 'gazebo':
                    return [Node(package='sim', executable='s')]
            return []

        def generate_launch_description():
            nodes = []
            match os.environ['ROS_DISTRO']:
                case 'humble':
                    nodes.append(Node(package='m', executable='h'))
                case 'jazzy' | 'kilted':
                    nodes.append(Node(package='m', executable='j'))
            match CFG:
                case {'kind': 'diff', 'wheels': [first, *rest]} if first == 1:
                    nodes.append(Node(package='k', executable=f'diff{first}_{len(rest)}'))
                case _:
                    nodes.append(Node(package='k', executable='other'))
            return nodes + [OpaqueFunction(function=setup)]
    """, "kilted")
    assert executables(acts) == ["j", "diff1_2"]
    (group,) = acts[2].actions
    # a literal pattern over LaunchConfiguration(...).perform(context) is a launch condition
    assert group.condition.kind == "if" and isinstance(group.condition.value[0], V.BoolOp)
    assert executables(group.actions) == ["s"]


def test_match_that_cannot_be_decided_keeps_every_case_under_unknown_conditions():
    acts = actions("""
        import os
        from launch_ros.actions import Node

        def generate_launch_description():
            nodes = []
            match os.environ['ROBOT']:
                case 'a':
                    nodes.append(Node(package='p', executable='a'))
                case _:
                    nodes.append(Node(package='p', executable='b'))
            return nodes
    """, "jazzy")
    first, rest = acts
    for group, exe, kind in ((first, "a", "if"), (rest, "b", "unless")):
        assert isinstance(group, L.Group) and group.condition.kind == kind
        assert isinstance(group.condition.value[0], V.Unknown) and "ROBOT" in group.condition.value[0].reason
        assert executables(group.actions) == [exe]


def test_cached_and_user_decorated_helpers_are_evaluated():
    acts = actions("""
        import functools
        from functools import cache, lru_cache
        from launch_ros.actions import Node

        def keep(f):
            return f

        @lru_cache(maxsize=None)
        def share(pkg):
            return '/opt/' + pkg

        @keep
        @cache
        def driver(name):
            return Node(package='base', executable=share('drv') + name)

        @functools.lru_cache
        def sensor(kind):
            return Node(package='s', executable=kind)

        def generate_launch_description():
            return [driver('x'), driver('x'), sensor('lidar')]
    """)
    assert executables(acts) == ["/opt/drvx", "/opt/drvx", "lidar"]
    assert acts[0].id == acts[1].id  # lru_cache gives back the very same Node object, as in Python


def test_unknown_decorator_makes_calls_unknown():
    acts = actions("""
        import some_pkg
        from launch_ros.actions import Node

        @some_pkg.retry(3)
        def driver():
            return Node(package='base', executable='drv')

        def generate_launch_description():
            return [driver()]
    """)
    (opaque,) = acts
    assert isinstance(opaque, L.OpaqueAction) and "some_pkg.retry" in opaque.reason


def test_simple_classes_and_dataclasses_hold_robot_data():
    acts = actions("""
        from dataclasses import dataclass, field
        from launch_ros.actions import Node

        @dataclass(frozen=True)
        class Robot:
            name: str
            ns: str = ''
            sensors: list = field(default_factory=list)

            def nodes(self):
                return [Node(package='s', executable=s, namespace=self.ns or self.name) for s in self.sensors]

        class Fleet:
            prefix = 'fleet'

            def __init__(self, names):
                self.robots = [Robot(n, sensors=['lidar']) for n in names]
                self.count = 0

            @property
            def size(self):
                return len(self.robots)

            def actions(self):
                out = []
                for r in self.robots:
                    self.count += 1
                    out += r.nodes()
                return out

        def generate_launch_description():
            fleet = Fleet(['a', 'b'])
            acts = fleet.actions()
            spare = Robot('spare')
            return acts + [Node(package='x', executable=f'{fleet.prefix}{fleet.size}{fleet.count}'),
                           Node(package='x', executable=f'{spare.name}{len(spare.sensors)}{spare.ns!r}')]
    """)
    assert executables(acts) == ["lidar", "lidar", "fleet22", "spare0''"]
    assert [lit(a.namespace) for a in acts[:2]] == ["a", "b"]


def test_classes_that_could_hide_behaviour_stay_unknown():
    acts = actions("""
        from dataclasses import dataclass
        from launch_ros.actions import Node
        from somewhere import Base

        class Name:
            def __str__(self):
                return 'n'
            def __eq__(self, other):
                return True

        class Derived(Base):
            def nodes(self):
                return [Node(package='d', executable='d')]

        @dataclass(frozen=True)
        class Frozen:
            name: str
            def __post_init__(self):
                self.name = 'changed'  # FrozenInstanceError in Python

        def generate_launch_description():
            return [Node(package='p', executable='e', name=Name()), Derived().nodes(),
                    Node(package='f', executable='f', name=Frozen('x').name)]
    """)
    node, derived, frozen = acts
    assert isinstance(node.name[0], V.Unknown) and '"__eq__"' in node.name[0].reason
    assert isinstance(derived, L.OpaqueAction) and "derives from a class" in derived.reason
    assert isinstance(frozen.name[0], V.Unknown)


def test_nonlocal_counter_and_failing_assert():
    acts = actions("""
        from launch_ros.actions import Node

        def make_counter():
            count = 0
            def next_name(prefix):
                nonlocal count
                count += 1
                return f'{prefix}{count}'
            return next_name

        def checked(x):
            assert x > 0, 'x must be positive'
            return Node(package='c', executable=f'ok{x}')

        def generate_launch_description():
            name = make_counter()
            return [Node(package='p', executable=name('n')), Node(package='p', executable=name('n')),
                    checked(1), checked(-1)]
    """)
    assert executables(acts[:3]) == ["n1", "n2", "ok1"]
    assert isinstance(acts[3], L.OpaqueAction) and "raises" in acts[3].reason


def test_test_markers_give_back_the_function():
    acts = actions("""
        import launch_testing.markers
        import pytest
        from launch_ros.actions import Node

        @pytest.mark.launch_test
        @pytest.mark.parametrize('x', [1])
        @launch_testing.markers.keep_alive
        def generate_launch_description():
            return [Node(package='p', executable='e')]
    """)
    assert executables(acts) == ["e"]


def test_subclass_calling_super_init():
    acts = actions("""
        from launch_ros.actions import Node

        class Base:
            def __init__(self, name):
                self.name = name
                self.params = {'rate': 10}

            def node(self):
                return Node(package='p', executable=self.name, parameters=[self.params])

        class Fast(Base):
            def __init__(self, name):
                super().__init__(name + '_fast')
                self.params['rate'] = 100

            def node(self):
                n = super().node()
                return n

        class Lone:
            def label(self):
                return super().label()

        def generate_launch_description():
            return [Fast('cam').node(), Base('slow').node(), Node(package='x', executable='x', name=Lone().label())]
    """)
    fast, _slow, lone = acts
    assert executables(acts[:2]) == ["cam_fast", "slow"]
    assert [(e.name, e.value.value) for e in fast.parameters[0].entries] == [("rate", 100)]
    assert isinstance(lone.name[0], V.Unknown) and "super()" in lone.name[0].reason
