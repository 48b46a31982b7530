"""Extraction from the statements around call words (a skim of the file, then windows of tokens)
against extraction from every token of the file: the same endpoints, parameters, positions."""
from __future__ import annotations

import dataclasses

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from test_cpp_tokenize_equivalence import SNIPPETS  # (this folder is on the path)

from physai_lint.interfaces import extract_cpp
from physai_lint.interfaces.cpp_scopes import CppFacts
from physai_lint.interfaces.extract_cpp import _extract_from, _Whole, _Windows


def _both(text: str) -> tuple[object, object]:
    whole, windows = CppFacts(), CppFacts()
    _extract_from("src/a.cpp", _Whole(text), whole)
    view = _Windows.of(text)
    _extract_from("src/a.cpp", view if view is not None else _Whole(text), windows)
    return _found(whole), _found(windows)


def _found(facts: CppFacts) -> dict[str, list[object]]:
    """What was found, without the classes holding it nor whether a condition guards it (only
    windows know where words are: the whole file's tokens are read without the skim)."""
    return {"endpoints": [(kind, dataclasses.replace(e, when=())) for kind, e, _ in facts.endpoints],
            "unnamed": [(kind, t) for kind, t, _ in facts.unnamed],
            "parameters": [d for d, _ in facts.parameters], "lifecycle": [len(facts.lifecycle)]}


def _same(text: str) -> None:
    whole, windows = _both(text)
    assert windows == whole


CALLS = [
    'pub_ = this->create_publisher<std_msgs::msg::String>("chatter", 10);',
    ('sub_ = create_subscription<sensor_msgs::msg::Image>(\n  "image", rclcpp::SensorDataQoS(),\n'
     '  [this](sensor_msgs::msg::Image::SharedPtr m) { cb(m); });'),
    'auto srv = node->create_service<std_srvs::srv::Trigger>(SERVICE_NAME, cb);',
    'client_ = create_client<std_srvs::srv::Empty>(kClient);',
    'server_ = rclcpp_action::create_server<nav2_msgs::action::Spin>(\n  this, "spin", a, b, c);',
    'ac_ = rclcpp_action::\n   create_client<nav2_msgs::action::Wait>(this, "wait");',
    'pub = image_transport::create_publisher(this, "camera/image");',
    'cam = it.advertiseCamera("cam", 1); s = it->\n  subscribe(kTopic, 1, &C::cb, this);',
    'tf_listener_ = std::make_shared<tf2_ros::TransformListener>(*buffer_);',
    'br_ = std::make_unique<tf2_ros::\nStaticTransformBroadcaster>(this); tf2_ros::TransformBroadcaster b(this);',
    'declare_parameter<double>("max_speed", 1.5);\nthis->declare_parameter("frame", std::string("map"));',
    'declare_parameter("n", 3, d); d.read_only = true;\ndeclare_parameter("m", 4, rd);\nrd.read_only = true;',
    'nav2_util::declare_parameter_if_not_declared(node, "t", rclcpp::ParameterValue(0.5));',
    'auto v = declare_or_get_parameter<std::vector<double>>("v", std::vector<double>{1.0});',
    ('const std::string kTopic = "from_constant"; static constexpr char kClient[] = "c";\n'
     'const char * SERVICE_NAME{"svc"}; std::string kTopic2("x");'),
    '#define SERVICE_NAME "defined"\n#define kTopic "defined_too"\n',
    'descriptor.read_only = true; desc->read_only = true;',
    ('// create_publisher<std_msgs::msg::String>("commented", 10);\n'
     '/* declare_parameter("in_block", 1); */ "declare_parameter(\\"in_string\\", 1);"'),
    'R"(create_publisher<std_msgs::msg::String>("raw", 10);)" x = 1\'000\'000;',
    '#if 0\ncreate_publisher<a::msg::B>("in_if0", 1);\n#endif\n',
    'f(\n"a" "b"); create_publisher<a::msg::B>("x" "y", 1);',
    'create_publisher<a::msg::B>("no_end", 1)',
    'x = u8R"d(raw)d"; create_publisher<a::msg::B>(u8"pref", 1);',
    '   # define CONT \\\n "continued"\n',
    ('s = create_subscription<a::msg::B>("lam", 1, [this](B m) {\n  f(m); if (x) { g(); }\n  for (;;) {}\n});'),
    'void Foo::subscribe() {\n  a(); b();\n}\nnamespace { int k; }',
    'create_service<a::srv::B>("s", [](){ return; }',
    ('#include <message_filters/subscriber.h>\nFoo::Foo() : Node("f"),\n  odom_(this, "odom"), n_{1}\n'
     '{ sub_.subscribe(this, "scan", qos); }\nmessage_filters::Subscriber<a::msg::B> odom_, b_{this, "b"};'),
    ('x_ = std::make_shared<message_filters::\nSubscriber<a::msg::B, rclcpp::Node>>(node, kTopic);\n'
     'y_ = new message_filters::Subscriber<a::msg::C>(node, "c"); f(message_filters::Subscriber<a::msg::D> & d) {}'),
]


@pytest.mark.parametrize("text", CALLS + SNIPPETS)
def test_windows_extract_what_every_token_does(text: str) -> None:
    _same(text)


def test_windows_on_all_calls_together() -> None:
    text = "\n".join(CALLS)
    whole, windows = _both(text)
    assert windows == whole
    publishers = [e for kind, e in whole["endpoints"] if kind == "publishers"]  # type: ignore[index]
    assert len(publishers) >= 4 and len(whole["parameters"]) >= 5  # type: ignore[index]


def test_a_char_literal_with_a_newline_falls_back_to_every_token() -> None:
    # the tokenizer does not count a newline in a char literal; windows would count it
    text = "char c = '\\\n';\ncreate_publisher<a::msg::B>(\"t\", 1);"
    assert _Windows.of(text) is None
    assert _Windows.of("x = 'a';") is not None
    _same(text)


def test_a_source_past_max_source_falls_back(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(extract_cpp, "MAX_SOURCE", 10)
    assert _Windows.of('create_publisher<a::msg::B>("t", 1);') is None


_PIECES = CALLS + [
    "\n", " ", "//", "/*", "*/", '"', "'", "#", "\\", ";", "{", "}", "(", ")", "<", ">", "::", "->",
    ".", ",", "=", "[", "]", "R", "u8", "L", "1'0", "x", "true", "read_only", "kTopic", "d",
    "create_publisher", "declare_parameter", "advertise", "tf2_ros", "TransformListener", "é",
    '"x", 1);', "<a::msg::B>", 'k = "v";', 'k[] = "v";', 'k{"v"}', "(k, 1)", "1.e5", "1.f", ".5",
    "0x1'F", "1e+", "[](){ f(); }", "{ x; }", "message_filters::Subscriber<a::msg::B> m_", "m_(this, ",
    "m_{node, ", "m_.subscribe(", "Foo::Foo() : "]


@settings(max_examples=2000, deadline=None)
@given(st.lists(st.sampled_from(_PIECES), max_size=20))
def test_generated_sources_extract_the_same(parts: list[str]) -> None:
    _same("".join(parts))
