"""The example workspaces are well-formed colcon workspaces, and buggy_ws differs from fixed_ws
only by the mistakes documented in examples/README.md.

These tests read the files; they never execute a launch file (Python launch files are only
given to ``ast.parse``).
"""
from __future__ import annotations

import ast
import re
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest
import yaml

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
WORKSPACES = ("buggy_ws", "fixed_ws")
LAUNCH_SUFFIXES = ("launch.py", "launch.xml", "launch.yaml")
ROW = re.compile(r"^\| (\d+) \| `([^`:]+):(\d+)` \| `([^`]+)` \| ([A-Z]\d{3}) [a-z-]+ \|")


def _files(ws: str) -> set[str]:
    root = EXAMPLES / ws
    return {p.relative_to(root).as_posix() for p in root.rglob("*") if p.is_file()}


def _packages(ws: str) -> list[Path]:
    return sorted(p.parent for p in (EXAMPLES / ws / "src").glob("*/package.xml"))


def _planted() -> list[tuple[int, str, int, str, str]]:
    text = (EXAMPLES / "README.md").read_text(encoding="utf-8")
    rows = []
    for line in text.splitlines():
        m = ROW.match(line)
        if m:
            rows.append((int(m[1]), m[2], int(m[3]), m[4], m[5]))
    return rows


@pytest.mark.parametrize("ws", WORKSPACES)
def test_every_package_has_a_format_3_manifest_with_a_build_type(ws: str) -> None:
    packages = _packages(ws)
    assert len(packages) == 6
    for pkg in packages:
        root = ET.parse(pkg / "package.xml").getroot()
        assert root.tag == "package" and root.get("format") == "3", pkg
        assert root.findtext("name") == pkg.name
        build_types = [e.text for e in root.iter("build_type")]
        assert build_types in (["ament_cmake"], ["ament_python"]), (pkg, build_types)
        if build_types == ["ament_python"]:
            assert (pkg / "setup.py").is_file() and (pkg / "setup.cfg").is_file(), pkg
            assert (pkg / "resource" / pkg.name).is_file(), pkg
            ast.parse((pkg / "setup.py").read_text(encoding="utf-8"))
        else:
            cmake = (pkg / "CMakeLists.txt").read_text(encoding="utf-8")
            assert f"project({pkg.name})" in cmake and "ament_package()" in cmake, pkg


@pytest.mark.parametrize("ws", WORKSPACES)
def test_launch_and_parameter_files_are_syntactically_valid(ws: str) -> None:
    launch_files = [p for p in (EXAMPLES / ws / "src").rglob("*") if p.name.endswith(LAUNCH_SUFFIXES)]
    assert {p.name.rsplit(".", 1)[-1] for p in launch_files} == {"py", "xml", "yaml"}
    for path in launch_files:
        text = path.read_text(encoding="utf-8")
        if path.suffix == ".py":
            tree = ast.parse(text, filename=str(path))
            names = {n.name for n in tree.body if isinstance(n, ast.FunctionDef)}
            assert "generate_launch_description" in names, path
        elif path.suffix == ".xml":
            assert ET.fromstring(text).tag == "launch", path
        else:
            assert set(yaml.safe_load(text)) == {"launch"}, path
    for path in (EXAMPLES / ws / "src").rglob("config/*.yaml"):
        data = yaml.safe_load(path.read_text(encoding="utf-8"))
        assert all("ros__parameters" in section for section in data.values()), path


@pytest.mark.parametrize("ws", WORKSPACES)
def test_interfaces_file_names_package_slash_executable(ws: str) -> None:
    data = yaml.safe_load((EXAMPLES / ws / "interfaces.yaml").read_text(encoding="utf-8"))
    packages = {p.name for p in _packages(ws)}
    for key, decl in data.items():
        assert re.fullmatch(r"[a-z0-9_]+/[A-Za-z0-9_:]+", key), key
        assert set(decl) <= {"publishers", "subscribers", "services", "parameters"}, key
        if key.split("/")[0].startswith("atlas_"):
            assert key.split("/")[0] in packages, key


def test_both_workspaces_hold_the_same_files() -> None:
    assert _files("buggy_ws") == _files("fixed_ws")


def test_planted_mistakes_are_documented_and_are_the_only_differences() -> None:
    rows = _planted()
    assert [r[0] for r in rows] == list(range(1, len(rows) + 1)) and len(rows) >= 10
    documented = set()
    for _, rel, line, token, _code in rows:
        buggy = (EXAMPLES / "buggy_ws" / "src" / rel).read_text(encoding="utf-8").splitlines()
        fixed = (EXAMPLES / "fixed_ws" / "src" / rel).read_text(encoding="utf-8").splitlines()
        assert token in buggy[line - 1], (rel, line, token)
        assert buggy != fixed, f"{rel} is documented as buggy but equals its fixed twin"
        documented.add(f"src/{rel}")
    differing = {
        rel for rel in _files("buggy_ws")
        if (EXAMPLES / "buggy_ws" / rel).read_bytes() != (EXAMPLES / "fixed_ws" / rel).read_bytes()
    }
    assert differing == documented


def test_the_linter_reports_every_planted_mistake_and_nothing_on_the_fixed_workspace() -> None:
    """Each planted mistake's rule is reported in its package (at the planted line or a related
    one, as the README allows), and the fixed workspace has no finding at all. (A wrong import in
    robot.launch.py once made the XML include opaque and hid mistake 5: the linter's own
    examples must stay runnable launch files.)"""
    from physai_lint.engine import CheckOptions, run_check

    def found(ws: str) -> list[tuple[str, str]]:
        root = EXAMPLES / ws
        opts = CheckOptions(paths=[str(root / "src")], workspace=str(root), cache=False,
                            interfaces=[str(root / "interfaces.yaml")])
        return [(f.code, Path(f.span.file).relative_to(root / "src").parts[0])
                for f in run_check(opts, cwd=str(root)).findings]

    buggy = found("buggy_ws")
    for n, rel, _line, _token, code in _planted():
        assert (code, rel.split("/")[0]) in buggy, f"planted mistake {n} ({code} in {rel}) not reported"
    assert found("fixed_ws") == []
