"""Node interfaces that a node's command-line arguments decide, per launched instance: the
Gazebo bridges and spawner of ros_gz (and its ros_ign predecessor).

``ros_gz_bridge``'s ``parameter_bridge`` makes one bridge per argument (``parameter_bridge.cpp ::
main``, after ``rclcpp::init_and_remove_ros_arguments``): ``NAME@ROS_TYPE@GZ_TYPE`` both ways (a ROS
publisher and subscriber), ``NAME@ROS_TYPE[GZ_TYPE`` from Gazebo to ROS (a publisher),
``NAME@ROS_TYPE]GZ_TYPE`` from ROS to Gazebo (a subscription), ``NAME@ROS_SRV_TYPE[@GZ_REQ@GZ_REP]``
a service. The ROS name is the text before the first ``@``, resolved in the node's namespace like
any name the code gives. A ``config_file`` parameter adds bridges from a file, which are not read
here: the node's interface is then unknown.

``ros_gz_sim``'s ``create`` subscribes to ``-topic`` (``create.cpp``: a transient-local
``std_msgs/msg/String`` subscription it waits on) when given; ``-file``/``-string`` need none.
"""
from __future__ import annotations

from dataclasses import replace
from typing import Any

from physai_lint.interfaces.model import Endpoint, NodeInterface
from physai_lint.model.span import Span
from physai_lint.model.values import span_of

BRIDGES = frozenset({("ros_gz_bridge", "parameter_bridge"), ("ros_ign_bridge", "parameter_bridge")})
SPAWNERS = frozenset({("ros_gz_sim", "create"), ("ros_ign_gazebo", "create")})
ARGUMENT_DECIDED = BRIDGES | SPAWNERS


def from_arguments(iface: NodeInterface | None, node: Any) -> NodeInterface | None:
    """``iface`` with the endpoints ``node``'s arguments decide, or None when they are not known
    (an argument not known statically, a bridge configuration file that may be given)."""
    key = (node.package, node.executable)
    own = own_arguments(node.arguments)
    if own is None:
        return None
    args = [a for _, a in own]
    base = iface or NodeInterface(source="ros_gz arguments")
    if key in SPAWNERS:
        if any(_may_set(node, name) for name in ("file", "string", "topic", "param")):
            return None  # since jazzy create reads these parameters before its flags
        topic = _option(args, "topic")
        if topic is False or any(_option(args, f) is False for f in ("file", "param", "string")):
            return None
        if _option(args, "file") or _option(args, "param") or _option(args, "string"):
            topic = None  # create.cpp reads -file, -param and -string before -topic
        subs = [Endpoint(topic, "std_msgs/msg/String")] if topic else []
        return replace(base, subscribers=subs, publishers=[], services=[], clients=[])
    if _may_set(node, "config_file"):
        return None
    pubs: list[Endpoint] = []
    subs: list[Endpoint] = []
    services: list[Endpoint] = []
    spans = argument_spans(node)
    for i, arg in own:
        bridge = _bridge(arg)
        if bridge is None:
            return None  # the bridge prints its usage and exits: nothing known of it
        name, ros_type, direction = bridge
        one = Endpoint(name, ros_type, spans[i] if spans else None)
        if direction == "service":
            services.append(one)
            continue
        if direction in ("both", "gz_to_ros"):
            pubs.append(one)
        if direction in ("both", "ros_to_gz"):
            subs.append(one)
    return replace(base, publishers=pubs, subscribers=subs, services=services, clients=[])


def own_arguments(arguments: tuple[str | None, ...]) -> list[tuple[int, str]] | None:
    """The arguments left once the ``--ros-args ... [--]`` sections are removed (what
    ``init_and_remove_ros_arguments`` leaves), with their indices, or None when one is not known."""
    out: list[tuple[int, str]] = []
    in_ros = False
    for i, a in enumerate(arguments):
        if a is None:
            return None
        if a == "--ros-args":
            in_ros = True
        elif a == "--" and in_ros:
            in_ros = False
        elif not in_ros:
            out.append((i, a))
    return out


def argument_spans(node: Any) -> list[Span | None] | None:
    """Where each of ``node.arguments`` is written, when the launch file's arguments match them
    one to one (XML ``args="a b"`` gives one per word); None otherwise."""
    written = getattr(getattr(node, "action", None), "arguments", None)
    if not written or len(written) != len(node.arguments):
        return None
    return [span_of(value) for value in written]


def _option(args: list[str], flag: str) -> str | None | bool:
    """The value of gflags flag ``flag`` (``-flag value``, ``--flag value``, ``-flag=value``,
    ``--flag=value``); None when absent, False when malformed."""
    for i, a in enumerate(args):
        for form in ("-" + flag, "--" + flag):
            if a == form:
                return args[i + 1] if i + 1 < len(args) else False
            if a.startswith(form + "="):
                return a[len(form) + 1:]
    return None


def _bridge(arg: str) -> tuple[str, str, str] | None:
    """(ROS name, ROS type, "both" / "gz_to_ros" / "ros_to_gz" / "service") of one bridge
    argument, as ``parameter_bridge.cpp :: main`` splits it; None where it refuses it."""
    at = arg.find("@")
    if at <= 0:
        return None
    name, rest = arg[:at], arg[at + 1:]
    for delim, direction in (("@", "both"), ("[", "gz_to_ros"), ("]", "ros_to_gz")):
        pos = rest.find(delim)
        if pos > 0:
            ros_type, gz = rest[:pos], rest[pos + 1:]
            if "/srv/" in ros_type:
                # a service bridge both ways names the Gazebo request and reply types: REQ@REP
                req, _, rep = gz.partition("@")
                return (name, ros_type, "service") if direction == "both" and req and rep else None
            return (name, ros_type, direction) if gz and "@" not in gz else None
        if pos == 0:
            return None
    return (name, rest, "service") if "/srv/" in rest else None


def _may_set(node: Any, name: str) -> bool:
    """Whether a parameter source of ``node`` may set ``name``: a dict that sets it, or a file."""
    for src in node.param_sources:
        params = getattr(src, "params", None)
        if params is None:
            return True  # a parameter file (or a source whose names are not known)
        if any(getattr(p, "name", None) in (name, None) for p in params):
            return True
    return False
