"""graph JSON says when a node's parameters are not fully known, instead of implying it gets none."""
import json

from physai_lint import api
from physai_lint.engine import CheckOptions

PKG = """<package format="3"><name>demo</name><version>0.0.0</version><description>d</description>
<maintainer email="m@example.com">a</maintainer><license>MIT</license>
<export><build_type>ament_cmake</build_type></export></package>
"""

LAUNCH = """
from launch import LaunchDescription
from launch_ros.actions import Node
from mystuff import make_params

def generate_launch_description():
    return LaunchDescription([
        Node(package="demo", executable="a", name="known", parameters=[{"rate": 5.0}]),
        Node(package="demo", executable="a", name="opaque", parameters=[{"rate": 5.0}, make_params()]),
    ])
"""


def test_unknown_parameter_source_marks_parameters_incomplete(tmp_path):
    pkg = tmp_path / "src" / "demo"
    (pkg / "launch").mkdir(parents=True)
    (pkg / "package.xml").write_text(PKG)
    (pkg / "CMakeLists.txt").write_text("project(demo)\ninstall(DIRECTORY launch DESTINATION share/${PROJECT_NAME})\n")
    entry = pkg / "launch" / "a.launch.py"
    entry.write_text(LAUNCH)
    doc = json.loads(api.graph(CheckOptions(paths=[str(entry)], workspace=str(tmp_path)), str(entry), "json"))
    by_name = {n["name"]: n for n in doc["nodes"]}
    assert by_name["known"]["parameters"] == {"rate": 5.0}
    assert by_name["known"]["parameters_complete"] is True
    assert by_name["opaque"]["parameters_complete"] is False
    # the value written in the launch file is still shown; parameters_complete says it may be overridden
    assert by_name["opaque"]["parameters"] == {"rate": 5.0}
