"""An endpoint whose name the code computes (a parameter's value, a built string) may be the
other end of any topic of its type: T201/T202 do not report a topic such an endpoint could be."""
from __future__ import annotations

from pathlib import Path
from typing import Any

from physai_lint.engine import CheckOptions, run_check
from physai_lint.interfaces.extract_cpp import extract_cpp
from physai_lint.interfaces.extract_py import extract_py

CMAKE = """project(demo)
add_executable(mapper src/mapper.cpp)
add_executable(user src/user.cpp)
install(TARGETS mapper user DESTINATION lib/${PROJECT_NAME})
install(DIRECTORY launch DESTINATION share/${PROJECT_NAME})
"""
MAPPER = """
Mapper::Mapper() : Node("mapper") {
  auto topic = declare_parameter<std::string>("topic_name", "map");
  pub_ = create_publisher<nav_msgs::msg::OccupancyGrid>(topic, 1);
  info_ = create_publisher<std_msgs::msg::String>("info", 1);
}
"""
USER = """
User::User() : Node("user") {
  map_ = create_subscription<TYPE>("/map", 1, [this](auto m) { on_map(m); });
  info_ = create_subscription<std_msgs::msg::String>("info", 1, std::bind(&User::cb, this, _1));
}
"""
LAUNCH = """<launch>
  <node pkg="demo" exec="mapper" name="mapper"/>
  <node pkg="demo" exec="user" name="user"/>
</launch>
"""


def _t201(tmp_path: Path, demo_package: Any, user_type: str) -> list[str]:
    pkg = demo_package({"CMakeLists.txt": CMAKE, "src/mapper.cpp": MAPPER,
                        "src/user.cpp": USER.replace("TYPE", user_type), "launch/a.launch.xml": LAUNCH})
    opts = CheckOptions(paths=[str(pkg / "launch/a.launch.xml")], workspace=str(tmp_path), cache=False)
    return [f.message for f in run_check(opts).findings if f.code == "T201"]


def test_a_computed_name_of_the_same_type_may_be_the_publisher(tmp_path: Path, demo_package: Any) -> None:
    assert _t201(tmp_path, demo_package, "nav_msgs::msg::OccupancyGrid") == []


def test_a_computed_name_of_another_type_is_not(tmp_path: Path, demo_package: Any) -> None:
    found = _t201(tmp_path, demo_package, "sensor_msgs::msg::Image")
    assert len(found) == 1 and '"/map"' in found[0]


def test_extractors_record_them() -> None:
    cpp = extract_cpp([("a.cpp", MAPPER)])
    assert [e.name for e in cpp.publishers] == ["info"]
    assert cpp.unnamed == [("publishers", "nav_msgs/msg/OccupancyGrid")]
    source = ("from nav_msgs.msg import OccupancyGrid\n"
              "class M(Node):\n    def __init__(self):\n"
              "        self.create_subscription(OccupancyGrid, self.topic, self.cb, 1)\n")
    py = extract_py([("a.py", source)])
    assert py.subscribers == [] and py.unnamed == [("subscribers", "nav_msgs/msg/OccupancyGrid")]


def test_an_include_that_cannot_be_followed_may_start_the_publisher(tmp_path: Path, demo_package: Any) -> None:
    # an include of a package outside the workspace (released, not built here) may start any node:
    # the topic nobody in the workspace publishes might be its
    def found(include: str) -> list[str]:
        pkg = demo_package({"CMakeLists.txt": CMAKE, "src/mapper.cpp": MAPPER,
                            "src/user.cpp": USER.replace("TYPE", "sensor_msgs::msg::Image"),
                            "launch/a.launch.xml": LAUNCH.replace("</launch>", include + "</launch>")})
        opts = CheckOptions(paths=[str(pkg / "launch/a.launch.xml")], workspace=str(tmp_path), cache=False)
        return [f.message for f in run_check(opts).findings if f.code == "T201"]

    assert len(found("")) == 1
    assert found('<include file="$(find-pkg-share realsense2_camera)/launch/rs_launch.py"/>') == []


CAMERA_LAUNCH = """from launch import LaunchDescription
from launch_ros.actions import LoadComposableNodes, Node
from launch_ros.descriptions import ComposableNode


def generate_launch_description():
    return LaunchDescription([
        Node(package='usb_cam', executable='usb_cam_node_exe', name='camera', namespace='front'),
        LoadComposableNodes(target_container='/vision', composable_node_descriptions=[
            ComposableNode(package='image_proc', plugin='image_proc::RectifyNode', name='rectify',
                           namespace='proc', remappings=[('image', '/front/image_raw')]),
        ]),
    ])
"""


def _camera_findings(tmp_path: Path, demo_package: Any, distro: str) -> list[tuple[str, str]]:
    pkg = demo_package({"launch/camera.launch.py": CAMERA_LAUNCH})
    opts = CheckOptions(paths=[str(pkg / "launch/camera.launch.py")], workspace=str(tmp_path), cache=False,
                        distro=distro)
    return sorted((f.code, f.message.split(" but ")[0]) for f in run_check(opts).findings if f.code in ("T201", "T202"))


def test_a_declared_endpoint_named_by_a_remapped_topic_is_unnamed_where_it_is(tmp_path: Path, demo_package: Any) -> None:
    # humble: image_proc 3.0 subscribes <ns>/camera_info whatever "image" is remapped to
    assert _camera_findings(tmp_path, demo_package, "humble") == [
        ("T201", '/proc/rectify subscribes to "/proc/camera_info"'),
        ("T202", '/front/camera publishes "/front/camera_info"'),
    ]


def test_from_jazzy_rectify_follows_its_remapped_image(tmp_path: Path, demo_package: Any) -> None:
    # image_proc 5.0 resolves "image" with its remappings: camera_info is /front/camera_info
    assert _camera_findings(tmp_path, demo_package, "jazzy") == []
