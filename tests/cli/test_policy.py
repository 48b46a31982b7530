"""Suppressions, baselines, selection and configuration as pure functions."""
from __future__ import annotations

import json
from pathlib import Path

import pytest
from cli_helpers import FIXTURE_RULES

from physai_lint import baseline, suppress
from physai_lint.catalog import load_catalog
from physai_lint.config import load_config
from physai_lint.errors import ConfigError
from physai_lint.model.findings import Finding
from physai_lint.model.span import Span
from physai_lint.selection import Selector, path_matches

CAT = load_catalog(FIXTURE_RULES)
PY = "/ws/a.launch.py"


def finding(code: str, line: int, file: str = PY, key: str = "k") -> Finding:
    name = CAT[code].name if code in CAT else "x"
    return Finding(code, name, "error", Span(file, line, 1, line, 2), "msg", None, (), key)


def run(text: str, findings: list[Finding], fmt: str = "python", path: str = PY, **kw):  # type: ignore[no-untyped-def]
    d = suppress.parse_directives(path, text, fmt)  # type: ignore[arg-type]
    return suppress.apply(findings, {path: d}, CAT, **kw)


def test_same_line_and_line_above() -> None:
    text = "a = 1  # physai-lint: ignore[N101]\n# physai-lint: ignore[parameter-file-missing]\n\nb = 2\n"
    kept, new = run(text, [finding("N101", 1), finding("P101", 4), finding("P101", 1)])
    assert [(f.code, f.span.line) for f in kept] == [("P101", 1)] and new == []


def test_unused_and_invalid_are_reported_at_the_comment() -> None:
    text = "a = 1  # physai-lint: ignore[N101, X004]\nb = 2  # physai-lint: ignore\nc = 3  # physai-lint: ignore[N1O1]\n"
    kept, new = run(text, [finding("N101", 1)])
    assert kept == []
    assert [(d.code, d.span.line, d.span.col) for d in new] == [("X004", 1, 8), ("X005", 2, 8), ("X005", 3, 8)]
    assert '"X004" (unused-suppression)' in new[0].message
    assert new[2].help == 'did you mean "N101"?'


def test_unused_not_reported_for_rules_that_did_not_run() -> None:
    _, new = run("a = 1  # physai-lint: ignore[N101]\n", [], enabled=lambda code: code != "N101")
    assert new == []


def test_ignore_file() -> None:
    text = "# physai-lint: ignore-file[N101]\na = 1\n"
    kept, new = run(text, [finding("N101", 2), finding("N101", 9), finding("P101", 2)])
    assert [f.code for f in kept] == ["P101"] and new == []
    _, new = run(text, [])
    assert [d.code for d in new] == ["X004"] and "in this file" in new[0].message


def test_noqa_shares_the_namespace_quietly() -> None:
    text = "a = 1  # noqa: N101, E501\nassert x  # noqa: S101\n"
    kept, new = run(text, [finding("N101", 1)])
    assert kept == [] and new == []


def test_xml_comment_forms() -> None:
    text = '<launch>\n  <!-- physai-lint: ignore[N101] -->\n  <node name="a"/>\n  <node name="b"/> <!-- physai-lint: ignore P101 -->\n</launch>\n'
    kept, new = run(text, [finding("N101", 3, "/ws/a.launch.xml"), finding("P101", 4, "/ws/a.launch.xml")], "xml", "/ws/a.launch.xml")
    assert kept == [] and new == []


def test_yaml_comment_forms() -> None:
    text = "talker:\n  ros__parameters:\n    # physai-lint: ignore P101\n    rate: 1\n    x: 2  # physai-lint: ignore[N101]\n"
    kept, new = run(text, [finding("P101", 4, "/ws/p.yaml"), finding("N101", 5, "/ws/p.yaml")], "yaml", "/ws/p.yaml")
    assert kept == [] and new == []


def test_baseline_round_trip_survives_moved_lines(tmp_path: Path) -> None:
    file = str(tmp_path / "a.launch.py")
    old = [finding("N101", 3, file, "/talker"), finding("N101", 7, file, "/talker"), finding("P101", 9, file, "p.yaml")]
    path = tmp_path / "baseline.json"
    assert baseline.write(str(path), old, str(tmp_path)) == 3
    doc = json.loads(path.read_text())
    assert doc["format"] == "physai-lint-baseline" and {e["file"] for e in doc["entries"]} == {"a.launch.py"}
    moved = [finding("N101", 13, file, "/talker"), finding("N101", 17, file, "/talker"), finding("N101", 20, file, "/talker"),
             finding("P101", 30, file, "p.yaml"), finding("P101", 31, file, "other.yaml")]
    kept, hidden = baseline.load(str(path)).filter(moved, str(tmp_path))
    assert hidden == 3 and [(f.code, f.span.line) for f in kept] == [("N101", 20), ("P101", 31)]


def test_baseline_errors(tmp_path: Path) -> None:
    with pytest.raises(ConfigError, match="does not exist"):
        baseline.load(str(tmp_path / "nope.json"))
    (tmp_path / "b.json").write_text("[]")
    with pytest.raises(ConfigError, match="not a physai-lint baseline"):
        baseline.load(str(tmp_path / "b.json"))


def test_selection_specificity_and_names() -> None:
    s = Selector(["N", "P101"], ["duplicate-node-name"], ["X"], {}, CAT)
    assert not s.enabled("N101") and s.enabled("P101") and s.enabled("X004")
    s = Selector(None, ["N"], [], {}, CAT)
    assert not s.enabled("N101") and s.enabled("P101")
    s = Selector(["N101"], ["N"], [], {}, CAT)  # the more specific selector wins
    assert s.enabled("N101")
    assert not Selector(["ALL"], ["ALL"], [], {}, CAT).enabled("N101")


def test_per_file_ignores() -> None:
    s = Selector(None, [], [], {"**/test/*.py": ["N"], "legacy.launch.xml": ["P101"]}, CAT)
    assert not s.enabled_for("N101", "src/a/test/x.py") and s.enabled_for("N101", "src/a/launch/x.py")
    assert not s.enabled_for("P101", "src/a/launch/legacy.launch.xml")
    assert path_matches(["build", "**/vendor/*"], "build/x/a.launch.py") and not path_matches(["build"], "src/a.py")


def test_unknown_selector_names_it() -> None:
    with pytest.raises(ConfigError, match='unknown rule code or name "Z1"'):
        Selector(["Z1"], [], [], {}, CAT)
    with pytest.raises(ConfigError, match="per-file-ignores"):
        Selector(None, [], [], {"*.py": ["nope"]}, CAT)


def test_config_walks_up_and_prefers_standalone(tmp_path: Path) -> None:
    (tmp_path / "pyproject.toml").write_text('[tool.physai-lint]\nselect = ["P"]\nbaseline = "b.json"\n')
    deep = tmp_path / "src" / "pkg"
    deep.mkdir(parents=True)
    cfg = load_config(str(deep), None)
    assert cfg.select == ["P"] and cfg.baseline == str(tmp_path / "b.json") and cfg.path == str(tmp_path / "pyproject.toml")
    (tmp_path / "src" / "pyproject.toml").write_text("[tool.black]\n")  # no table: skipped
    (tmp_path / "physai-lint.toml").write_text('select = ["N"]\n')
    assert load_config(str(deep), None).select == ["N"]
    assert load_config(str(deep), "../../pyproject.toml").select == ["P"]
    with pytest.raises(ConfigError, match='config file "x.toml" does not exist'):
        load_config(str(deep), "x.toml")


def test_config_defaults_without_file(tmp_path: Path) -> None:
    cfg = load_config(str(tmp_path), None)
    assert cfg.path is None and cfg.select is None and cfg.ignore == []


def test_invalid_config_messages(tmp_path: Path) -> None:
    (tmp_path / "physai-lint.toml").write_text('[severity]\nN101 = "fatal"\n')
    with pytest.raises(ConfigError, match=r'physai-lint.toml: "severity.N101": .fatal. is not one of'):
        load_config(str(tmp_path), None)
    (tmp_path / "physai-lint.toml").write_text("select = \"N\"\n")
    with pytest.raises(ConfigError, match=r'"select": expected array, got str'):
        load_config(str(tmp_path), None)
