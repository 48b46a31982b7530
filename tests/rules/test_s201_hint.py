"""S201's did-you-mean offers only nodes no manager lists yet: map_server, already in node_names,
is no misspelling of the missing map_saver."""
from __future__ import annotations

from typing import Any

LAUNCH = """from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='nav2_map_server', executable='map_server', name='map_server'),
        Node(package='nav2_amcl', executable='amcl', name='amcl'),
        Node(package='nav2_map_server', executable='map_saver_server', name='map_savr'),
        Node(package='nav2_lifecycle_manager', executable='lifecycle_manager', name='lifecycle_manager',
             parameters=[{'autostart': True, 'node_names': [{names}]}]),
    ])
"""


def test_the_hint_skips_nodes_the_manager_lists_already(demo_findings: Any) -> None:
    text = LAUNCH.replace("{names}", "'map_server', 'amcl', 'map_saver'")
    (found,) = demo_findings({"launch/loc.launch.py": text}, "launch/loc.launch.py", "S201")
    assert 'manages "map_saver" (/map_saver) but no such node is launched; did you mean "/map_savr"?' \
        in found[1]
