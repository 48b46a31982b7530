"""Workspace packages are named when the index is built and read when first asked for: a check of
one launch file reads the packages it uses, and still reports its own package's manifest problems."""
from physai_lint.engine import CheckOptions, run_check
from physai_lint.workspace import build_package_index

MANIFEST = ('<?xml version="1.0"?>\n<package format="3">\n  <name>{name}</name>\n'
            '  <version>0.0.0</version>\n  <description>d</description>\n'
            '  <maintainer email="dev@example.com">m</maintainer>\n  <license>MIT</license>\n'
            '  <exec_depend>demo_nodes_cpp</exec_depend>\n</package>\n')
LAUNCH = ('<launch>\n  <node pkg="demo_nodes_cpp" exec="talker"/>\n'
          '  <include file="$(find-pkg-share {other})/launch/x.launch.xml"/>\n</launch>\n')


def _pkg(root, name, manifest=None, launch=None):
    d = root / "src" / name
    (d / "launch").mkdir(parents=True)
    (d / "package.xml").write_text(manifest if manifest is not None else MANIFEST.format(name=name))
    (d / "CMakeLists.txt").write_text(f"project({name})\ninstall(DIRECTORY launch DESTINATION share/${{PROJECT_NAME}})\n")
    (d / "launch" / "x.launch.xml").write_text(launch or "<launch/>\n")
    return d


def _ws(tmp_path):
    _pkg(tmp_path, "app", MANIFEST.format(name="app").replace("</package>", "  <exec_depend>used</exec_depend>\n</package>"),
         LAUNCH.format(other="used"))
    _pkg(tmp_path, "used")
    _pkg(tmp_path, "unused")
    # catkin_pkg rejects it (no version, description...), but its name is plain: named, not read
    _pkg(tmp_path, "broken", manifest="<package format='3'><name>broken</name></package>\n")
    return tmp_path


def test_packages_are_named_at_build_and_read_on_demand(tmp_path):
    idx = build_package_index(str(_ws(tmp_path)))
    assert sorted(idx.packages) == ["app", "broken", "unused", "used"]
    assert idx.problems == []
    assert idx.workspace_package("used").name == "used"
    idx.read_packages_holding([str(tmp_path / "src/broken/launch/x.launch.xml")])
    assert [p.endswith("src/broken/package.xml") for p, _, _ in idx.problems] == [True]
    assert not idx.workspace_package("broken").valid


def test_a_check_reports_its_own_packages_manifest_and_no_other(tmp_path):
    ws = _ws(tmp_path)

    def codes(path):
        report = run_check(CheckOptions(paths=[str(ws / path)], cache=False, jobs=1), cwd=str(ws))
        return [(f.code, f.span.file[len(str(ws)) + 1:]) for f in report.findings]

    assert codes("src/app/launch/x.launch.xml") == []
    assert codes("src/broken") == [("X001", "src/broken/package.xml")]
