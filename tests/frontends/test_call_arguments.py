"""L012: calls of the launch file's own functions with arguments their signature refuses."""
from __future__ import annotations

import ast

import pytest

from physai_lint.frontends.python.calls import refused_arguments

SIGNATURES = [
    "def f(a, b, c=1): pass",
    "def f(a, /, b, *, k, m=2): pass",
    "def f(*args, k): pass",
    "def f(a, **kw): pass",
    "def f(a, /, **kw): pass",
    "def f(): pass",
    "def f(a=1): pass",
]
CALLS = [((), ()), ((1,), ()), ((1, 2), ()), ((1, 2, 3, 4), ()), ((1,), ("b",)), ((1,), ("a",)),
         ((), ("a", "b")), ((1, 2), ("k",)), ((), ("k",)), ((1,), ("zz",)), ((), ("a",))]


@pytest.mark.parametrize("source", SIGNATURES)
def test_the_message_is_the_type_error_python_raises(source: str) -> None:
    """Against CPython itself, on functions this test defines."""
    node = ast.parse(source).body[0]
    assert isinstance(node, ast.FunctionDef)
    namespace: dict[str, object] = {}
    exec(compile(ast.Module([node], []), "<test>", "exec"), namespace)  # noqa: S102 - the test's own code
    f = namespace["f"]
    kw_defaults = {k.arg for k, d in zip(node.args.kwonlyargs, node.args.kw_defaults) if d is not None}
    for given, keywords in CALLS:
        try:
            f(*given, **{k: 0 for k in keywords})  # type: ignore[operator]
            expected = None
        except TypeError as exc:
            expected = str(exc)
        got = refused_arguments(node, len(node.args.defaults), kw_defaults, len(given), list(keywords))
        assert got == expected, (source, given, keywords)


FRAGMENT = """
from launch import LaunchDescription
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import ComposableNodeContainer
from launch_ros.descriptions import ComposableNode
from vendor_launch.fragments import LaunchFragment


class CameraFragment(LaunchFragment):

    @staticmethod
    def components(specs):
        return [ComposableNode(package='demo', plugin='demo::Camera', name='camera',
                               parameters=[{'rate': LaunchConfiguration('rate')}])]


def generate_launch_description():
    return LaunchDescription([
        ComposableNodeContainer(package='rclcpp_components', executable='component_container',
                                name='cameras', namespace='',
                                composable_node_descriptions=CameraFragment.components(CALL_ARGS)),
    ])
"""


def test_a_method_of_a_class_with_an_imported_base_is_checked(demo_findings) -> None:
    """Python finds what the class body defines before looking in its bases: the imported base
    does not hide the staticmethod's signature."""
    files = {"launch/cameras.launch.py": FRAGMENT.replace("CALL_ARGS", "")}
    (finding,) = demo_findings(files, "launch/cameras.launch.py", "L012")
    assert finding == (21, ("this call raises TypeError when it runs: components() missing 1 required "
                            "positional argument: 'specs'"))


def test_nothing_the_refused_call_would_build_is_reported(demo_findings) -> None:
    """Python raises at the call: the configuration read inside never is (no L101 on it)."""
    files = {"launch/cameras.launch.py": FRAGMENT.replace("CALL_ARGS", "")}
    assert demo_findings(files, "launch/cameras.launch.py", "L101") == []
    files = {"launch/cameras.launch.py": FRAGMENT.replace("CALL_ARGS", "{}")}
    assert demo_findings(files, "launch/cameras.launch.py", "L012") == []
    assert [line for line, _ in demo_findings(files, "launch/cameras.launch.py", "L101")] == [14]


def test_a_class_with_an_imported_base_may_read_what_it_is_given(demo_findings) -> None:
    """Its base's __init__ runs: an argument handed to it counts as read (no L102)."""
    launch = (
        "from launch import LaunchDescription, Substitution\n"
        "from launch.actions import DeclareLaunchArgument\n"
        "from launch.substitutions import LaunchConfiguration\n\n\n"
        "class ConfigPath(Substitution):\n"
        "    def perform(self, context):\n"
        "        return 'x'\n\n\n"
        "def generate_launch_description():\n"
        "    path = ConfigPath(LaunchConfiguration('joy_config'))\n"
        "    return LaunchDescription([DeclareLaunchArgument('joy_config', default_value='ps3')])\n")
    assert demo_findings({"launch/joy.launch.py": launch}, "launch/joy.launch.py", "L102") == []
