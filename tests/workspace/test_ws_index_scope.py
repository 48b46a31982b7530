"""A scoped index (a run that resolves no launch file) reads only the manifests it needs, and
reports exactly the problems the full index reports for the packages holding the scope paths."""
import os

import pytest

from physai_lint.workspace import build_package_index

MANIFEST = ('<?xml version="1.0"?>\n<package format="3">\n  <name>{name}</name>\n'
            '  <version>0.0.0</version>\n  <description>d</description>\n'
            '  <maintainer email="dev@example.com">m</maintainer>\n  <license>MIT</license>\n</package>\n')


def _pkg(root, rel, name=None, text=None):
    d = root / "src" / rel
    (d / "config").mkdir(parents=True)
    (d / "config" / "p.yaml").write_text("n:\n  ros__parameters:\n    a: 1\n")
    (d / "package.xml").write_text(text if text is not None else MANIFEST.format(name=name or rel.split("/")[-1]))
    return d


@pytest.fixture
def dup_ws(ws):
    _pkg(ws, "z_dup/first", "twin")
    _pkg(ws, "z_dup/second", "twin")
    _pkg(ws, "z_dup/third", text=MANIFEST.format(name="twin<!-- c -->").replace("twin<!-- c -->", "tw<!-- c -->in"))
    _pkg(ws, "z_dup/dirname_only", text="<package><name>no close")  # catkin fails, regex fails:
    _pkg(ws, "z_dup/other/dirname_only", text="<package>")  # both are named after their directory
    return ws


def _held(problems, paths):
    return sorted(p for p in problems if any(q.startswith(os.path.dirname(p[0]) + "/") for q in paths))


def test_scoped_problems_equal_the_full_ones_for_every_package(dup_ws):
    full = build_package_index(str(dup_ws))
    assert any("duplicate package name" in m for _, m, _ in full.problems)
    pkg_dirs = sorted({os.path.dirname(p) for p, _, _ in full.problems} | {p.path for p in full.packages.values()})
    for d in pkg_dirs:
        paths = [d + "/config/p.yaml"]
        scoped = build_package_index(str(dup_ws), scope=paths)
        assert scoped.packages == {}
        assert _held(scoped.problems, paths) == _held(full.problems, paths), d


def test_scope_reads_only_what_may_collide(dup_ws, monkeypatch):
    from physai_lint.workspace import index

    read = []
    real = index._read_manifest
    monkeypatch.setattr(index, "_read_manifest", lambda idx, d: read.append(d) or real(idx, d))
    scoped = build_package_index(str(dup_ws), scope=[str(dup_ws / "src/z_dup/second/config/p.yaml")])
    assert [os.path.relpath(d, dup_ws) for d in read] == [
        "src/z_dup/first", "src/z_dup/second", "src/z_dup/third"]
    assert [m for _, m, _ in scoped.problems] == [
        f'duplicate package name "twin" (also in {dup_ws}/src/z_dup/first); colcon refuses to build this workspace',
        f'duplicate package name "twin" (also in {dup_ws}/src/z_dup/first); colcon refuses to build this workspace']
