"""Which checked launch files are roots (resolved and reported on their own) and which are analysed
through an includer; and that guessing includers from file names saves resolutions without
changing the roots."""
from __future__ import annotations

import networkx as nx
from hypothesis import given, settings
from hypothesis import strategies as st

from physai_lint.engine import CheckOptions, build_project
from physai_lint.resolve import instantiate
from physai_lint.resolve.roots import included_names, nodes_on_cycles


def _node(name: str) -> str:
    return f'  <node pkg="demo" exec="talker" name="{name}"/>\n'


def _inc(target: str, pkg: str = "demo") -> str:
    return f'  <include file="$(find-pkg-share {pkg})/launch/{target}"/>\n'


def _launch(*body: str) -> str:
    return "<launch>\n" + "".join(body) + "</launch>\n"


def _project(tmp_path, demo_package, monkeypatch, files):
    resolved: list[str] = []
    real = instantiate.resolve_launch

    def counting(entry, *args, **kwargs):
        resolved.append(entry.rsplit("/", 1)[-1])
        return real(entry, *args, **kwargs)

    monkeypatch.setattr(instantiate, "resolve_launch", counting)
    pkg = demo_package({f"launch/{k}": val for k, val in files.items()})
    project = build_project(CheckOptions(paths=[str(pkg / "launch")], workspace=str(tmp_path), cache=False,
                                         jobs=1))
    roots = [r.entry.rsplit("/", 1)[-1] for r in project.launches]
    return roots, sorted(resolved), project


def test_an_included_includer_is_not_resolved_on_its_own(tmp_path, demo_package, monkeypatch):
    files = {
        "top.launch.xml": _launch(_inc("mid.launch.xml"), _node("top")),
        "mid.launch.xml": _launch(_inc("leaf.launch.xml"), _node("mid")),
        "leaf.launch.xml": _launch(_node("leaf")),
    }
    roots, resolved, project = _project(tmp_path, demo_package, monkeypatch, files)
    assert roots == ["top.launch.xml"]
    assert resolved == ["top.launch.xml"]  # mid: named by top; leaf: has no include
    assert sorted(n.name for n in project.launches[0].nodes) == ["leaf", "mid", "top"]


def test_a_wrong_guess_is_resolved_afterwards(tmp_path, demo_package, monkeypatch):
    # top names a file called mid.launch.xml, but of another package: the guess does not come
    # true, so the demo package's mid.launch.xml is resolved and is a root, as without guessing.
    files = {
        "top.launch.xml": _launch(_inc("mid.launch.xml", pkg="elsewhere"), _node("top")),
        "mid.launch.xml": _launch(_inc("leaf.launch.xml"), _node("mid")),
        "leaf.launch.xml": _launch(_node("leaf")),
    }
    roots, resolved, _ = _project(tmp_path, demo_package, monkeypatch, files)
    assert roots == ["mid.launch.xml", "top.launch.xml"]
    assert resolved == ["mid.launch.xml", "top.launch.xml"]


def test_include_cycles_make_every_file_a_root(tmp_path, demo_package, monkeypatch):
    files = {
        "a.launch.xml": _launch(_inc("b.launch.xml"), _node("a")),
        "b.launch.xml": _launch(_inc("a.launch.xml"), _node("b")),
    }
    roots, resolved, _ = _project(tmp_path, demo_package, monkeypatch, files)
    assert roots == ["a.launch.xml", "b.launch.xml"]
    assert resolved == ["a.launch.xml", "b.launch.xml"]


def test_a_root_outside_the_cycle_is_still_the_only_root(tmp_path, demo_package, monkeypatch):
    files = {
        "top.launch.xml": _launch(_inc("a.launch.xml"), _node("top")),
        "a.launch.xml": _launch(_inc("b.launch.xml"), _node("a")),
        "b.launch.xml": _launch(_inc("a.launch.xml"), _node("b")),
    }
    roots, resolved, _ = _project(tmp_path, demo_package, monkeypatch, files)
    assert roots == ["top.launch.xml"]
    # a and b are on a cycle of guesses: resolved, as without guessing
    assert resolved == ["a.launch.xml", "b.launch.xml", "top.launch.xml"]


def test_a_leaf_reached_through_an_unnamed_include_is_still_no_root(tmp_path, demo_package, monkeypatch):
    # Leaves that no include names by file name are resolved along with the first wave of
    # includers; top reaches hidden.launch.xml through an argument, so hidden is resolved early
    # (no include names it) but stays out of the roots, as without resolving it early.
    files = {
        "top.launch.xml": _launch('  <arg name="which" default="hidden.launch.xml"/>\n',
                                  '  <include file="$(find-pkg-share demo)/launch/$(var which)"/>\n',
                                  _node("top")),
        "hidden.launch.xml": _launch(_node("hidden")),
        "alone.launch.xml": _launch(_node("alone")),
        "mid.launch.xml": _launch(_inc("named.launch.xml"), _node("mid")),
        "named.launch.xml": _launch(_node("named")),
    }
    roots, resolved, project = _project(tmp_path, demo_package, monkeypatch, files)
    assert roots == ["alone.launch.xml", "mid.launch.xml", "top.launch.xml"]
    assert resolved == ["alone.launch.xml", "hidden.launch.xml", "mid.launch.xml", "top.launch.xml"]
    top = next(r for r in project.launches if r.entry.endswith("/top.launch.xml"))
    assert sorted(n.name for n in top.nodes) == ["hidden", "top"]


def test_included_names_reads_the_literal_end_of_python_and_xml_paths(tmp_path, demo_package):
    from physai_lint.files import FileStore

    py = '''
import os
from launch import LaunchDescription
from launch.actions import IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import PathJoinSubstitution, LaunchConfiguration
from launch_ros.substitutions import FindPackageShare

def generate_launch_description():
    d = FindPackageShare("demo")
    return LaunchDescription([
        IncludeLaunchDescription(PythonLaunchDescriptionSource(
            PathJoinSubstitution([d, "launch", "a_launch.py"]))),
        IncludeLaunchDescription(PythonLaunchDescriptionSource(
            os.path.join("/opt", "b_launch.py"))),
        IncludeLaunchDescription(PythonLaunchDescriptionSource(
            [LaunchConfiguration("robot"), "_launch.py"])),
        IncludeLaunchDescription(PythonLaunchDescriptionSource(LaunchConfiguration("file"))),
    ])
'''
    pkg = demo_package({"launch/p.launch.py": py, "launch/x.launch.xml": _launch(_inc("c.launch.xml"))})
    store = FileStore()
    assert included_names(store.launch(str(pkg / "launch/p.launch.py"))) == {
        "a_launch.py", "b_launch.py", "_launch.py"}
    assert included_names(store.launch(str(pkg / "launch/x.launch.xml"))) == {"c.launch.xml"}


@settings(max_examples=200, deadline=None)
@given(st.dictionaries(st.integers(0, 7), st.sets(st.integers(0, 7), max_size=4), max_size=8))
def test_on_cycle_matches_networkx(edges):
    graph = {str(k): {str(x) for x in vs} for k, vs in edges.items()}
    for vs in list(graph.values()):
        for x in vs:
            graph.setdefault(x, set())
    g = nx.DiGraph()
    g.add_nodes_from(graph)
    g.add_edges_from((a, b) for a, bs in graph.items() for b in bs)
    expected = {n for comp in nx.strongly_connected_components(g) for n in comp
                if len(comp) > 1 or g.has_edge(n, n)}
    assert nodes_on_cycles(graph) == expected


def test_an_include_naming_its_package_guesses_only_that_packages_file(tmp_path, monkeypatch):
    # Three packages, each with a bringup.launch.xml; p2's includes p1's, p1's includes p0's. By
    # file name alone every bringup names every other (a cycle of guesses: all three resolved);
    # with the package the include names, only p2's is resolved. The roots are the same either way.
    from tests.conftest import DEMO_CMAKE, DEMO_PACKAGE_XML

    for i in range(3):
        pkg = tmp_path / "src" / f"p{i}"
        (pkg / "launch").mkdir(parents=True)
        (pkg / "package.xml").write_text(DEMO_PACKAGE_XML.replace("<name>demo</name>", f"<name>p{i}</name>"))
        (pkg / "CMakeLists.txt").write_text(DEMO_CMAKE.replace("project(demo)", f"project(p{i})"))
        body = _inc("bringup.launch.xml", pkg=f"p{i - 1}") if i else ""
        (pkg / "launch" / "bringup.launch.xml").write_text(_launch(body, _node(f"n{i}")))
    resolved: list[str] = []
    real = instantiate.resolve_launch

    def counting(entry, *args, **kwargs):
        resolved.append(entry.split("/src/", 1)[1])
        return real(entry, *args, **kwargs)

    monkeypatch.setattr(instantiate, "resolve_launch", counting)
    project = build_project(CheckOptions(paths=[str(tmp_path / "src")], workspace=str(tmp_path), cache=False,
                                         jobs=1))
    assert [r.entry.split("/src/", 1)[1] for r in project.launches] == ["p2/launch/bringup.launch.xml"]
    assert resolved == ["p2/launch/bringup.launch.xml"]
    assert sorted(n.name for n in project.launches[0].nodes) == ["n0", "n1", "n2"]
