"""Reporter output: golden snapshots plus schema and GitHub-rule validation."""
from __future__ import annotations

import hashlib
import json
import xml.etree.ElementTree as ET
from pathlib import Path

import jsonschema
import pytest
from report_fixtures import A, SOURCES, FakeReport, catalog, check_snapshot, sample_report

from physai_lint.report import github, json_report, junit, sarif, text

SCHEMAS = Path(__file__).resolve().parents[2] / "schemas"


def _text(**kw):  # type: ignore[no-untyped-def]
    return text.render(sample_report(), catalog(), read_source=SOURCES.get, **kw)


def test_text_snapshot() -> None:
    out = _text()
    check_snapshot("report.txt", out)
    assert "\x1b[" not in out
    assert 'src/demo/launch/bringup.launch.py:4:26: N101 [duplicate-node-name] duplicate node name "/talker"' in out
    assert "  |                          ^^^^^^^^" in out
    assert out.rstrip().endswith("Found 1 error, 1 warning (1 note) in 3 files. (2 findings hidden by the baseline)")


def test_text_tab_alignment_and_colour() -> None:
    out = _text()
    lines = out.splitlines()
    source = next(line for line in lines if line.startswith("3 | ") and "rate" in line)
    carets = lines[lines.index(source) + 1]
    assert carets.index("^^^^") == source.index("rate")  # tabs expand alike in both lines
    coloured = _text(color=True)
    assert "\x1b[" in coloured and "[duplicate-node-name]" in coloured


def test_text_statistics_and_clean() -> None:
    check_snapshot("statistics.txt", _text(statistics=True))
    clean = FakeReport([], ["/ws/a.launch.py"])
    assert text.render(clean, catalog()) == "All checks passed! (1 file)\n"
    assert text.render(clean, catalog(), quiet=True) == ""


def test_text_without_source() -> None:
    out = text.render(sample_report(), catalog(), read_source=lambda p: None)
    assert " | " not in out and "  = help: give one of the nodes another name" in out
    assert "  = note: src/demo/launch/bringup.launch.py:3:26: first defined here" in out


def test_json_snapshot_and_contract() -> None:
    out = json_report.render(sample_report(), catalog())
    check_snapshot("report.json", out)
    doc = json.loads(out)
    schema = json.loads((SCHEMAS / "contracts" / "report.schema.json").read_text())
    jsonschema.Draft202012Validator(schema).validate(doc)
    assert [f["code"] for f in doc["findings"]] == ["P101", "X004", "N101"]  # config/ sorts before launch/
    assert doc["findings"][2]["related"][0]["line"] == 3 and doc["findings"][2]["fix"]["replacement"] == "talker2"
    assert doc["summary"]["baseline_suppressed"] == 2


def _sarif() -> dict:
    return json.loads(sarif.render(sample_report(), catalog()))


def test_sarif_snapshot_validates_against_oasis_schema() -> None:
    check_snapshot("report.sarif", sarif.render(sample_report(), catalog()))
    schema = json.loads((SCHEMAS / "sarif" / "sarif-schema-2.1.0.json").read_text())
    validator_cls = jsonschema.validators.validator_for(schema)
    validator_cls(schema, format_checker=validator_cls.FORMAT_CHECKER).validate(_sarif())


def test_sarif_follows_github_rules() -> None:
    log = _sarif()
    assert log["$schema"] and log["version"] == "2.1.0" and len(log["runs"]) == 1
    run = log["runs"][0]
    assert run["columnKind"] == "unicodeCodePoints" and run["automationDetails"]["id"] == "physai-lint/"
    assert run["originalUriBaseIds"]["%SRCROOT%"]["uri"] == "file:///ws/"
    rules = run["tool"]["driver"]["rules"]
    assert [r["id"] for r in rules] == ["N101", "P101", "X004"]
    for rule in rules:
        for key in ("shortDescription", "fullDescription"):
            assert 0 < len(rule[key]["text"]) <= 1024
        assert rule["help"]["text"] and rule["help"]["markdown"]
        assert rule["helpUri"].endswith("#" + rule["id"].lower())
        assert rule["defaultConfiguration"]["level"] in ("error", "warning", "note")
        assert len(rule["properties"]["tags"]) <= 20
    assert rules[1]["fullDescription"]["text"] == "Reports a parameters=[...] entry naming a file that does not exist."
    for res in run["results"]:
        assert rules[res["ruleIndex"]]["id"] == res["ruleId"]
        assert 1 <= len(res["locations"]) <= 10
        loc = res["locations"][0]["physicalLocation"]
        assert not loc["artifactLocation"]["uri"].startswith(("/", "file:"))
        assert set(loc["region"]) == {"startLine", "startColumn", "endLine", "endColumn"}
        assert "primaryLocationLineHash" not in res["partialFingerprints"]
        assert res["partialFingerprints"]["physaiLint/v1"]
    first = run["results"][2]
    assert first["message"]["text"].startswith('Duplicate node name "/talker". Give one')
    assert first["relatedLocations"][0]["physicalLocation"]["region"]["startLine"] == 3


def test_sarif_caps_results(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(sarif, "MAX_RESULTS", 2)
    run = _sarif()["runs"][0]
    assert [r["level"] for r in run["results"]] == ["warning", "error"]  # the note is dropped first
    assert "1 results left out" in run["invocations"][0]["toolExecutionNotifications"][0]["message"]["text"]


def test_sarif_schema_copy_is_the_oasis_file() -> None:
    digest = hashlib.sha256((SCHEMAS / "sarif" / "sarif-schema-2.1.0.json").read_bytes()).hexdigest()
    assert digest == "c3b4bb2d6093897483348925aaa73af03b3e3f4bd4ca38cef26dcb4212a2682e"
    assert "OASIS" in (SCHEMAS / "sarif" / "NOTICE").read_text()


def test_github_snapshot_and_escaping() -> None:
    out = github.render(sample_report(), catalog())
    check_snapshot("report.github.txt", out)
    lines = out.splitlines()
    assert lines[0] == (
        "::warning file=src/demo/config/params.yaml,line=3,col=2,endLine=3,endColumn=6,"
        'title=P101 parameter-file-missing::parameter "rate": 100%25, not found,%0Areally'
    )
    assert lines[1].startswith("::notice ") and lines[2].startswith("::error ")
    assert github.escape_property("a:b,c%\n") == "a%3Ab%2Cc%25%0A"


def test_junit_snapshot() -> None:
    out = junit.render(sample_report(), catalog(), fail_on="warning")
    check_snapshot("report.junit.xml", out)
    suite = ET.fromstring(out).find("testsuite")
    assert suite is not None and suite.get("tests") == "3" and suite.get("failures") == "2"
    cases = {c.get("name"): c for c in suite.findall("testcase")}
    assert [f.get("type") for f in cases["src/demo/launch/bringup.launch.py"].findall("failure")] == ["N101"]
    assert "X004" in (cases["src/demo/launch/bringup.launch.py"].findtext("system-out") or "")
    assert cases["src/demo/launch/other.launch.py"].find("failure") is None


def test_junit_survives_control_characters() -> None:
    rep = sample_report()
    rep.findings[0] = rep.findings[0].__class__(**{**{s: getattr(rep.findings[0], s) for s in rep.findings[0].__slots__}, "message": "bad \x00 <&>"})
    ET.fromstring(junit.render(rep, catalog()))


def test_paths_are_relative_and_slashed() -> None:
    out = json.loads(json_report.render(sample_report(), catalog()))
    assert all(not f["file"].startswith("/") and "\\" not in f["file"] for f in out["findings"])
    assert A.endswith(out["findings"][2]["file"])
