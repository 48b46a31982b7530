"""T102 (unused-remap) says a rule matches none of a node's topics only when an interfaces file
declares them: sources miss what base classes and library members create."""
from physai_lint.engine import CheckOptions, run_check

CMAKE = """project(demo)
add_executable(talker src/talker.cpp)
install(TARGETS talker DESTINATION lib/${PROJECT_NAME})
install(DIRECTORY launch DESTINATION share/${PROJECT_NAME})
"""
SOURCE = """
#include <rclcpp/rclcpp.hpp>
class Talker : public rclcpp::Node {
 public:
  Talker() : Node("talker") { pub_ = create_publisher<std_msgs::msg::String>("chatter", 10); }
};
"""
LAUNCH = """
from launch import LaunchDescription
from launch_ros.actions import Node

def generate_launch_description():
    return LaunchDescription([
        Node(package="demo", executable="talker", remappings=[("chatter_typo", "/speech")]),
    ])
"""
INTERFACES = "demo/talker:\n  publishers: [chatter]\n"


def _t102(tmp_path, demo_package, interfaces: bool) -> list[str]:
    pkg = demo_package({"CMakeLists.txt": CMAKE, "src/talker.cpp": SOURCE, "launch/a.launch.py": LAUNCH})
    extra = []
    if interfaces:
        (tmp_path / "interfaces.yaml").write_text(INTERFACES)
        extra = [str(tmp_path / "interfaces.yaml")]
    opts = CheckOptions(paths=[str(pkg / "launch/a.launch.py")], workspace=str(tmp_path), interfaces=extra)
    return [f.message for f in run_check(opts).findings if f.code == "T102"]


def test_extracted_sources_are_not_trusted_to_be_complete(tmp_path, demo_package):
    assert _t102(tmp_path, demo_package, interfaces=False) == []


def test_declared_interfaces_are(tmp_path, demo_package):
    assert [m.split(" (")[0] for m in _t102(tmp_path, demo_package, interfaces=True)] == [
        'remap "chatter_typo" matches no topic of /talker']
