"""Frozen, slotted model dataclasses pickle as tuples (model/pickling.py): parse results, cache
entries and findings from forked rule groups must come back equal, of the same class."""
from __future__ import annotations

import copy
import dataclasses
import pickle
from pathlib import Path

import pytest

from physai_lint.files import Job, run_job
from physai_lint.model import launch, pickling, span, values
from physai_lint.model.pickling import fast_pickle

EXAMPLES = Path(__file__).resolve().parent.parent / "examples"


def _walk(obj: object, seen: set[int]) -> list[object]:
    """Every dataclass instance reachable from ``obj``."""
    if id(obj) in seen:
        return []
    seen.add(id(obj))
    out: list[object] = []
    if dataclasses.is_dataclass(obj) and not isinstance(obj, type):
        out.append(obj)
        for f in dataclasses.fields(obj):
            out += _walk(getattr(obj, f.name), seen)
    elif isinstance(obj, dict):
        for k, v in obj.items():
            out += _walk(k, seen) + _walk(v, seen)
    elif isinstance(obj, (list, tuple, set, frozenset)):
        for v in obj:
            out += _walk(v, seen)
    return out


def test_parse_results_of_the_examples_round_trip() -> None:
    paths = sorted(p for p in EXAMPLES.rglob("*") if p.is_file() and p.name.endswith(
        (".launch.py", ".launch.xml", ".launch.yaml", ".yaml")))
    assert paths
    kinds: set[type] = set()
    for path in paths:
        text = path.read_text()
        kind = "launch" if ".launch." in path.name else "params"
        value, _ = run_job(Job(kind, str(path), text, "humble"), None)
        back = pickle.loads(pickle.dumps(value, protocol=pickle.HIGHEST_PROTOCOL))
        assert back == value
        for a, b in zip(_walk(value, set()), _walk(back, set())):
            assert type(a) is type(b)
            kinds.add(type(a))
    assert span.Span in kinds and launch.NodeAction in kinds  # the walk saw the model


def test_every_frozen_slotted_model_class_pickles_through_the_tuple_reduce() -> None:
    for module in (span, launch, values):
        for obj in vars(module).values():
            if isinstance(obj, type) and dataclasses.is_dataclass(obj) and \
                    obj.__module__ == module.__name__ and obj.__dataclass_params__.frozen:  # type: ignore[attr-defined]
                assert obj.__reduce__ is pickling._reduce, obj


def test_a_subclass_keeps_its_own_fields_and_copies_work() -> None:
    @fast_pickle
    @dataclasses.dataclass(frozen=True, slots=True)
    class Base:
        a: int
        b: str = "x"

    @dataclasses.dataclass(frozen=True, slots=True)
    class Child(Base):  # not given fast_pickle itself: inherits the reduce, not the base's shape
        c: tuple[int, ...] = ()

    globals()["Base"], globals()["Child"] = Base, Child  # picklable by qualified name
    Base.__qualname__, Child.__qualname__ = "Base", "Child"
    try:
        obj = Child(1, "y", (2, 3))
        back = pickle.loads(pickle.dumps(obj))
        assert back == obj and type(back) is Child
        assert copy.copy(obj) == obj and copy.deepcopy(obj) == obj
        s = span.Span("/a.py", 1, 2, 3, 4)
        assert pickle.loads(pickle.dumps([s, s]))[0] is not s
        both = pickle.loads(pickle.dumps([s, s]))
        assert both[0] is both[1]  # shared objects stay shared
    finally:
        del globals()["Base"], globals()["Child"]


# ---- fast_init ---------------------------------------------------------------------------------

def _twin_classes():
    from physai_lint.model.pickling import fast_init

    def make(fast):
        @dataclasses.dataclass(frozen=True, slots=True)
        class Point:
            file: str
            line: int
            col: int = 1
            tag: tuple = ()

        return fast_init(Point) if fast else Point

    return make(False), make(True)


def test_fast_init_builds_the_same_objects_with_the_same_signature():
    import inspect

    plain, fast = _twin_classes()
    assert fast.__init__.__code__.co_freevars  # replaced: the descriptors are bound in a closure
    same = [(p.name, p.kind, p.default) for p in inspect.signature(plain).parameters.values()]
    assert [(p.name, p.kind, p.default) for p in inspect.signature(fast).parameters.values()] == same
    for args, kwargs in [(("a", 1), {}), (("a", 1, 7), {}), (("a",), {"line": 2, "tag": (1,)}),
                         ((), {"file": "b", "line": 3, "col": 4})]:
        a, b = plain(*args, **kwargs), fast(*args, **kwargs)
        assert dataclasses.astuple(a) == dataclasses.astuple(b)
        assert repr(a).split("(", 1)[1] == repr(b).split("(", 1)[1]
    assert fast("a", 1) == fast("a", 1) and hash(fast("a", 1)) == hash(fast("a", 1))
    with pytest.raises(TypeError):
        fast("a")  # a required field is still required
    with pytest.raises(TypeError):
        fast("a", 1, nope=2)
    with pytest.raises(dataclasses.FrozenInstanceError):
        fast("a", 1).line = 2  # type: ignore[misc]


def test_fast_init_leaves_classes_it_cannot_rebuild_alone():
    from physai_lint.model.pickling import fast_init

    @dataclasses.dataclass(frozen=True, slots=True)
    class WithFactory:
        items: list = dataclasses.field(default_factory=list)

    @dataclasses.dataclass(slots=True)
    class Mutable:
        x: int

    for cls in (WithFactory, Mutable):
        before = cls.__init__
        assert fast_init(cls) is cls and cls.__init__ is before
    assert WithFactory().items == [] and WithFactory().items is not WithFactory().items


def test_the_hot_model_classes_have_the_fast_init_and_pickle_round_trip():
    import pickle

    from physai_lint.model.span import Span
    from physai_lint.params.model import FileParam

    assert Span.__init__.__code__.co_freevars and FileParam.__init__.__code__.co_freevars
    span = Span("/a.yaml", 1, 2, 3, 4)
    fp = FileParam("rate", 1.0, "double", "1.0", span, span)
    assert fp.quoted is False and fp.launch_value is None
    assert pickle.loads(pickle.dumps(fp)) == fp


def test_a_string_literal_with_its_position_pickles_and_copies() -> None:
    from physai_lint.frontends.python.runtime import SStr

    where = span.Span("a.launch.py", 3, 5, 3, 9)
    s = SStr("name", where)
    for back in (pickle.loads(pickle.dumps(s, protocol=pickle.HIGHEST_PROTOCOL)),
                 pickle.loads(pickle.dumps(s, protocol=0)), copy.deepcopy(s), copy.copy(s)):
        assert type(back) is SStr and back == "name" and back.span == where


def test_a_composable_node_s_extra_arguments_come_back_from_a_pickle(tmp_path: Path) -> None:
    # Their keys are the literals as written (SStr): the parse result used to fail to unpickle,
    # so a --jobs helper's result and a disk-cache entry of the file were both thrown away.
    path = tmp_path / "c.launch.py"
    path.write_text(
        "from launch import LaunchDescription\n"
        "from launch_ros.actions import ComposableNodeContainer\n"
        "from launch_ros.descriptions import ComposableNode\n"
        "def generate_launch_description():\n"
        "    return LaunchDescription([ComposableNodeContainer(\n"
        "        name='c', namespace='', package='rclcpp_components', executable='component_container',\n"
        "        composable_node_descriptions=[ComposableNode(package='p', plugin='p::N', name='n',\n"
        "            extra_arguments=[{'use_intra_process_comms': True}])])])\n")
    value, _ = run_job(Job("launch", str(path), path.read_text(), "humble"), None)
    back = pickle.loads(pickle.dumps(value, protocol=pickle.HIGHEST_PROTOCOL))
    assert back == value
