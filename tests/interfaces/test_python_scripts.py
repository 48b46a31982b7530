"""A Python node installed as a program without the .py extension (``nodes/run_demo``, its first
line ``#!/usr/bin/env python3``) has its code read for its interface, as a ``.py`` one has."""
from __future__ import annotations

from typing import Any

CMAKE = """project(demo)
install(PROGRAMS nodes/talker nodes/listener.py DESTINATION lib/${PROJECT_NAME})
install(DIRECTORY launch DESTINATION share/${PROJECT_NAME})
"""
TALKER = """#!/usr/bin/env python3
import rclpy
from rclpy.node import Node
from geometry_msgs.msg import Twist


class Talker(Node):
    def __init__(self):
        super().__init__('talker')
        self.pub = self.create_publisher(Twist, 'cmd_vel', 10)
"""
LISTENER = TALKER.replace("'talker'", "'listener'").replace(
    "self.create_publisher(Twist, 'cmd_vel', 10)", "self.create_subscription(Twist, 'cmd_vel', print, 10)")
LAUNCH = """from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='demo', executable='talker'),
        Node(package='demo', executable='listener.py'),
    ])
"""


def test_an_extensionless_python_program_has_its_interface(demo_graph: Any) -> None:
    nodes = demo_graph({"CMakeLists.txt": CMAKE, "nodes/talker": TALKER, "nodes/listener.py": LISTENER,
                        "launch/a.launch.py": LAUNCH}, "launch/a.launch.py")
    assert set(nodes) == {"talker", "listener"}
    assert nodes["talker"]["fqn"] == "/talker"


def test_a_shell_program_without_extension_stays_unknown(demo_graph: Any) -> None:
    nodes = demo_graph({"CMakeLists.txt": CMAKE, "nodes/talker": "#!/bin/sh\nexec python3 -m x\n",
                        "nodes/listener.py": LISTENER, "launch/a.launch.py": LAUNCH}, "launch/a.launch.py")
    assert None in set(nodes) and "listener" in nodes
