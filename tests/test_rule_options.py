"""Rule options documented in the catalog (``options`` in rules/<L>/<code>-*.md) do what they say,
and the rules' defaults are the documented ones."""
from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest

from physai_lint.catalog import load_catalog
from physai_lint.checks import param_values, topics
from physai_lint.engine import CheckOptions, run_check
from physai_lint.files import MAX_FILE_BYTES

ROOT = Path(__file__).resolve().parents[1]

INTERFACES = """demo/talker:
  publishers:
    - {name: /initialpose, type: geometry_msgs/msg/PoseWithCovarianceStamped}
    - {name: chatter_out, type: std_msgs/msg/String}
  subscribers:
    - {name: chatter, type: std_msgs/msg/String}
    - {name: odom, type: nav_msgs/msg/Odometry}
demo/listener:
  subscribers:
    - {name: /chatter_ou, type: std_msgs/msg/String}
    - {name: /initialpose, type: geometry_msgs/msg/PoseWithCovarianceStamped}
  publishers:
    - {name: /diagnostics_x, type: std_msgs/msg/String}
demo/servo:
  parameters:
    rate: {type: double, default: 1.0}
  parameters_complete: true
"""

LAUNCH = """<launch>
  <node pkg="demo" exec="talker" name="talker"/>
  <node pkg="demo" exec="listener" name="listener" namespace="Front_Lidar_"/>
  <node pkg="demo" exec="servo" name="servo" namespace="arm">
    <param name="rate" value="2.0"/>
    <param name="use_sim_time" value="true"/>
    <param name="qos_overrides./odom.publisher.depth" value="5"/>
    <param name="debug_level" value="3"/>
  </node>
</launch>
"""


def _run(tmp_path: Path, demo_package: Callable[[dict[str, str]], Path], **rule_options: dict[str, Any]
         ) -> list[tuple[str, str]]:
    pkg = demo_package({"launch/a.launch.xml": LAUNCH})
    (tmp_path / "interfaces.yaml").write_text(INTERFACES)
    opts = CheckOptions(paths=[str(pkg / "launch/a.launch.xml")], workspace=str(tmp_path), cache=False,
                        interfaces=[str(tmp_path / "interfaces.yaml")],
                        rule_options={k.replace("_", "").upper(): v for k, v in rule_options.items()})
    return sorted((f.code, f.message) for f in run_check(opts).findings)


def _codes(found: list[tuple[str, str]], code: str) -> list[str]:
    return [m for c, m in found if c == code]


def test_the_rules_defaults_are_the_documented_ones() -> None:
    catalog = load_catalog(ROOT / "rules")

    def default(code: str, key: str) -> Any:
        return catalog[code].options["properties"][key]["default"]

    assert list(topics.T201_IGNORE_TOPICS) == default("T201", "ignore-topics")
    assert list(topics.T202_IGNORE_TOPICS) == default("T202", "ignore-topics")
    assert list(param_values.P109_IGNORE) == default("P109", "ignore")
    assert MAX_FILE_BYTES == default("X002", "max-bytes")
    assert (default("T202", "only-with-near-miss"), default("N106", "double-underscore"),
            default("N106", "trailing-underscore"), default("N106", "uppercase")) == (True, True, True, False)


def test_every_documented_option_is_read_by_its_rule() -> None:
    source = "\n".join(p.read_text() for p in (ROOT / "physai_lint").rglob("*.py"))
    for code, doc in load_catalog(ROOT / "rules").items():
        for key in (doc.options or {}).get("properties", {}):
            assert f'"{key}"' in source, f"{code} option {key} is documented but never read"


def test_t201_ignore_topics(tmp_path, demo_package) -> None:
    found = _codes(_run(tmp_path, demo_package), "T201")
    assert any('"/chatter"' in m for m in found) and any('"/odom"' in m for m in found)
    found = _codes(_run(tmp_path, demo_package, t201={"ignore-topics": ["/odom", "/chat*"]}), "T201")
    assert found == []


def test_t202_near_miss_and_ignore_topics(tmp_path, demo_package) -> None:
    near = _codes(_run(tmp_path, demo_package), "T202")
    assert len(near) == 1 and '"/chatter_out"' in near[0] and '"/chatter_ou"' in near[0]
    every = _codes(_run(tmp_path, demo_package, t202={"only-with-near-miss": False}), "T202")
    assert {m.split('"')[1] for m in every} == {"/chatter_out", "/diagnostics_x"}
    assert _codes(_run(tmp_path, demo_package, t202={"only-with-near-miss": False,
                                                     "ignore-topics": ["/chatter_*", "/diag*"]}),
                  "T202") == []


def test_p109_ignore(tmp_path, demo_package) -> None:
    found = _codes(_run(tmp_path, demo_package), "P109")
    assert len(found) == 1 and '"debug_level"' in found[0]  # use_sim_time, qos_overrides.* ignored
    found = _codes(_run(tmp_path, demo_package, p109={"ignore": ["debug_*"]}), "P109")
    assert len(found) == 2 and {m.split('"')[1] for m in found} == {"use_sim_time", "qos_overrides./odom.publisher.depth"}


def test_n106_switches(tmp_path, demo_package) -> None:
    found = _codes(_run(tmp_path, demo_package), "N106")
    assert found == [('namespace "/Front_Lidar_" has a part ending in "_" (rcl accepts '
                      'it, but the ROS 2 naming design rules it out)')]
    found = _codes(_run(tmp_path, demo_package, n106={"uppercase": True}), "N106")
    assert found == [('namespace "/Front_Lidar_" has a part ending in "_" and capital letters (rcl accepts '
                      'it, but the ROS 2 naming design rules it out)')]
    assert _codes(_run(tmp_path, demo_package, n106={"trailing-underscore": False}), "N106") == []


@pytest.mark.parametrize("limit,reported", [(100, True), (10_000, False)])
def test_x002_max_bytes(tmp_path, demo_package, limit: int, reported: bool) -> None:
    found = _codes(_run(tmp_path, demo_package, x002={"max-bytes": limit}), "X002")
    if reported:
        assert found and found[0].startswith("file is ") and found[0].endswith("larger than the 100 bytes limit")
    else:
        assert found == []


def test_t201_t202_leave_invalid_names_to_n104(tmp_path, demo_package) -> None:
    # the talker's "chatter_out" remapped to an invalid name: N104 reports it; T202 does not, and
    # T201 does not suggest it for the listener's "/chatter_ou"
    launch = LAUNCH.replace('<node pkg="demo" exec="talker" name="talker"/>',
                            '<node pkg="demo" exec="talker" name="talker">'
                            '<remap from="chatter_out" to="/chatter//ou"/></node>')
    pkg = demo_package({"launch/a.launch.xml": launch})
    (tmp_path / "interfaces.yaml").write_text(INTERFACES)
    opts = CheckOptions(paths=[str(pkg / "launch/a.launch.xml")], workspace=str(tmp_path), cache=False,
                        interfaces=[str(tmp_path / "interfaces.yaml")],
                        rule_options={"T202": {"only-with-near-miss": False}})
    found = sorted((f.code, f.message) for f in run_check(opts).findings)
    assert any("//" in m for m in _codes(found, "N104") + _codes(found, "N105"))
    assert not any("//" in m for c, m in found if c in ("T201", "T202"))
    assert any('"/chatter_ou"' in m for m in _codes(found, "T201"))


def test_t201_default_ignores_namespaced_tf_and_poses(tmp_path, demo_package) -> None:
    # a multi-robot launch remaps /tf to /r1/tf: the default patterns cover both
    interfaces = ("demo/nav:\n  subscribers: [tf, tf_static, initialpose, odom]\n"
                  "demo/driver:\n  publishers: [scan]\n")
    launch = ('<launch>\n  <node pkg="demo" exec="nav" name="nav" namespace="r1"/>\n'
              '  <node pkg="demo" exec="driver" name="driver" namespace="r1"/>\n</launch>\n')
    pkg = demo_package({"launch/a.launch.xml": launch})
    (tmp_path / "interfaces.yaml").write_text(interfaces)
    opts = CheckOptions(paths=[str(pkg / "launch/a.launch.xml")], workspace=str(tmp_path), cache=False,
                        interfaces=[str(tmp_path / "interfaces.yaml")])
    found = [f.message for f in run_check(opts).findings if f.code == "T201"]
    assert found == ['/r1/nav subscribes to "/r1/odom" but nothing publishes it']
