"""The name a node's code gives it (``NodeInterface.node_name``): one literal name is the name;
a computed one, several, or only a name passed on from a caller not seen, cannot be told."""
from __future__ import annotations

import pytest

from physai_lint.interfaces.extract_cpp import extract_cpp
from physai_lint.interfaces.extract_py import extract_py
from physai_lint.interfaces.store import parse_interfaces_file


def _cpp_iface(*sources: str):
    return extract_cpp([(f"/ws/src/f{i}.cpp", s) for i, s in enumerate(sources)])


def _cpp(*sources: str) -> tuple[str | None, bool]:
    iface = _cpp_iface(*sources)
    return iface.node_name, iface.node_name_decided


@pytest.mark.parametrize(("source", "expected"), [
    ('Talker::Talker(const rclcpp::NodeOptions & o) : Node("talker", o) {}', ("talker", True)),
    ('class T : public rclcpp::Node { T() : rclcpp::Node("t") {} };', ("t", True)),
    ('auto n = rclcpp::Node::make_shared("foo");', ("foo", True)),
    ('auto n = std::make_shared<rclcpp::Node>("bar", options);', ("bar", True)),
    ('A::A() : nav2_util::LifecycleNode("amcl", "", options) {}', ("amcl", True)),
    ('auto n = std::shared_ptr<rclcpp::Node>(new rclcpp::Node("raw"));', ("raw", True)),
    ('static const char * kName = "konst";\nA::A() : rclcpp::Node(kName) {}', ("konst", True)),
    ('auto n = rclcpp::Node::make_shared(std::string("n_") + suffix);', (None, True)),
    ('A::A() : Node("a") {}\nB::B() : Node("b") {}', (None, True)),  # two nodes
    ('B::B(const std::string & node_name) : rclcpp::Node(node_name) {}', (None, True)),
    ('// Node("in_a_comment")\nauto x = "Node(\\"in_a_string\\")";', (None, False)),
    ('auto p = std::make_shared<Talker>();', (None, False)),  # no node made here
])
def test_cpp(source, expected):
    assert _cpp(source) == expected


def test_cpp_a_name_passed_on_takes_the_literal_main_constructs_the_class_with():
    cls = ('class LifecycleTalker : public rclcpp_lifecycle::LifecycleNode {\n public:\n'
           '  explicit LifecycleTalker(const std::string & node_name, bool ipc = false)\n'
           '  : rclcpp_lifecycle::LifecycleNode(node_name, rclcpp::NodeOptions()) {}\n};\n')
    main = 'int main() { rclcpp::spin(std::make_shared<LifecycleTalker>("lc_talker")->get_node_base_interface()); }'
    assert _cpp(cls, main) == ("lc_talker", True)
    assert _cpp(cls) == (None, True)


def _py(source: str) -> tuple[str | None, bool]:
    header = "import rclpy\nfrom rclpy.node import Node\nfrom rclpy.lifecycle import LifecycleNode\nNAME = 'konst'\n"
    iface = extract_py([("/ws/src/p.py", header + source)])
    return iface.node_name, iface.node_name_decided


@pytest.mark.parametrize(("source", "expected"), [
    ("class T(Node):\n    def __init__(self):\n        super().__init__('talker')\n", ("talker", True)),
    ("class T(Node):\n    def __init__(self):\n        super(T, self).__init__(node_name='t2')\n", ("t2", True)),
    ("class T(Node):\n    def __init__(self):\n        Node.__init__(self, NAME)\n", ("konst", True)),
    ("class T(LifecycleNode):\n    def __init__(self):\n        super().__init__('lc')\n", ("lc", True)),
    ("node = rclpy.create_node('simple')\n", ("simple", True)),
    ("node = Node('plain')\n", ("plain", True)),
    ("node = Node(f'n_{1}')\n", (None, True)),
    (("class Base(Node):\n    def __init__(self, name):\n        super().__init__(name)\n"
      "class Planner(Base):\n    def __init__(self):\n        super().__init__('planner')\n"), ("planner", True)),
    (("class Base(Node):\n    def __init__(self, name):\n        super().__init__(name)\n"
      "def main():\n    rclpy.spin(Base('given'))\n"), ("given", True)),
    ("class Base(Node):\n    def __init__(self, name):\n        super().__init__(name)\n", (None, True)),
    ("class Worker(Thread):\n    def __init__(self):\n        super().__init__(daemon=True)\n", (None, False)),
    ("a = Node('a')\nb = Node('b')\n", (None, True)),
])
def test_python(source, expected):
    assert _py(source) == expected


def test_an_interfaces_file_declares_the_node_name():
    entries, diags = parse_interfaces_file("/i.yaml", "a/b:\n  node_name: bee\nc/d:\n  node_name: null\n"
                                                      "e/f:\n  node_name: 'not a name'\n")
    assert (entries[("a", "b")].node_name, entries[("a", "b")].node_name_decided) == ("bee", True)
    assert (entries[("c", "d")].node_name, entries[("c", "d")].node_name_decided) == (None, True)
    assert not entries[("e", "f")].node_name_decided
    assert [d.code for d in diags] == ["P104"]


def test_python_a_class_made_without_a_literal_name_makes_the_name_unknown():
    # example_route's way: its own node, and a navigator node named by a default argument
    source = ("class Navigator(Node):\n    def __init__(self, node_name='navigator'):\n"
              "        super().__init__(node_name=node_name)\n"
              "def main():\n    node = rclpy.create_node('route')\n    nav = Navigator()\n")
    assert _py(source) == (None, True)


def test_python_follows_the_package_modules_whose_node_classes_the_entry_constructs():
    files = {
        "/ws/src/pybot/pybot/talker.py": "from rclpy.node import Node\n\n\nclass Talker(Node):\n"
                                         "    def __init__(self):\n        super().__init__('talker')\n",
        "/ws/src/pybot/pybot/util.py": "class Pid:\n    def __init__(self, kp):\n        self.kp = kp\n",
        "/ws/src/pybot/pybot/nav.py": "from rclpy.node import Node\n\n\nclass Nav(Node):\n"
                                      "    def __init__(self, node_name='nav'):\n        super().__init__(node_name)\n",
    }
    main = ("import rclpy\nfrom pybot.talker import Talker\nfrom .util import Pid\n\n\n"
            "def main():\n    pid = Pid(1.0)\n    rclpy.spin(Talker())\n")
    iface = extract_py([("/ws/src/pybot/pybot/main.py", main)], files.get)
    assert (iface.node_name, iface.node_name_span.file) == ("talker", "/ws/src/pybot/pybot/talker.py")
    both = main + "    nav = Nav()\n"
    iface = extract_py([("/ws/src/pybot/pybot/main.py", both.replace("import Pid", "import Pid\nfrom pybot.nav import Nav"))],
                       files.get)
    assert (iface.node_name, iface.node_name_decided) == (None, True)
    assert extract_py([("/ws/src/pybot/pybot/main.py", main)]).node_name_decided is False  # not read


def _cpp_ns(*sources: str) -> tuple[str | None, str]:
    iface = _cpp_iface(*sources)
    return iface.node_name, iface.node_namespace


def test_cpp_the_namespace_the_code_gives():
    assert _cpp_ns('auto n = std::make_shared<rclcpp::Node>("driver", "robot1");') == ("driver", "robot1")
    assert _cpp_ns('A::A(const rclcpp::NodeOptions & options) : Node("a", options) {}') == ("a", "")
    assert _cpp_ns('A::A() : nav2_util::LifecycleNode("amcl", "", rclcpp::NodeOptions()) {}') == ("amcl", "")
    assert _cpp_ns('A::A(std::string ns) : Node("a", ns) {}') == (None, "")  # not known


def test_a_name_the_code_remaps_itself_is_not_known():
    # rcl applies the node's own arguments before launch's: the node is /camera_driver
    source = ('auto options = rclcpp::NodeOptions().arguments({"--ros-args", "-r", "__node:=camera_driver"});\n'
              'auto node = std::make_shared<rclcpp::Node>("placeholder", options);\n')
    assert _cpp(source) == (None, True)
    assert _py("node = rclpy.create_node('placeholder', cli_args=['--ros-args', '-r', '__node:=real'])\n") == (
        None, True)
    assert _py("node = rclpy.create_node('placeholder', cli_args=ARGS)\n") == (None, True)


def test_python_namespace():
    source = ("from rclpy.node import Node\n\n\nclass S(Node):\n    def __init__(self):\n"
              "        super().__init__('server', namespace='arm')\n")
    iface = extract_py([("/ws/p.py", source)])
    assert (iface.node_name, iface.node_namespace) == ("server", "arm")


def test_cpp_a_header_only_node_class_the_sources_construct():
    from physai_lint.interfaces.linked import extract_linked

    header = ('#include <rclcpp/rclcpp.hpp>\nclass Worker : public rclcpp::Node {\n public:\n'
              '  Worker() : Node("worker") {}\n};\n')
    main = ('#include "demo/worker.hpp"\nint main() {\n  auto w = std::make_shared<Worker>();\n'
            '  auto helper = rclcpp::Node::make_shared("worker_helper");\n}\n')
    files = {"/ws/src/demo/include/demo/worker.hpp": header}
    iface = extract_linked([("/ws/src/demo/src/worker_main.cpp", main)], [], [], None, files.get)
    assert (iface.node_name, iface.node_name_decided) == (None, True)  # two nodes: /worker, /worker_helper
    alone = main.replace('  auto helper = rclcpp::Node::make_shared("worker_helper");\n', "")
    iface = extract_linked([("/ws/src/demo/src/worker_main.cpp", alone)], [], [], None, files.get)
    assert iface.node_name == "worker"
