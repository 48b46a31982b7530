"""Endpoints a node has only under some parameter values (``when:`` in an interfaces file or a
bundled declaration): imu_filter_madgwick subscribes to imu/mag only with use_mag true."""
from __future__ import annotations

from pathlib import Path
from typing import Any

from physai_lint.engine import CheckOptions, run_check
from physai_lint.interfaces.store import parse_interfaces_file

CMAKE = """project(demo)
add_executable(imu src/imu.cpp)
install(TARGETS imu DESTINATION lib/${PROJECT_NAME})
install(DIRECTORY launch DESTINATION share/${PROJECT_NAME})
"""
IMU = """
Imu::Imu() : Node("imu") {
  pub_ = create_publisher<sensor_msgs::msg::Imu>("imu/data_raw", 10);
}
"""
LAUNCH = """<launch>
  <node pkg="demo" exec="imu" name="imu"/>
  <node pkg="imu_filter_madgwick" exec="imu_filter_madgwick_node" name="filter">PARAMS</node>
</launch>
"""


def _t201(tmp_path: Path, demo_package: Any, params: str) -> list[str]:
    pkg = demo_package({"CMakeLists.txt": CMAKE, "src/imu.cpp": IMU,
                        "launch/a.launch.xml": LAUNCH.replace("PARAMS", params)})
    opts = CheckOptions(paths=[str(pkg / "launch/a.launch.xml")], workspace=str(tmp_path), cache=False)
    return [f.message for f in run_check(opts).findings if f.code == "T201"]


def test_the_default_use_mag_subscribes_to_the_magnetometer(tmp_path: Path, demo_package: Any) -> None:
    assert _t201(tmp_path, demo_package, "") == ['/filter subscribes to "/imu/mag" but nothing publishes it']


def test_use_mag_false_has_no_magnetometer_subscription(tmp_path: Path, demo_package: Any) -> None:
    assert _t201(tmp_path, demo_package, '<param name="use_mag" value="false"/>') == []


def test_an_unknown_use_mag_is_not_guessed(tmp_path: Path, demo_package: Any) -> None:
    assert _t201(tmp_path, demo_package, '<param name="use_mag" value="$(env USE_MAG)"/>') == []


def test_interfaces_files_declare_when() -> None:
    text = ("demo/filter:\n  subscribers:\n"
            "    - {name: mag, type: sensor_msgs/msg/MagneticField, when: {use_mag: true, mode: 2}}\n"
            "    - {name: bad, when: [use_mag]}\n")
    ifaces, diags = parse_interfaces_file("i.yaml", text)
    mag, bad = ifaces[("demo", "filter")].subscribers
    assert mag.when == (("mode", 2), ("use_mag", True)) and bad.when == ()
    assert [d.message for d in diags] == ["when maps parameter names to plain values"]


def test_a_static_transform_publisher_has_known_topics(tmp_path: Path, demo_package: Any) -> None:
    # tf2_ros's static_transform_publisher publishes /tf_static only: it no longer makes the
    # launch's topics unknown
    tf = '<node pkg="tf2_ros" exec="static_transform_publisher" name="tf" args="0 0 0 0 0 0 a b"/>'
    found = _t201(tmp_path, demo_package, "</node>\n  " + tf + "\n  <node pkg=\"demo\" exec=\"imu\" name=\"imu2\">")
    assert found == ['/filter subscribes to "/imu/mag" but nothing publishes it']
