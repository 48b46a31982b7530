"""N101 when one line launches a node twice because its file is included twice: the message
names the includes, which are what differ, not the node's own line twice."""
from __future__ import annotations

NODES = """<launch>
  <node pkg="demo_nodes_cpp" exec="talker" name="talker"/>
</launch>
"""
MAIN = """<launch>
  <include file="$(find-pkg-share demo)/launch/nodes.launch.xml"/>
  <group>
    <include file="$(find-pkg-share demo)/launch/nodes.launch.xml"/>
  </group>
</launch>
"""


def test_a_file_included_twice_names_both_includes(tmp_path, demo_package):
    from physai_lint.engine import CheckOptions, run_check

    pkg = demo_package({"launch/nodes.launch.xml": NODES, "launch/main.launch.xml": MAIN})
    report = run_check(CheckOptions(paths=[str(pkg / "launch/main.launch.xml")], workspace=str(tmp_path),
                                    cache=False))
    (f,) = [f for f in report.findings if f.code == "N101"]
    assert f.message.startswith('node "/talker" is launched twice: ')
    assert "nodes.launch.xml is included 2 times in the same namespace" in f.message
    assert [(r.span.file.rsplit("/", 1)[-1], r.span.line, r.message) for r in f.related] == [
        ("main.launch.xml", 2, "included here"), ("main.launch.xml", 4, "included here")]
