"""Hostile and broken input through the whole pipeline: each case ends as a finding (or a one-line
exit-2 error), in bounded time and memory, never a traceback.

The frontends' own tests cover the parser level (billion laughs, external entities, alias bombs,
5,000 nested parentheses, deep parameter nesting, discovery through symlink loops); these run the
real CLI end to end, in a child process under a 2 GB address-space limit.
"""
from __future__ import annotations

import json
import os
import resource
import subprocess
import sys
from pathlib import Path

import pytest
from hardening_helpers import assert_no_traceback, cli_env, package, run_cli, write

LOL = '<?xml version="1.0"?>\n<!DOCTYPE launch [<!ENTITY l0 "lol">' + "".join(
    f'<!ENTITY l{i} "{("&l" + str(i - 1) + ";") * 10}">' for i in range(1, 10)) + ']>\n<launch><arg name="a" default="&l9;"/></launch>\n'
YAML_BOMB = "launch:\n- let:\n    name: x\n    value: &a0 [lol, lol, lol, lol, lol, lol, lol, lol, lol]\n" + "".join(
    f"- let: {{name: x{i}, value: &a{i} [{', '.join(['*a' + str(i - 1)] * 9)}]}}\n" for i in range(1, 10))
PARAM_BOMB = "n:\n  ros__parameters:\n    a0: &a0 [1, 1, 1, 1, 1, 1, 1, 1, 1]\n" + "".join(
    f"    a{i}: &a{i} [{', '.join(['*a' + str(i - 1)] * 9)}]\n" for i in range(1, 10))
HEAD = "from launch import LaunchDescription\nfrom launch_ros.actions import Node\n"
GLD = "\ndef generate_launch_description():\n    return LaunchDescription([Node(package='demo', executable='e')])\n"


def _chain(fmt: str, n: int) -> dict[str, str | bytes]:
    """``n`` launch files, each including the next, by relative path."""
    out: dict[str, str | bytes] = {}
    for i in range(n):
        nxt = f"c{i + 1}.launch.{fmt}"
        if fmt == "xml":
            body = f'<launch><include file="$(dirname)/{nxt}"/></launch>\n' if i < n - 1 else "<launch/>\n"
        else:
            body = f"launch:\n- include: {{file: $(dirname)/{nxt}}}\n" if i < n - 1 else "launch: []\n"
        out[f"launch/c{i}.launch.{fmt}"] = body
    return out


def _py_chain(n: int) -> dict[str, str | bytes]:
    out: dict[str, str | bytes] = {}
    for i in range(n):
        inc = ("from launch.actions import IncludeLaunchDescription\n"
               "from launch.launch_description_sources import PythonLaunchDescriptionSource\nimport os\n")
        act = f"IncludeLaunchDescription(PythonLaunchDescriptionSource(os.path.join(os.path.dirname(__file__), 'c{i + 1}.launch.py')))" \
            if i < n - 1 else "Node(package='demo', executable='e')"
        out[f"launch/c{i}.launch.py"] = HEAD + inc + f"\ndef generate_launch_description():\n    return LaunchDescription([{act}])\n"
    return out


# name -> (files of package "demo", the file expected to carry the finding or None, codes allowed there)
CASES: dict[str, tuple[dict[str, str | bytes], str | None, set[str]]] = {
    "xml_billion_laughs": ({"launch/a.launch.xml": LOL}, "launch/a.launch.xml", {"X001"}),
    "xml_external_dtd": ({"launch/a.launch.xml": '<!DOCTYPE launch SYSTEM "http://127.0.0.1:9/x.dtd">\n<launch/>\n'},
                         "launch/a.launch.xml", {"X001"}),
    "xml_deep_nesting": ({"launch/a.launch.xml": "<launch>" + "<group>" * 20000 + "</group>" * 20000 + "</launch>"},
                         "launch/a.launch.xml", {"X001"}),
    "yaml_alias_bomb": ({"launch/a.launch.yaml": YAML_BOMB}, "launch/a.launch.yaml", {"X001"}),
    "yaml_deep_nesting": ({"launch/a.launch.yaml": "launch:\n- let: {name: a, value: " + "[" * 20000 + "]" * 20000 + "}\n"},
                          "launch/a.launch.yaml", {"X001"}),
    "param_alias_bomb": ({"config/p.yaml": PARAM_BOMB, "launch/a.launch.xml":
                          '<launch><node pkg="demo" exec="e" name="n"><param from="$(dirname)/../config/p.yaml"/></node></launch>'},
                         "config/p.yaml", {"P104", "X001"}),
    "param_deep_nesting": ({"config/p.yaml": "n:\n  ros__parameters:\n    " + "{a: " * 20000 + "1" + "}" * 20000 + "\n"},
                           "config/p.yaml", {"P104", "X001"}),
    "python_5000_brackets": ({"launch/a.launch.py": "x = " + "[" * 5000 + "]" * 5000 + "\n" + GLD}, "launch/a.launch.py", {"X001"}),
    "python_5000_calls": ({"launch/a.launch.py": "x = " + "f(" * 5000 + ")" * 5000 + "\n" + GLD}, "launch/a.launch.py", {"X001"}),
    "python_100k_operands": ({"launch/a.launch.py": "x = " + "+".join(["'a'"] * 100_000) + "\n" + GLD},
                             "launch/a.launch.py", {"X001"}),
    "python_huge_literals": ({"launch/a.launch.py": HEAD + "x = 10**10**10\ny = 'a' * 10**12\nz = [0] * 10**11\n"
                              "w = 'x' * 5_000_000\n" + GLD}, None, set()),
    "python_recursive_helpers": ({"launch/a.launch.py": HEAD + "def f(n):\n    return f(n + 1) + [Node(package='demo', executable='e')]\n"
                                  "def g(n):\n    return h(n)\ndef h(n):\n    return g(n)\n"
                                  "def generate_launch_description():\n    return LaunchDescription(f(0) + g(1))\n"}, None, set()),
    "python_endless_loops": ({"launch/a.launch.py": HEAD + "def generate_launch_description():\n    i = 0\n    while True:\n"
                              "        i += 1\n    for k in range(10**12):\n        pass\n    return LaunchDescription([])\n"}, None, set()),
    "include_cycle": ({"launch/a.launch.xml": '<launch><include file="$(dirname)/b.launch.yaml"/></launch>',
                       "launch/b.launch.yaml": "launch:\n- include: {file: $(dirname)/a.launch.xml}\n"},
                      "launch/a.launch.xml", {"L107"}),
    "include_self": ({"launch/a.launch.xml": '<launch><include file="$(dirname)/a.launch.xml"/></launch>'},
                     "launch/a.launch.xml", {"L107"}),
    "include_chain_3000_xml": (_chain("xml", 3000), None, set()),
    "include_chain_2000_yaml": (_chain("yaml", 2000), None, set()),
    "include_chain_1000_python": (_py_chain(1000), None, set()),
    "binary_launch_file": ({"launch/a.launch.py": b"\x7fELF\x02\x01\x01\x00" + bytes(range(256)) * 8}, "launch/a.launch.py", {"X002"}),
    "undecodable_launch_file": ({"launch/a.launch.xml": b"<launch>\n<arg name='\xff\xfe'/>\n</launch>\n"}, "launch/a.launch.xml", {"X002"}),
    "latin1_param_file": ({"config/p.yaml": "n:\n  ros__parameters:\n    city: 'Zürich'\n".encode("latin-1"),
                           "launch/a.launch.xml": '<launch><node pkg="demo" exec="e" name="n"><param from="$(dirname)/../config/p.yaml"/></node></launch>'},
                          "config/p.yaml", {"X002"}),
    "utf16_launch_file": ({"launch/a.launch.yaml": "launch: []\n".encode("utf-16")}, "launch/a.launch.yaml", {"X002"}),
}

CHILD_LIMIT = 2 << 30


def _limit() -> None:
    resource.setrlimit(resource.RLIMIT_AS, (CHILD_LIMIT, CHILD_LIMIT))


def _check_json(ws: Path, tmp: Path, *paths: str) -> tuple[subprocess.CompletedProcess[str], list[dict[str, object]]]:
    proc = subprocess.run([sys.executable, "-m", "physai_lint", "check", *(paths or ["."]), "--format", "json"],
                          cwd=ws, env=cli_env(tmp), capture_output=True, text=True, timeout=300, preexec_fn=_limit)
    assert_no_traceback(proc)
    findings = json.loads(proc.stdout)["findings"] if proc.returncode in (0, 1) else []
    return proc, findings


@pytest.mark.parametrize("case", sorted(CASES))
def test_hostile_input_is_a_finding_within_bounds(case: str, tmp_path: Path) -> None:
    files, where, codes = CASES[case]
    ws = write(tmp_path / "ws", package("demo", files))
    proc, findings = _check_json(ws, tmp_path)
    assert proc.returncode in (0, 1), proc.stderr
    assert not [f for f in findings if f["code"] == "X003"], findings
    if where is not None:
        at = {f["code"] for f in findings if str(f["file"]).endswith(where)}
        assert at & codes, (case, findings)


def test_unreadable_file_and_directory(tmp_path: Path) -> None:
    if os.geteuid() == 0:
        pytest.skip("running as root: chmod 000 does not make files unreadable (see the monkeypatched test)")
    ws = write(tmp_path / "ws", package("demo", {"launch/a.launch.xml": "<launch/>\n", "launch/b.launch.xml": "<launch/>\n",
                                                   "secret/c.launch.xml": "<launch/>\n"}))
    (ws / "src/demo/launch/a.launch.xml").chmod(0)
    (ws / "src/demo/secret").chmod(0)
    try:
        proc, findings = _check_json(ws, tmp_path)
    finally:
        (ws / "src/demo/launch/a.launch.xml").chmod(0o644)
        (ws / "src/demo/secret").chmod(0o755)
    assert proc.returncode == 1
    assert ("X002", "src/demo/launch/a.launch.xml") in {(f["code"], f["file"]) for f in findings}


def test_unreadable_file_even_as_root(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """The same path without chmod: the engine's reader gets PermissionError (root can read anything)."""
    import builtins

    from physai_lint.engine import CheckOptions, run_check

    ws = write(tmp_path / "ws", package("demo", {"launch/a.launch.xml": "<launch/>\n",
                                                   "launch/b.launch.xml": '<launch><arg name="x"/></launch>\n'}))
    real_open = builtins.open
    bad = str(ws / "src/demo/launch/a.launch.xml")

    def guarded(file, *args, **kwargs):  # type: ignore[no-untyped-def]
        if str(file) == bad:
            raise PermissionError(13, "Permission denied", str(file))
        return real_open(file, *args, **kwargs)

    monkeypatch.setattr(builtins, "open", guarded)
    report = run_check(CheckOptions(paths=["."], cache=False), cwd=str(ws))
    got = {(f.code, os.path.relpath(f.span.file, ws)) for f in report.findings}
    assert ("X002", "src/demo/launch/a.launch.xml") in got
    assert ("L102", "src/demo/launch/b.launch.xml") in got  # the other file still reports


def test_symlink_loops_and_dangling_links(tmp_path: Path) -> None:
    ws = write(tmp_path / "ws", package("demo", {"launch/b.launch.xml": '<launch><arg name="x"/></launch>\n'}))
    launch = ws / "src/demo/launch"
    os.symlink(str(ws / "src"), str(launch / "loop"))  # a directory loop
    os.symlink("self.launch.xml", str(launch / "self.launch.xml"))  # a file link to itself (ELOOP)
    os.symlink("missing.launch.py", str(launch / "dangling.launch.py"))
    os.symlink("b.launch.xml", str(launch / "alias.launch.xml"))
    proc, findings = _check_json(ws, tmp_path)
    assert proc.returncode == 0  # L102 is a warning
    assert any(f["code"] == "L102" and str(f["file"]).endswith("b.launch.xml") for f in findings), findings
    proc2, _ = _check_json(ws, tmp_path, "src/demo/launch/self.launch.xml")
    assert proc2.returncode in (0, 1, 2)  # a finding, or one error line naming the path


@pytest.mark.parametrize("fmt", ["text", "json", "sarif", "github", "junit"])
def test_paths_with_spaces_and_non_ascii(tmp_path: Path, fmt: str) -> None:
    ws = write(tmp_path / "my ws" / "ロボット ü", package("demo", {
        "launch/bring up ü.launch.xml": '<launch><arg name="ünused"/></launch>\n',
        "config/ça va.yaml": "n:\n  ros__parameters:\n    a: [1, 'x']\n"}))
    proc = run_cli(["check", ".", "--format", fmt], ws, tmp_path)
    assert_no_traceback(proc)
    assert proc.returncode == 1, proc.stderr  # P106 mixed-type array is an error
    if fmt == "sarif":
        uris = [r["locations"][0]["physicalLocation"]["artifactLocation"]["uri"]
                for r in json.loads(proc.stdout)["runs"][0]["results"]]
        assert uris and all(" " not in u for u in uris), uris  # URIs are percent-encoded
    elif fmt in ("text", "json", "github"):
        assert "bring up ü.launch.xml" in proc.stdout or "bring%20up" in proc.stdout


@pytest.mark.parametrize("fmt", [
    "xml",
    "python",
    pytest.param("params", marks=pytest.mark.xfail(strict=True, reason=(
        "no finding at all for a 50 MB parameter file: the loader's X001 'too many YAML nodes' "
        "and the X006 duplicate key never reach the report"))),
])
def test_50_megabyte_files(tmp_path: Path, fmt: str) -> None:
    """A 50 MB launch or parameter file: bounded time and memory, and a clear outcome.

    A 50 MB launch.py needed more than 6 GB (its AST): Python launch files over 2 MB are X002."""
    if fmt == "python":
        line = "    Node(package='demo', executable='e', name='n{i}'),\n"
        body = HEAD + "def generate_launch_description():\n  return LaunchDescription([\n" + "".join(
            line.format(i=i) for i in range(50_000_000 // 60)) + "  ])\n"
        rel = "launch/big.launch.py"
    elif fmt == "xml":
        line = '<node pkg="demo" exec="e" name="n{i}"><param name="p" value="{i}"/></node>\n'
        body = "<launch>\n" + "".join(line.format(i=i) for i in range(50_000_000 // 72)) + "</launch>\n"
        rel = "launch/big.launch.xml"
    else:
        body = "n:\n  ros__parameters:\n" + "".join(f"    p{i}: {i}\n" for i in range(50_000_000 // 18))
        body += "    p0: duplicate\n"
        rel = "config/big.yaml"
    ws = write(tmp_path / "ws", package("demo", {rel: body}))
    assert 45_000_000 < (ws / "src/demo" / rel).stat().st_size < 64 * 1024 * 1024
    proc, findings = _check_json(ws, tmp_path)
    assert proc.returncode in (0, 1)
    assert not [f for f in findings if f["code"] == "X003"]
    if fmt in ("python", "xml"):
        assert [f["code"] for f in findings if str(f["file"]).endswith(f"big.launch.{'py' if fmt == 'python' else 'xml'}")] == ["X002"]
    if fmt == "params":
        assert any(str(f["file"]).endswith("big.yaml") for f in findings), findings[:5]


@pytest.mark.parametrize("manifest", [
    "<package format='3'><name>demo</name",
    LOL.replace("launch", "package").replace('<arg name="a" default="&l9;"/>', "<name>demo&l9;</name>"),
])
def test_broken_package_xml_is_reported(tmp_path: Path, manifest: str) -> None:
    files = package("demo", {"launch/a.launch.xml": "<launch/>\n"})
    files["src/demo/package.xml"] = manifest
    ws = write(tmp_path / "ws", files)
    proc, findings = _check_json(ws, tmp_path)
    assert any(str(f["file"]).endswith("package.xml") for f in findings), findings
