"""nav2_common.launch helpers (RewrittenYaml, ReplaceString, LaunchConfigAsBool, HasNodeParams)
are evaluated as data, the way nav2 implements them; fixture: fixtures/nav2_ws."""
from __future__ import annotations

import os
from pathlib import Path

import pytest

from physai_lint.engine import CheckOptions, build_project
from physai_lint.params.effective import effective_parameters

WS = Path(__file__).parent / "fixtures" / "nav2_ws"
ENTRY = "src/demo_bringup/launch/nav.launch.py"
PARAMS = str(WS / "src/demo_bringup/config/params.yaml")
LAUNCH = str(WS / ENTRY)


def _nodes(**args: str):
    cwd = os.getcwd()
    os.chdir(WS)
    try:
        project = build_project(CheckOptions(paths=[ENTRY], workspace=".", launch_args=dict(args)))
    finally:
        os.chdir(cwd)
    launch = project.launches[0]
    out = {}
    for n in launch.nodes:
        eff = effective_parameters(n.fqn, n.param_sources, project.param_files)
        out.setdefault(n.fqn, []).append((n, eff))
    return out


def _where(ep):
    return os.path.basename(ep.origin.file), ep.origin.line


def test_conditions_on_launch_config_as_bool_and_has_node_params_are_known():
    nodes = _nodes()
    assert nodes["/ctrl"][0][0].active is False  # not True -> False
    assert nodes["/never"][0][0].active is False  # no "missing" key in the file
    assert [n.active for n, _ in nodes["/planner"]] == [True, True]
    assert _nodes(use_composition="off")["/ctrl"][0][0].active is True  # "off" is not true


def test_rewritten_yaml_rewrites_leaf_keys_paths_and_values_with_positions():
    _, eff = _nodes()["/planner"][0]
    assert eff["use_sim_time"].value is True and _where(eff["use_sim_time"]) == ("nav.launch.py", 23)
    assert eff["frequency"].value == 10.0 and _where(eff["frequency"]) == ("params.yaml", 5)
    assert eff["added"].value == 3 and eff["added"].kind == "integer"  # add_params, convert_types
    assert eff["nested.rate"].value == 8 and _where(eff["nested.rate"]) == ("nav.launch.py", 25)
    assert eff["rate"].value == 5
    assert eff["zone"].value is True and _where(eff["zone"]) == ("nav.launch.py", 29)


def test_rewritten_yaml_round_trip_typing():
    """safe_load then yaml.dump then rcl: the types the node really gets."""
    _, eff = _nodes()["/planner"][0]
    assert eff["mode"].value is True and eff["mode"].kind == "bool"  # "y" dumped plain
    assert eff["big"].value == 1000 and eff["big"].kind == "integer"  # PyYAML reads 1_000
    assert eff["quoted_exp"].value == 1000.0 and eff["quoted_exp"].kind == "double"
    assert eff["empty"].value == "null" and eff["empty"].kind == "string"
    assert _where(eff["big"]) == ("params.yaml", 7)


def test_key_rewrites_root_key_and_unknown_rewrite_value():
    nodes = _nodes(namespace="r1")
    _, eff = nodes["/r1/ctrl"][0]
    assert eff["rate"].value == 20 and eff["plugins"].value == ["a", "b"]
    assert eff["unknown_rate"].value is None and not eff["unknown_rate"].certain
    _, planner = nodes["/r1/planner"][0]
    assert planner["frequency"].value == 10.0


def test_empty_root_key_does_not_wrap_and_unknown_source_is_unknown():
    nodes = _nodes()
    assert "rate" in nodes["/ctrl"][0][1]
    opaque, eff = nodes["/opaque"][0]
    assert eff == {} and opaque.param_sources[0].status == "unknown"


def test_replace_string_keeps_lines_of_the_source():
    node, eff = _nodes(namespace="")["/planner"][1]
    assert eff["frame"].value == "/base_link"
    assert eff["mode"].value == "y" and eff["mode"].kind == "string"  # rcl reads the text as is
    assert _where(eff["frame"]) == ("params.yaml", 10)
    model = node.param_sources[0].model
    assert [(d.code, d.span.line) for d in model.diagnostics] == [("P104", 14)]  # `empty:`


def test_unknown_launch_config_as_bool_keeps_node_activity_unknown():
    from physai_lint.model import values as V
    from physai_lint.resolve.evaluate import Evaluator, Scope

    ev = Evaluator(None)
    lc = V.LaunchConfigAsBool((V.LaunchConfig((V.Text("x"),), None),))
    assert ev.eval((lc,), Scope(configs={"x": None})) is None
    assert ev.eval((lc,), Scope(configs={"x": " Yes "})) == "True"
    assert ev.eval((lc,), Scope(configs={"x": "2"})) == "False"


@pytest.mark.parametrize("name", ["RewrittenYaml", "LaunchConfigAsBool", "ReplaceString", "HasNodeParams"])
def test_recognised_by_qualified_import(name):
    from physai_lint.frontends.python.api import canonical, is_substitution

    for qual in (f"nav2_common.launch.{name}", f"nav2_common.launch.x_mod.{name}"):
        assert canonical(qual) == f"nav2_common.launch.{name}"
    assert is_substitution(f"nav2_common.launch.{name}")
