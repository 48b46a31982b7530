import json
from pathlib import Path

import jsonschema
import pytest
import yaml

from physai_lint.interfaces import (
    build_interface_store, parse_gpl, parse_interfaces_file, type_compatible, validate,
)
from physai_lint.interfaces.extract_cpp import extract_cpp, tokenize
from physai_lint.interfaces.extract_py import extract_py
from physai_lint.interfaces.gpl import mapped_declaration
from physai_lint.interfaces.model import ParamDecl

HERE = Path(__file__).parent
SCHEMAS = HERE.parents[1] / "schemas"

GPL = """\
wheel_controller:
  joints:
    type: string_array
    default_value: []
    validation:
      not_empty<>: []
      unique<>: []
  rate:
    type: double
    default_value: 50.0
    read_only: true
    description: "Rate"
    validation:
      gt<>: [0.0]
  speed:
    type: double
    default_value: 1.0
    validation:
      bounds<>: [0.0, 5.0]
  mode:
    type: string
    default_value: fast
    validation:
      one_of<>: [[fast, slow]]
  gains:
    type: double_array
    default_value: [1.0]
    validation:
      fixed_size<>: [3]
      element_bounds<>: [0.0, 10.0]
  pid:
    p:
      type: double
      default_value: 1.0
  __map_joints:
    offset:
      type: double
      default_value: 0.0
"""


def test_gpl_parse_and_validate():
    decls, patterns, diags = parse_gpl("/p.yaml", GPL)
    assert diags == []
    assert set(decls) == {"joints", "rate", "speed", "mode", "gains", "pid.p", "__map_joints.offset"}
    assert patterns == [""]
    assert decls["rate"].read_only and decls["rate"].type == "double"
    assert decls["rate"].span.line == 8
    assert decls["speed"].min == 0.0 and decls["speed"].max == 5.0
    assert decls["mode"].choices == ["fast", "slow"]
    assert validate(decls["speed"], 6.0) and not validate(decls["speed"], 5.0)
    assert validate(decls["rate"], 0.0) == ["0.0 must be > 0.0"]
    assert validate(decls["mode"], "medium")
    assert validate(decls["joints"], []) == ["must not be empty"]
    assert validate(decls["joints"], ["a", "a"])
    assert len(validate(decls["gains"], [1.0, 20.0])) == 2
    assert validate(decls["gains"], [1.0, 2.0, 3.0]) == []


def test_mapped_declarations_follow_the_array_they_name():
    # ParamListener declares "<j>.offset" for each element j of joints, with the template's type
    decls, _, _ = parse_gpl("/p.yaml", GPL)
    keys = {"joints": ["elbow", "wrist"]}.get
    decl = mapped_declaration(decls, "elbow.offset", keys)
    assert decl is not None and decl.name == "elbow.offset" and decl.type == "double"
    assert mapped_declaration(decls, "knee.offset", keys) is None  # not an element of joints
    assert mapped_declaration(decls, "elbow.offset", lambda _: None) is None  # joints unknown
    assert mapped_declaration(decls, "elbow.other", keys) is None


def test_type_compatible():
    assert type_compatible("double", 50) is False  # rclcpp InvalidParameterTypeException
    assert type_compatible("integer", 5.0) is False
    assert type_compatible("double", 5.0) is True
    assert type_compatible("bool", 1) is False
    assert type_compatible("integer", True) is False
    assert type_compatible("string_array", ["a"]) is True
    assert type_compatible("double_array", [1, 2]) is False
    assert type_compatible("double_array", []) is None
    assert type_compatible(None, 1) is None


def test_gpl_bad_yaml():
    decls, _, diags = parse_gpl("/p.yaml", "a: [\n")
    assert decls == {} and diags[0].code == "X001" and diags[0].span.line == 2


def test_cpp_tokenizer_skips_comments_and_strings():
    toks = tokenize('// create_publisher("x")\n/* y */ auto s = R"d(a"b)d"; f("p" "q");')
    assert [t.text for t in toks if t.kind == "str"] == ['a"b', "pq"]


def test_cpp_extraction():
    text = (HERE / "fixtures" / "foo_node.cpp").read_text()
    i = extract_cpp([("/ws/src/foo/src/foo_node.cpp", text)])
    assert [(e.name, e.type) for e in i.publishers] == [
        ("cmd_vel", "geometry_msgs/msg/Twist"), ("status", "std_msgs/msg/String"),
        ("image_out", "sensor_msgs/msg/Image")]
    assert [e.name for e in i.subscribers] == ["scan", "image_in"]
    assert i.publishers[0].span.line == 13
    assert [e.name for e in i.services] == ["~/reset"]
    assert [e.name for e in i.clients] == ["/global_srv"]
    assert [(e.name, e.type) for e in i.action_servers] == [
        ("navigate_to_pose", "nav2_msgs/action/NavigateToPose")]
    assert [e.name for e in i.action_clients] == ["follow"]
    p = i.parameters
    assert (p["rate"].type, p["use_x"].type, p["count"].type, p["gain"].type) == (
        "double", "bool", "integer", "double")
    assert p["frame"].type == "string" and p["frame"].default == "odom"
    assert p["joints"].type == "string_array"
    assert p["tolerance"].type == "double" and p["tolerance"].default == 0.25
    assert not i.parameters_complete


def test_cpp_callbacks_written_as_lambdas_with_statements():
    # a ";" inside a lambda's braces does not end the call (it used to hide the endpoint)
    text = """
    sub_ = create_subscription<std_msgs::msg::String>(
      "chatter", 10, [this](const std_msgs::msg::String::SharedPtr msg) {
        RCLCPP_INFO(get_logger(), "%s", msg->data.c_str());
        for (int i = 0; i < 3; ++i) { count_ += i; }
      });
    srv_ = create_service<std_srvs::srv::Trigger>("reset",
      [](const std::shared_ptr<std_srvs::srv::Trigger::Request>, std::shared_ptr<std_srvs::srv::Trigger::Response> r) {
        r->success = true;
      });
    broken = create_publisher<std_msgs::msg::String>("unclosed", 10;
    after = create_publisher<std_msgs::msg::String>("after", 10);
    """
    i = extract_cpp([("/ws/src/foo/src/lambdas.cpp", text)])
    assert [(e.name, e.span.line) for e in i.subscribers] == [("chatter", 3)]
    assert [e.name for e in i.services] == ["reset"]
    assert [e.name for e in i.publishers] == ["after"]  # a ";" outside braces still ends a call


def test_cpp_names_from_constants_only_when_they_are_constants():
    text = """
    static constexpr char kScan[] = "scan";
    std::string topic_ = "map";          // a variable: set from a parameter below
    const char * TWICE = "a";
    void f() { topic_ = get_parameter("topic").as_string(); }
    void g() { const char * TWICE = "b"; }  // another scope, another value: unknown
    #define DEFINED "defined"
    auto s = create_subscription<sensor_msgs::msg::LaserScan>(kScan, 10, cb);
    auto m = create_subscription<nav_msgs::msg::OccupancyGrid>(topic_, 10, cb);
    auto t = create_publisher<std_msgs::msg::String>(TWICE, 10);
    auto d = create_publisher<std_msgs::msg::String>(DEFINED, 10);
    """
    i = extract_cpp([("/ws/src/foo/src/consts.cpp", text)])
    assert [e.name for e in i.subscribers] == ["scan"]
    assert [e.name for e in i.publishers] == ["defined"]
    assert i.unnamed == [("subscribers", "nav_msgs/msg/OccupancyGrid"), ("publishers", "std_msgs/msg/String")]


def test_py_extraction():
    text = (HERE / "fixtures" / "talker.py").read_text()
    i = extract_py([("/ws/src/t/t/talker.py", text)])
    assert [(e.name, e.type) for e in i.publishers] == [("chatter", "std_msgs/msg/String")]
    assert [(e.name, e.type) for e in i.subscribers] == [("imu", "sensor_msgs/msg/Imu")]
    assert [(e.name, e.type) for e in i.services] == [("~/add", "example_interfaces/srv/AddTwoInts")]
    assert [e.name for e in i.clients] == ["/other/add"]
    assert [(e.name, e.type) for e in i.action_servers] == [("navigate", "nav2_msgs/action/NavigateToPose")]
    assert [e.name for e in i.action_clients] == ["navigate_remote"]
    p = i.parameters
    assert p["rate"].type == "double" and p["name"].type == "string"
    assert p["typed"].type == "integer_array"
    assert p["limits.max"].type == "integer" and p["limits.min"].type == "double"
    assert "limits.flags" in p and p["limits.flags"].type is None
    assert extract_py([("/bad.py", "def (:")]).publishers == []


class FakeIndex:
    def __init__(self, files, gpl=None, sources=None):
        self.files = files
        self.gpl = gpl or {}
        self.sources = sources or {}

    def parameter_yaml_for(self, package, executable):
        return self.gpl.get((package, executable), [])

    def source_files_for(self, package, executable):
        return self.sources.get((package, executable), [])

    def read_text(self, path):
        return self.files.get(path)


def test_store_merging():
    ifile = (
        "rover_control/wheel_controller:\n"
        "  publishers: [odom]\n"
        "rover_navigation/local_planner:\n"
        "  publishers: [cmd_vel_nav, {name: path, type: nav_msgs/msg/Path}]\n"
        "  subscribers: [odom]\n"
        "  parameters:\n"
        "    max_speed: {type: double, default: 0.5, min: 0.0, max: 2.0}\n"
        "nav2_controller/controller_server:\n"
        "  publishers: [cmd_vel_custom]\n"
    )
    idx = FakeIndex(
        {"/ws/src/rover_control/src/p.yaml": GPL,
         "/ws/src/rover_control/src/w.cpp": (HERE / "fixtures" / "foo_node.cpp").read_text()},
        gpl={("rover_control", "wheel_controller"): ["/ws/src/rover_control/src/p.yaml"]},
        sources={("rover_control", "wheel_controller"): ["/ws/src/rover_control/src/w.cpp"]})
    store, diags = build_interface_store([("/ws/interfaces.yaml", ifile)], idx, "humble")
    assert diags == []
    w = store.get("rover_control", "wheel_controller")
    assert [e.name for e in w.publishers] == ["odom"]  # interfaces file wins
    assert [e.name for e in w.subscribers] == ["scan", "image_in"]  # extracted
    assert w.parameters["rate"].read_only and w.parameters["use_x"].type == "bool"
    assert w.parameters_complete  # generate_parameter_library
    assert w.is_declared("anything.offset") is True  # __map_ pattern at top level
    lp = store.get("rover_navigation", "local_planner")
    assert lp.parameters["max_speed"].max == 2.0 and not lp.parameters_complete
    assert lp.publishers[1].type == "nav_msgs/msg/Path"
    cs = store.get("nav2_controller", "controller_server")
    assert [e.name for e in cs.publishers] == ["cmd_vel_custom"]
    assert cs.parameters["controller_frequency"].type == "double"  # bundled
    lm = store.get("nav2_lifecycle_manager", "lifecycle_manager")
    assert lm.parameters["node_names"].type == "string_array"
    assert lm.parameters["autostart"].type == "bool"
    assert store.get("nope", "nope") is None and store.get(None, "x") is None


def test_bad_interfaces_files():
    _, diags = parse_interfaces_file("/i.yaml", "a/b:\n  publishers: [x\n")
    assert diags[0].code == "X001" and diags[0].span.line == 3
    _, diags = parse_interfaces_file("/i.yaml", "nopackage:\n  publishers: [x]\n")
    assert diags[0].code == "P104" and diags[0].span.line == 1
    _, diags = parse_interfaces_file("/i.yaml", "a/b:\n  publisher: [x]\n")
    assert diags[0].code == "P104" and diags[0].span.line == 2
    _, diags = parse_interfaces_file("/i.yaml", "a/b:\n  parameters:\n    p: {type: float64}\n")
    assert diags[0].code == "P104" and diags[0].span.line == 3


def test_contract_example_files():
    shared = Path("/work/shared/acceptance/cases")
    text = "usb_cam/usb_cam_node_exe:\n  publishers: [image_raw, camera_info]\n"
    entries, diags = parse_interfaces_file("/i.yaml", text)
    assert diags == [] and [e.name for e in entries[("usb_cam", "usb_cam_node_exe")].publishers] == [
        "image_raw", "camera_info"]


BUNDLED = sorted(p for p in SCHEMAS.glob("*.yaml"))


@pytest.mark.parametrize("path", BUNDLED, ids=[p.name for p in BUNDLED])
def test_bundled_schema_files_validate(path):
    schema = json.loads((SCHEMAS / "interface.schema.json").read_text())
    jsonschema.Draft202012Validator.check_schema(schema)
    data = yaml.safe_load(path.read_text())
    jsonschema.validate(data, schema)


def test_bundled_coverage():
    pkgs = {yaml.safe_load(p.read_text())["package"] for p in BUNDLED}
    for pkg in ("nav2_amcl", "nav2_controller", "nav2_planner", "nav2_bt_navigator",
                "nav2_behaviors", "nav2_map_server", "nav2_lifecycle_manager",
                "nav2_velocity_smoother", "robot_state_publisher", "joint_state_publisher",
                "usb_cam", "image_proc", "rplidar_ros", "imu_filter_madgwick",
                "teleop_twist_joy", "robot_localization", "slam_toolbox"):
        assert pkg in pkgs


def test_validate_plain_ranges():
    d = ParamDecl("x", "double", min=0.0, max=1.0, choices=None)
    assert validate(d, 2.0) and not validate(d, 0.5) and validate(d, None) == []


def test_read_only_descriptors_are_extracted() -> None:
    from physai_lint.interfaces.extract_cpp import extract_cpp
    from physai_lint.interfaces.extract_py import extract_py

    cpp = extract_cpp([("/w/n.cpp", """
rcl_interfaces::msg::ParameterDescriptor desc;
desc.read_only = true;
declare_parameter("frame_id", std::string("base"), desc);
declare_parameter("rate", 10.0);
node->declare_parameter("port", 1, rcl_interfaces::msg::ParameterDescriptor{}.set__read_only(true));
""")])
    assert {k: v.read_only for k, v in (cpp.parameters or {}).items()} == {
        "frame_id": True, "rate": False, "port": True}
    py = extract_py([("/w/n.py", """
from rcl_interfaces.msg import ParameterDescriptor
d = ParameterDescriptor(read_only=True)
node.declare_parameter('frame_id', 'base', d)
node.declare_parameter('port', 1, descriptor=ParameterDescriptor(read_only=True))
node.declare_parameter('rate', 10.0, ParameterDescriptor(description='hz'))
""")])
    assert {k: v.read_only for k, v in (py.parameters or {}).items()} == {
        "frame_id": True, "port": True, "rate": False}


def test_cpp_tf2_listener_and_broadcasters_use_absolute_tf_topics():
    text = """
    #include <tf2_ros/transform_listener.h>
    class Localizer : public rclcpp::Node {
      std::shared_ptr<tf2_ros::TransformListener> listener_;
      std::unique_ptr<tf2_ros::TransformBroadcaster> broadcaster_;
      tf2_ros::StaticTransformBroadcaster static_broadcaster_{this};
      // tf2_ros::TransformListener in a comment, TransformListener without tf2_ros:: are not counted
      std::shared_ptr<TransformListener> other_;
    };
    """
    i = extract_cpp([("/ws/src/loc/src/loc.cpp", text)])
    assert [(e.name, e.type) for e in i.subscribers] == [("/tf", "tf2_msgs/msg/TFMessage"),
                                                         ("/tf_static", "tf2_msgs/msg/TFMessage")]
    assert [e.name for e in i.publishers] == ["/tf", "/tf_static"]
    assert i.subscribers[0].span.line == 4
