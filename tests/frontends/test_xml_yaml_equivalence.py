"""The same launch system written in XML and YAML gives the same IR up to spans and ids."""
from __future__ import annotations

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[2]))  # tests run without an install

import dataclasses  # noqa: E402
from typing import Any  # noqa: E402

from physai_lint.frontends.tags import unknown_markup  # noqa: E402
from physai_lint.frontends.xml_launch import parse_xml_launch  # noqa: E402
from physai_lint.frontends.yaml_launch import parse_yaml_launch  # noqa: E402
from physai_lint.model import launch as ir  # noqa: E402
from physai_lint.model import values  # noqa: E402
from physai_lint.model.span import Span  # noqa: E402
from physai_lint.params.typing import pyyaml_type  # noqa: E402

FIXTURES = Path(__file__).parent / "fixtures" / "markup"


def strip(obj: Any) -> Any:
    """Drop spans and ids (and keep only the keys of ``field_spans``) recursively.

    A parameter value launch reads without substitutions is compared as the value it becomes: XML
    ``value="10.0"`` is YAML-typed at run time (a ``PSubst``) while YAML ``value: 10.0`` is a float
    as written (a ``PLit``); both reach the node as 10.0."""
    if isinstance(obj, Span):
        return None
    if isinstance(obj, values.PSubst) and obj.sep is None \
            and all(isinstance(p, values.Text) for p in obj.value):
        text = "".join(p.text for p in obj.value)
        return ("param-value", text if obj.value_type == "str" else pyyaml_type(text))
    if isinstance(obj, values.PLit):
        return ("param-value", obj.value)
    if dataclasses.is_dataclass(obj) and not isinstance(obj, type):
        out: dict[str, Any] = {"__type__": type(obj).__name__}
        for f in dataclasses.fields(obj):
            value = getattr(obj, f.name)
            if f.name == "id":
                continue
            if f.name == "field_spans":
                value = tuple(sorted(k for k, _ in value))
            if f.name == "raw" and isinstance(obj, ir.Condition):
                continue
            out[f.name] = strip(value)
        return out
    if isinstance(obj, (tuple, list)):
        return tuple(strip(x) for x in obj)
    return obj


def load(name: str) -> ir.LaunchFile:
    path = FIXTURES / name
    parse = parse_xml_launch if name.endswith(".xml") else parse_yaml_launch
    result = parse(str(path), path.read_text())
    assert result.diagnostics == []
    assert result.launch is not None
    return result.launch


def test_xml_and_yaml_give_the_same_ir() -> None:
    xml, yaml = load("system.launch.xml"), load("system.launch.yaml")
    assert xml.format == "xml" and yaml.format == "yaml"
    assert len(xml.actions) == 18
    for a, b in zip(xml.actions, yaml.actions):
        assert strip(a) == strip(b), type(a).__name__
    assert strip(xml.actions) == strip(yaml.actions)


def test_both_formats_have_no_unknown_markup() -> None:
    for name in ("system.launch.xml", "system.launch.yaml"):
        launch = load(name)
        assert unknown_markup(launch.markup or ir.MarkupFacts(), launch.format) == []


def test_a_sep_key_is_xml_only() -> None:
    # launch_xml's Entity.get_attr reads "<name>-sep" for a list; launch_yaml has no such key and
    # rejects the file ("Unexpected key(s) found in `param`: {'value-sep'}")
    text = "launch:\n- node:\n    pkg: p\n    exec: e\n    param:\n    - {name: n, value: a;b, value-sep: ;}\n"
    launch = parse_yaml_launch("a.launch.yaml", text).launch
    assert launch is not None and launch.markup is not None
    assert [(m, h) for _, m, h in unknown_markup(launch.markup, "yaml")] == [
        ('unknown attribute "value-sep" on "param"', "give value as a YAML list instead")]


def test_markup_facts_record_every_tag_with_its_parent() -> None:
    for name in ("system.launch.xml", "system.launch.yaml"):
        facts = load(name).markup
        assert facts is not None
        tags = [(tag, parent) for tag, parent, _, _ in facts.elements]
        assert ("composable_node", "node_container") in tags
        assert ("param", "param") in tags
        assert ("keep", "reset") in tags
        assert ("executable", "timer") in tags
