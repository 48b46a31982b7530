"""The disk cache for C++ interface extraction and package reading (manifests, CMakeLists.txt).

A warm run must print what a cold run prints; an edited source, manifest or subdirectory
CMakeLists.txt must be a miss that gives the new result; a corrupt or wrong-shaped entry is a
miss; ``--no-cache`` writes nothing. The fixture workspace is written here:

- ``talker`` (ament_cmake): its executable is declared in ``nodes/CMakeLists.txt`` (an
  ``add_subdirectory``), and its source publishes "2chatter", an invalid name (N104, found only
  through C++ extraction);
- ``broken``: a package.xml without a license (X001, found only through catkin_pkg).
"""
from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[1]

PACKAGE_XML = """<?xml version="1.0"?>
<package format="3">
  <name>{name}</name>
  <version>0.1.0</version>
  <description>A test package.</description>
  <maintainer email="dev@example.com">dev</maintainer>
  {license}
  <buildtool_depend>ament_cmake</buildtool_depend>
  <depend>rclcpp</depend>
  <export><build_type>ament_cmake</build_type></export>
</package>
"""
TALKER_CMAKE = """cmake_minimum_required(VERSION 3.8)
project(talker)
find_package(ament_cmake REQUIRED)
add_subdirectory(nodes)
install(DIRECTORY launch DESTINATION share/${PROJECT_NAME})
ament_package()
"""
NODES_CMAKE = """add_executable({exe} talker.cpp)
install(TARGETS {exe} DESTINATION lib/${{PROJECT_NAME}})
"""
TALKER_CPP = """#include "rclcpp/rclcpp.hpp"
#include "std_msgs/msg/string.hpp"

class Talker : public rclcpp::Node
{{
public:
  Talker() : Node("talker")
  {{
    rate_ = declare_parameter("rate", 10.0);
    pub_ = create_publisher<std_msgs::msg::String>("{topic}", 10);
  }}

private:
  double rate_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
}};
"""
HELPER_CPP = "// nothing a node declares here\nint twice(int x) { return 2 * x; }\n"
TALKER_LAUNCH = """<launch>
  <node pkg="talker" exec="talker" name="talker">
    <param name="rate" value="5.0"/>
  </node>
</launch>
"""


def write_workspace(root: Path) -> Path:
    files = {
        "src/talker/package.xml": PACKAGE_XML.format(name="talker", license="<license>MIT</license>"),
        "src/talker/CMakeLists.txt": TALKER_CMAKE,
        "src/talker/nodes/CMakeLists.txt": NODES_CMAKE.format(exe="talker"),
        "src/talker/nodes/talker.cpp": TALKER_CPP.format(topic="2chatter"),
        "src/talker/nodes/helper.cpp": HELPER_CPP,
        "src/talker/launch/talker.launch.xml": TALKER_LAUNCH,
        "src/broken/package.xml": PACKAGE_XML.format(name="broken", license=""),
        "src/broken/CMakeLists.txt": "project(broken)\nament_package()\n",
        "src/broken/launch/empty.launch.xml": "<launch/>\n",
    }
    for rel, text in files.items():
        (root / rel).parent.mkdir(parents=True, exist_ok=True)
        (root / rel).write_text(text)
    return root


@pytest.fixture
def ws(tmp_path: Path) -> Path:
    return write_workspace(tmp_path / "ws")


def lint(ws: Path, cache_dir: Path, *extra: str) -> str:
    env = {k: v for k, v in os.environ.items() if k not in ("NO_COLOR", "FORCE_COLOR")}
    env.update({"PYTHONPATH": str(REPO), "PHYSAI_LINT_CACHE_DIR": str(cache_dir)})
    proc = subprocess.run([sys.executable, "-m", "physai_lint", "check", "src", "--workspace", ".",
                           "--format", "json", "-j", "1", *extra], cwd=ws, env=env, check=False,
                          capture_output=True, text=True, timeout=300)
    assert proc.returncode in (0, 1), proc.stderr
    assert "Traceback" not in proc.stderr
    return proc.stdout


def entries(cache: Path) -> dict[Path, int]:
    return {p: p.stat().st_mtime_ns for p in cache.rglob("*.pickle")} if cache.exists() else {}


def test_warm_run_prints_the_cold_report_and_no_cache_writes_nothing(ws: Path, tmp_path: Path) -> None:
    unused = tmp_path / "unused"
    reference = lint(ws, unused, "--no-cache")
    assert not unused.exists()
    assert '"N104"' in reference and '"X001"' in reference  # extraction and catkin_pkg both count
    cache = tmp_path / "cache"
    assert lint(ws, cache) == reference
    written = entries(cache)
    # 2 launch files + 2 manifests + 2 CMakeLists.txt + talker.cpp (helper.cpp declares nothing)
    assert len(written) == 7
    assert lint(ws, cache) == reference
    assert entries(cache) == written  # a warm run only reads


@pytest.mark.parametrize("edit", ["source", "manifest", "subdirectory cmake"])
def test_an_edited_file_is_a_miss_and_gives_the_new_result(edit: str, ws: Path, tmp_path: Path) -> None:
    cache = tmp_path / "cache"
    before = lint(ws, cache)
    if edit == "source":
        (ws / "src/talker/nodes/talker.cpp").write_text(TALKER_CPP.format(topic="3chatter"))
    elif edit == "manifest":
        (ws / "src/broken/package.xml").write_text(
            PACKAGE_XML.format(name="broken", license="<license>MIT</license>"))
    else:  # only add_subdirectory's file changes: the top-level CMakeLists.txt entry must not hit
        (ws / "src/talker/nodes/CMakeLists.txt").write_text(NODES_CMAKE.format(exe="talker_node"))
    after = lint(ws, cache)
    assert after == lint(ws, tmp_path / "unused", "--no-cache")
    assert after != before
    if edit == "source":
        assert "3chatter" in after and "2chatter" not in after
    elif edit == "manifest":
        assert '"X001"' not in after
    else:
        assert '"U102"' in after and '"N104"' not in after


def test_corrupt_entries_are_misses(ws: Path, tmp_path: Path) -> None:
    cache = tmp_path / "cache"
    reference = lint(ws, cache)
    for i, entry in enumerate(sorted(entries(cache))):
        entry.write_bytes([b"", b"\x80\x05garbage", b"not a pickle at all"][i % 3])
    assert lint(ws, cache) == reference
    assert lint(ws, cache) == reference  # the rewritten entries read back


# ---- in process: what is stored, and what a hit of the wrong shape does -----------------------


def test_cpp_extraction_is_stored_per_file_and_read_back(ws: Path, tmp_path: Path) -> None:
    from physai_lint.cache import ParseCache, dumps
    from physai_lint.interfaces.extract_cpp import CACHE_KIND, _file_interface, extract_cpp

    files = [(str(p), p.read_text()) for p in sorted((ws / "src/talker/nodes").glob("*.cpp"))]
    plain = extract_cpp(files)
    cold = ParseCache(str(tmp_path / "cache"))
    assert extract_cpp(files, cold) == plain
    assert cold.writes == 1  # talker.cpp; helper.cpp has no call word, so no entry
    _file_interface.cache_clear()  # else the in-memory memo answers
    warm = ParseCache(str(tmp_path / "cache"))
    assert extract_cpp(files, warm) == plain
    assert (warm.hits, warm.writes) == (1, 0)
    # a readable entry of the wrong shape is a miss, recomputed and rewritten
    path, text = files[1]
    assert path.endswith("talker.cpp")
    warm.put_bytes(warm.key(CACHE_KIND, path, text), dumps(("not", "an interface")) or b"")
    _file_interface.cache_clear()
    again = ParseCache(str(tmp_path / "cache"))
    assert extract_cpp(files, again) == plain and again.writes == 1


def _snapshot(index: object) -> object:
    pkgs = index.packages  # type: ignore[attr-defined]
    return ({n: pkgs[n] for n in sorted(pkgs)}, sorted(index.problems),  # type: ignore[attr-defined]
            sorted(index.notes))  # type: ignore[attr-defined]


def test_package_reading_is_stored_and_read_back(ws: Path, tmp_path: Path) -> None:
    from physai_lint.cache import ParseCache, dumps
    from physai_lint.workspace import build_package_index

    plain = _snapshot(build_package_index(str(ws)))
    cold = ParseCache(str(tmp_path / "cache"))
    assert _snapshot(build_package_index(str(ws), cache=cold)) == plain
    assert cold.writes == 4  # two manifests, two CMakeLists.txt
    warm = ParseCache(str(tmp_path / "cache"))
    assert _snapshot(build_package_index(str(ws), cache=warm)) == plain
    assert (warm.hits, warm.writes) == (4, 0)
    # the broken manifest's problem comes from the cache too
    assert any("license" in message for _, message, _ in plain[1])  # type: ignore[index]
    # readable entries of the wrong shape are misses
    for entry in (tmp_path / "cache").rglob("*.pickle"):
        entry.write_bytes(dumps({"wrong": "shape"}) or b"")
    odd = ParseCache(str(tmp_path / "cache"))
    assert _snapshot(build_package_index(str(ws), cache=odd)) == plain
    assert odd.writes == 4


def test_a_scoped_index_reads_manifests_through_the_cache(ws: Path, tmp_path: Path) -> None:
    from physai_lint.cache import ParseCache
    from physai_lint.workspace import build_package_index

    scope = [str(ws / "src/broken/launch/empty.launch.xml")]
    plain = build_package_index(str(ws), scope=scope).problems
    assert plain
    cold = ParseCache(str(tmp_path / "cache"))
    assert build_package_index(str(ws), scope=scope, cache=cold).problems == plain
    warm = ParseCache(str(tmp_path / "cache"))
    assert build_package_index(str(ws), scope=scope, cache=warm).problems == plain
    assert warm.writes == 0 and warm.hits == cold.writes > 0
