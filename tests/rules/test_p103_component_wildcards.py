"""P103 for a wildcard key in a file a component loads: launch_ros reads a component's own parameter
files itself (to_parameters_list) and honours only "/**" and the exact "ns/name" key, so a key such
as "/**/camera" that rcl would match never reaches it, even when another key of the file does."""
from __future__ import annotations

from typing import Any

CAMERA = ("package='image_proc', plugin='image_proc::RectifyNode', name='camera', namespace='front', "
          "parameters=[params]")


def test_a_wildcard_key_beside_the_exact_one_is_ignored(demo_findings: Any, component_launch: Any) -> None:
    params = ("front/camera:\n  ros__parameters:\n    a: 1\n"
              "/**/camera:\n  ros__parameters:\n    b: 2\n"
              "/**:\n  ros__parameters:\n    c: 3\n"
              "/other/*:\n  ros__parameters:\n    d: 4\n")
    launch = component_launch(CAMERA, namespace="front")
    found = demo_findings({"launch/a.launch.py": launch, "config/cam.yaml": params},
                          "launch/a.launch.py", "P103")
    assert [(line, "is ignored for composable nodes" in message) for line, message in found] == [(4, True)]
