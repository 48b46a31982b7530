"""N101 duplicate-node-name across containers: a component is a node of the ROS graph like any
other. Two components of one container are N107's; the same name loaded into two containers, or a
component named like a node (its own container included), is N101. A component does not take its
container's namespace (launch_ros sends make_namespace_absolute(prefix_namespace(pushed, ns)),
rclcpp_components does not forward the container's own -r __ns:=), so per-camera containers with
unnamespaced components collide."""
CAMERAS = """<launch>
  <node_container pkg="rclcpp_components" exec="component_container" name="camera_container" namespace="front">
    <composable_node pkg="image_proc" plugin="image_proc::RectifyNode" name="rectify"/>
  </node_container>
  <node_container pkg="rclcpp_components" exec="component_container" name="camera_container" namespace="rear">
    <composable_node pkg="image_proc" plugin="image_proc::RectifyNode" name="rectify"/>
  </node_container>
</launch>
"""

NAMED_LIKE_CONTAINER = """<launch>
  <node_container pkg="rclcpp_components" exec="component_container" name="perception">
    <composable_node pkg="image_proc" plugin="image_proc::RectifyNode" name="perception"/>
  </node_container>
</launch>
"""

ONE_CONTAINER = """<launch>
  <node_container pkg="rclcpp_components" exec="component_container" name="c">
    <composable_node pkg="image_proc" plugin="image_proc::RectifyNode" name="rectify"/>
    <composable_node pkg="image_proc" plugin="image_proc::RectifyNode" name="rectify"/>
  </node_container>
</launch>
"""


def _codes(demo_findings, text: str, code: str) -> list[tuple[int, str]]:
    return demo_findings({"launch/a.launch.xml": text}, "launch/a.launch.xml", code)


def test_one_name_loaded_into_two_containers_is_a_duplicate_node(demo_findings):
    assert _codes(demo_findings, CAMERAS, "N101") == [(6, (
        'node "/rectify" is a component of container "/rear/camera_container" here and a component '
        'of container "/front/camera_container" at line 3; services, parameters and topics of the two '
        "collide (a component does not take its container's namespace: give it namespace= or push one "
        "around the container)"))]
    assert _codes(demo_findings, CAMERAS, "N107") == []


def test_a_component_named_like_its_container_is_a_duplicate_node(demo_findings):
    assert _codes(demo_findings, NAMED_LIKE_CONTAINER, "N101") == [(3, (
        'node "/perception" is a component of container "/perception" here and a container at line 2; '
        "services, parameters and topics of the two collide"))]


def test_two_components_of_one_container_stay_n107(demo_findings):
    assert _codes(demo_findings, ONE_CONTAINER, "N101") == []
    assert [line for line, _ in _codes(demo_findings, ONE_CONTAINER, "N107")] == [4]
