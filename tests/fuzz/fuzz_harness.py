"""Fuzz harness: structure-aware generators (hypothesis) for launch XML/YAML/Python and parameter
YAML, byte-level mutation of seed files, and a runner that feeds one input through every frontend
and the whole pipeline (build_project + run_check + every report formatter).

A *failure* is any exception escaping, or an X003 internal-error finding (the engine turns crashes
into X003; each one is a bug). Used by ``tests/fuzz/test_fuzz_quick.py`` (a seeded run in the
suite) and ``scripts/fuzz_long.py`` (the long run, see docs/fuzzing.md).
"""
from __future__ import annotations

import os
import shutil
import sys
import tempfile
from dataclasses import dataclass
from pathlib import Path

from hypothesis import strategies as st

REPO = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(REPO))

from physai_lint.frontends.tags import ACCEPTED  # noqa: E402

FORMATS = ("xml", "yaml", "python", "params")
LAUNCH_NAME = {"xml": "fuzz.launch.xml", "yaml": "fuzz.launch.yaml", "python": "fuzz.launch.py"}

# ---------------------------------------------------------------- values

NAMES = st.sampled_from(["a", "ns", "robot", "use_sim_time", "x_1", "talker", "/abs", "~priv", "", "a b",
                         "__ns", "名前", "rate", "config", "1bad", "a//b", "*", "**"])
SUBSTITUTIONS = st.sampled_from([
    "$(var a)", "$(var ns)", "$(find-pkg-share demo)", "$(find-pkg-share nope)", "$(env HOME)",
    "$(env X default)", "$(eval '1 + 1')", "$(eval \"'$(var a)' == 'true'\")", "$(command 'ls')",
    "$(dirname)", "$(filename)", "$(anon n)", "$(equals $(var a) b)", "$(not $(var a))",
    "$(find-pkg-prefix demo)", "$(exec-in-pkg e demo)", "$(var", "$(", "$(unknown x)", "$$(var a)",
    "$(var $(var a))", "$(find-pkg-share demo)/config/p.yaml", "$(find-pkg-share demo)/launch/other.launch.xml",
])
PLAIN = st.text(alphabet=st.characters(codec="utf-8", exclude_categories=("Cs",)), max_size=12)
VALUES = st.one_of(
    SUBSTITUTIONS, NAMES, PLAIN,
    st.sampled_from(["true", "false", "True", "1", "0", "1.5", "-3", "[1, 2]", "['a', 'b']", "0x10",
                     "1e3", "nan", ".inf", "~", "null", "0483", "yes", "on"]),
    st.lists(SUBSTITUTIONS | NAMES, min_size=2, max_size=3).map("".join),
)


@dataclass(frozen=True)
class Element:
    tag: str
    attrs: tuple[tuple[str, str], ...]
    children: tuple[Element, ...]


def _attrs(tag: str) -> st.SearchStrategy[tuple[tuple[str, str], ...]]:
    spec = ACCEPTED.get(tag)
    known = sorted(spec.attributes) if spec else []
    names = st.sampled_from(known + ["bogus", "name"]) if known else st.sampled_from(["name", "bogus"])
    return st.lists(st.tuples(names, VALUES), max_size=4, unique_by=lambda kv: kv[0]).map(tuple)


TAGS = sorted(ACCEPTED) + ["bogus"]


def _element(children: st.SearchStrategy[tuple[Element, ...]]) -> st.SearchStrategy[Element]:
    return st.sampled_from(TAGS).flatmap(lambda tag: st.builds(Element, st.just(tag), _attrs(tag), children))


LEAF = st.sampled_from(TAGS).flatmap(lambda tag: st.builds(Element, st.just(tag), _attrs(tag), st.just(())))
TREE = st.recursive(LEAF, lambda kids: _element(st.lists(kids, max_size=4).map(tuple)), max_leaves=14)
LAUNCH_TREE = st.lists(TREE, max_size=6).map(lambda kids: Element("launch", (), tuple(kids)))

# ---------------------------------------------------------------- launch XML / YAML


def _xml_escape(s: str) -> str:
    return s.replace("&", "&amp;").replace("<", "&lt;").replace('"', "&quot;")


def to_xml(e: Element, indent: str = "") -> str:
    attrs = "".join(f' {k}="{_xml_escape(v)}"' for k, v in e.attrs)
    if not e.children:
        return f"{indent}<{e.tag}{attrs}/>\n"
    inner = "".join(to_xml(c, indent + "  ") for c in e.children)
    return f"{indent}<{e.tag}{attrs}>\n{inner}{indent}</{e.tag}>\n"


SUB_ENTITIES = frozenset({"param", "remap", "arg", "env", "composable_node", "choice", "keep"})


def _yaml_data(e: Element, parent: str) -> dict[str, object]:
    """A tag as launch_yaml reads it: attributes, sub-entities as lists, actions under ``children``."""
    body: dict[str, object] = dict(e.attrs)
    for c in e.children:
        if c.tag in SUB_ENTITIES and parent != "launch":
            body.setdefault(c.tag, [])
            items = body[c.tag]
            if isinstance(items, list):
                items.append(_yaml_data(c, e.tag)[c.tag])
        else:
            kids = body.setdefault("children", [])
            if isinstance(kids, list):
                kids.append(_yaml_data(c, e.tag))
    return {e.tag: body}


def to_yaml(e: Element) -> str:
    import yaml

    doc = {"launch": [_yaml_data(c, "launch") for c in e.children]}
    return yaml.safe_dump(doc, allow_unicode=True, default_flow_style=None, sort_keys=False)


# ---------------------------------------------------------------- launch Python


def _py_str(v: str) -> str:
    return repr(v)


PY_VALUE = st.one_of(
    VALUES.map(_py_str),
    NAMES.map(lambda n: f"LaunchConfiguration({n!r})"),
    st.sampled_from([
        "LaunchConfiguration('a', default='x')", "PathJoinSubstitution([FindPackageShare('demo'), 'config', 'p.yaml'])",
        "os.path.join(get_package_share_directory('demo'), 'config', 'p.yaml')", "PythonExpression(['1 + ', '2'])",
        "PythonExpression([\"'\", LaunchConfiguration('a'), \"' == 'x'\"])", "Command(['xacro ', 'robot.urdf'])",
        "EnvironmentVariable('HOME')", "TextSubstitution(text='t')", "[LaunchConfiguration('ns'), '/x']",
        "42", "1.5", "True", "None", "[1, 2, 'a']", "{'k': 1}", "helper(3)", "CONST", "str(7) + 'x'",
        "f'{CONST}_x'", "'a' * 3", "undefined_name", "Node", "AnonName('n')", "ThisLaunchFileDir()",
    ]),
)
PY_KW = st.sampled_from(["package", "executable", "name", "namespace", "parameters", "remappings",
                         "arguments", "output", "condition", "ros_arguments", "exec_name", "bogus_kw",
                         "node_executable", "default_value", "description", "choices",
                         "launch_arguments", "composable_node_descriptions", "period", "actions"])
PY_ACTION_NAMES = st.sampled_from([
    "Node", "DeclareLaunchArgument", "GroupAction", "IncludeLaunchDescription", "SetLaunchConfiguration",
    "PushRosNamespace", "SetRemap", "SetParameter", "TimerAction", "ExecuteProcess", "LifecycleNode",
    "ComposableNodeContainer", "ComposableNode", "LoadComposableNodes", "OpaqueFunction", "LogInfo",
    "RegisterEventHandler", "SetEnvironmentVariable", "UnknownAction",
])
PY_CONDITION = st.sampled_from([
    "IfCondition(LaunchConfiguration('a'))", "UnlessCondition('true')", "IfCondition('maybe')",
    "LaunchConfigurationEquals('a', 'x')", "IfCondition(PythonExpression(['True']))",
])


def _py_call(depth: int) -> st.SearchStrategy[str]:
    kw_value = PY_VALUE if depth <= 0 else st.one_of(PY_VALUE, PY_CONDITION, st.lists(
        st.deferred(lambda: _py_call(depth - 1)), max_size=3).map(lambda xs: "[" + ", ".join(xs) + "]"),
        st.dictionaries(NAMES.map(repr), PY_VALUE, max_size=3).map(
            lambda d: "[{" + ", ".join(f"{k}: {v}" for k, v in d.items()) + "}]"))
    return st.tuples(PY_ACTION_NAMES, st.lists(PY_VALUE, max_size=2),
                     st.lists(st.tuples(PY_KW, kw_value), max_size=5, unique_by=lambda kv: kv[0])).map(
        lambda t: f"{t[0]}(" + ", ".join([*t[1], *(f"{k}={v}" for k, v in t[2])]) + ")")


PY_PRELUDE = """import os
from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import (DeclareLaunchArgument, ExecuteProcess, GroupAction, IncludeLaunchDescription,
                            LogInfo, OpaqueFunction, RegisterEventHandler, SetEnvironmentVariable,
                            SetLaunchConfiguration, TimerAction)
from launch.conditions import IfCondition, LaunchConfigurationEquals, UnlessCondition
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import (AnonName, Command, EnvironmentVariable, LaunchConfiguration,
                                  PathJoinSubstitution, PythonExpression, TextSubstitution,
                                  ThisLaunchFileDir)
from launch_ros.actions import (ComposableNodeContainer, LifecycleNode, LoadComposableNodes, Node,
                                PushRosNamespace, SetParameter, SetRemap)
from launch_ros.descriptions import ComposableNode
from launch_ros.substitutions import FindPackageShare

CONST = 'c'


def helper(n):
    return helper(n - 1) if n > 0 else [Node(package='demo', executable='e', name='h')]
"""

PY_STATEMENT = st.one_of(
    _py_call(2).map(lambda c: f"    actions.append({c})"),
    st.tuples(NAMES, PY_VALUE).map(lambda t: f"    v_{abs(hash(t[0])) % 7} = {t[1]}"),
    _py_call(1).map(lambda c: f"    for i in range(3):\n        actions.append({c})"),
    st.tuples(PY_CONDITION, _py_call(1)).map(lambda t: f"    if {t[0]}:\n        actions.append({t[1]})"),
    st.sampled_from([
        "    actions += helper(2)", "    actions.extend([x for x in helper(1)])",
        "    ld_args = {'a': 'x', 'ns': LaunchConfiguration('ns')}",
        "    actions.append(IncludeLaunchDescription(PythonLaunchDescriptionSource(os.path.join("
        "get_package_share_directory('demo'), 'launch', 'other.launch.py')), launch_arguments={'a': 'b'}.items()))",
        "    return LaunchDescription(actions)", "    raise RuntimeError('x')", "    pass",
        "    while True:\n        pass", "    v_1 = v_1 + 1", "    global CONST\n    CONST = CONST * 2",
    ]),
)
PY_LAUNCH = st.lists(PY_STATEMENT, max_size=8).map(
    lambda body: PY_PRELUDE + "\n\ndef generate_launch_description():\n    actions = []\n"
    + "\n".join(body) + "\n    return LaunchDescription(actions)\n")

# ---------------------------------------------------------------- parameter YAML

PARAM_SCALAR = st.one_of(
    st.integers(-2**70, 2**70), st.floats(allow_nan=True), st.booleans(), st.none(), PLAIN,
    st.sampled_from(["0483", "yes", "1e3", ".nan", "~", "$(var a)", "0x1F", "-.inf", "!!binary aGk="]),
)
PARAM_VALUE = st.recursive(PARAM_SCALAR | st.lists(PARAM_SCALAR, max_size=4),
                           lambda inner: st.dictionaries(NAMES, inner, max_size=3) | st.lists(inner, max_size=3),
                           max_leaves=10)
NODE_KEYS = st.sampled_from(["talker", "/talker", "/ns/talker", "/**", "**", "/*/talker", "/**/talker",
                             "ns/talker", "ros__parameters", "", "a.b"])
PARAM_DOC = st.dictionaries(
    NODE_KEYS, st.one_of(st.dictionaries(st.just("ros__parameters"), st.dictionaries(NAMES, PARAM_VALUE, max_size=5),
                                         min_size=1), PARAM_VALUE), max_size=4)


def to_param_yaml(doc: object) -> str:
    import yaml

    return yaml.safe_dump(doc, allow_unicode=True, default_flow_style=None, sort_keys=False)


# ---------------------------------------------------------------- seeds and byte mutation

SEEDS: dict[str, str] = {
    "xml": """<launch>
  <arg name="ns" default="robot1"/>
  <arg name="use_sim_time" default="false"/>
  <let name="cfg" value="$(find-pkg-share demo)/config/p.yaml"/>
  <include file="$(find-pkg-share demo)/launch/other.launch.xml">
    <arg name="a" value="$(var ns)"/>
  </include>
  <group scoped="true" if="$(var use_sim_time)">
    <push-ros-namespace namespace="$(var ns)"/>
    <node pkg="demo" exec="talker" name="talker" output="screen">
      <param name="rate" value="10"/>
      <param from="$(var cfg)"/>
      <remap from="chatter" to="/chatter"/>
    </node>
  </group>
  <node_container pkg="rclcpp_components" exec="component_container" name="c" namespace="">
    <composable_node pkg="demo" plugin="demo::Talker" name="t"/>
  </node_container>
</launch>
""",
    "yaml": """launch:
- arg: {name: ns, default: robot1}
- arg: {name: use_sim_time, default: "false"}
- include:
    file: $(find-pkg-share demo)/launch/other.launch.xml
    arg: [{name: a, value: $(var ns)}]
- group:
    scoped: "true"
    children:
    - push-ros-namespace: {namespace: $(var ns)}
    - node:
        pkg: demo
        exec: talker
        name: talker
        param: [{name: rate, value: 10}, {from: $(find-pkg-share demo)/config/p.yaml}]
        remap: [{from: chatter, to: /chatter}]
""",
    "python": PY_PRELUDE + """

def generate_launch_description():
    ns = LaunchConfiguration('ns')
    params = PathJoinSubstitution([FindPackageShare('demo'), 'config', 'p.yaml'])
    return LaunchDescription([
        DeclareLaunchArgument('ns', default_value='robot1', choices=['robot1', 'robot2']),
        DeclareLaunchArgument('use_sim_time', default_value='false'),
        IncludeLaunchDescription(PythonLaunchDescriptionSource(os.path.join(
            get_package_share_directory('demo'), 'launch', 'other.launch.py')), launch_arguments={'a': ns}.items()),
        GroupAction([
            PushRosNamespace(ns),
            Node(package='demo', executable='talker', name='talker', parameters=[params, {'rate': 10}],
                 remappings=[('chatter', '/chatter')], condition=IfCondition(LaunchConfiguration('use_sim_time'))),
        ]),
        TimerAction(period=2.0, actions=[Node(package='demo', executable='listener')]),
    ])
""",
    "params": """talker:
  ros__parameters:
    rate: 10
    frame_id: "base_link"
    gains: [1.0, 2.5, 3.0]
    names: [a, b]
    nested:
      deep:
        value: true
/**:
  ros__parameters:
    use_sim_time: false
""",
}

TOKENS = [b"<", b">", b"/>", b"</", b'"', b"'", b"$(", b")", b"$(var ", b"{", b"}", b"[", b"]", b":", b"- ",
          b"\n", b"  ", b"\t", b"&", b"&amp;", b"<!--", b"-->", b"<![CDATA[", b"]]>", b"*a", b"&a ", b"!!",
          b"(", b"def ", b"return ", b"lambda", b"\\", b"\x00", b"\xff", b"\xc3", b"\xe2\x80\xae", b"\r\n",
          b"ros__parameters", b"\xef\xbb\xbf", b"%", b"#", b"---\n", b"...\n", b"?", b"|", b">-"]


@st.composite
def mutated(draw: st.DrawFn, fmt: str) -> bytes:
    """A seed file with 1-8 byte-level edits: flips, inserts, deletes, duplications, token splices."""
    data = bytearray(SEEDS[fmt].encode("utf-8"))
    for _ in range(draw(st.integers(1, 8))):
        op = draw(st.sampled_from(["flip", "insert", "delete", "dup", "token", "truncate"]))
        pos = draw(st.integers(0, max(len(data) - 1, 0)))
        if op == "flip" and data:
            data[pos] ^= 1 << draw(st.integers(0, 7))
        elif op == "insert":
            data[pos:pos] = draw(st.binary(min_size=1, max_size=4))
        elif op == "delete":
            del data[pos:pos + draw(st.integers(1, 16))]
        elif op == "dup":
            end = pos + draw(st.integers(1, 64))
            data[end:end] = data[pos:end] * draw(st.integers(1, 4))
        elif op == "token":
            data[pos:pos] = draw(st.sampled_from(TOKENS))
        elif op == "truncate":
            del data[pos:]
    return bytes(data)


def structured(fmt: str) -> st.SearchStrategy[bytes]:
    text = {
        "xml": LAUNCH_TREE.map(lambda e: '<?xml version="1.0"?>\n' + to_xml(e)),
        "yaml": LAUNCH_TREE.map(to_yaml),
        "python": PY_LAUNCH,
        "params": PARAM_DOC.map(to_param_yaml),
    }[fmt]
    return text.map(lambda s: s.encode("utf-8"))


def inputs(fmt: str) -> st.SearchStrategy[bytes]:
    """Half structure-aware generation, half byte mutation of a seed."""
    return st.one_of(structured(fmt), mutated(fmt))


# ---------------------------------------------------------------- the runner

PACKAGE_XML = """<?xml version="1.0"?>
<package format="3">
  <name>demo</name><version>0.1.0</version><description>d</description>
  <maintainer email="m@example.com">m</maintainer><license>Apache-2.0</license>
  <buildtool_depend>ament_cmake</buildtool_depend>
  <export><build_type>ament_cmake</build_type></export>
</package>
"""
CMAKE = """cmake_minimum_required(VERSION 3.8)
project(demo)
find_package(ament_cmake REQUIRED)
add_executable(talker src/talker.cpp)
install(TARGETS talker DESTINATION lib/${PROJECT_NAME})
install(DIRECTORY launch config DESTINATION share/${PROJECT_NAME})
ament_package()
"""
OTHER_XML = '<launch><arg name="a" default="x"/><node pkg="demo" exec="talker" name="o" namespace="$(var a)"/></launch>\n'
OTHER_PY = PY_PRELUDE + "\n\ndef generate_launch_description():\n    return LaunchDescription([DeclareLaunchArgument('a')])\n"


class Failure(Exception):
    """An input that crashed physai-lint or produced an X003 internal-error finding."""


class Runner:
    """One scratch workspace, reused: each input overwrites the fuzzed file and runs everything."""

    def __init__(self, root: str | None = None) -> None:
        self.root = Path(root or tempfile.mkdtemp(prefix="physai-fuzz-"))
        pkg = self.root / "src" / "demo"
        for rel, text in {"package.xml": PACKAGE_XML, "CMakeLists.txt": CMAKE, "src/talker.cpp": "int main() {}\n",
                          "launch/other.launch.xml": OTHER_XML, "launch/other.launch.py": OTHER_PY,
                          "config/p.yaml": SEEDS["params"]}.items():
            (pkg / rel).parent.mkdir(parents=True, exist_ok=True)
            (pkg / rel).write_text(text, encoding="utf-8")
        os.environ.pop("AMENT_PREFIX_PATH", None)
        from physai_lint.catalog import load_catalog

        self.catalog = load_catalog()

    def close(self) -> None:
        shutil.rmtree(self.root, ignore_errors=True)

    def target(self, fmt: str) -> Path:
        if fmt == "params":
            return self.root / "src" / "demo" / "config" / "fuzz.yaml"
        return self.root / "src" / "demo" / "launch" / LAUNCH_NAME[fmt]

    def run(self, fmt: str, data: bytes, api: bool = True) -> None:
        """Raise ``Failure`` if the input crashes any stage; otherwise return quietly.

        ``api``: also run ``graph``/``plan``/``params`` on a launch input (three more pipeline builds)."""
        path = self.target(fmt)
        path.write_bytes(data)
        try:
            self._frontend(fmt, str(path), data)
            self._pipeline(fmt, path, api)
        except Failure:
            raise
        except Exception as exc:  # noqa: BLE001 - that is what we are looking for
            import traceback

            raise Failure(f"{type(exc).__name__}: {exc}\n{traceback.format_exc()}") from exc
        finally:
            path.unlink()

    def _frontend(self, fmt: str, path: str, data: bytes) -> None:
        text = data.decode("utf-8", errors="replace")
        if fmt == "xml":
            from physai_lint.frontends.xml_launch import parse_xml_launch

            parse_xml_launch(path, text)
        elif fmt == "yaml":
            from physai_lint.frontends.yaml_launch import parse_yaml_launch

            parse_yaml_launch(path, text)
        elif fmt == "python":
            from physai_lint.frontends.python import parse_python_launch

            try:
                parse_python_launch(path, text, lambda p: None)
            except RecursionError:
                pass  # the engine's file loader reports this as X001 (files.parse_launch_text)
        else:
            from physai_lint.params.loader import load_param_file

            load_param_file(path, text, "humble")

    def _pipeline(self, fmt: str, path: Path, api_too: bool) -> None:
        from physai_lint import api
        from physai_lint.engine import CheckOptions, run_check
        from physai_lint.errors import UnloadableLaunch, UsageError
        from physai_lint.report import FORMATS, render

        opts = CheckOptions(paths=[str(self.root)], workspace=str(self.root), cache=False, jobs=1)
        report = run_check(opts, cwd=str(self.root))
        crashes = [f for f in report.findings if f.code == "X003"]
        if crashes:
            raise Failure("X003: " + "; ".join(f.message for f in crashes))
        for out in FORMATS:
            render(out, report, self.catalog, color=False, show_source=True, statistics=False,
                   quiet=False, fail_on="error")
        if fmt != "params" and api_too:
            for call in (lambda: api.graph(opts, str(path), "json"), lambda: api.plan(opts, str(path), "json"),
                         lambda: api.params(opts, str(path), None, "json")):
                try:
                    call()
                except (UsageError, UnloadableLaunch):
                    pass  # one-line errors for the user (exit 2, or 1 with the parse error), not a crash
