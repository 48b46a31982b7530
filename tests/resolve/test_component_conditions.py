"""A composable node description's condition. Humble's ``LoadComposableNodes.execute`` sends a
load request for every description without asking its condition; iron and later ask
(ros2/launch_ros#339). ``ComposableNodeContainer.execute`` filters its own descriptions by their
conditions on every distro. On humble the component is therefore loaded whatever the condition
says (L115 says so), and the rules see it loaded."""
CONTAINER = """launch:
  - arg: {name: teleop_stream, default: "false"}
  - node_container:
      pkg: rclcpp_components
      exec: component_container
      name: camera_container
      namespace: front
"""

# two components of one name, the second behind a condition false by default
COMPONENTS = """      composable_node:
        - pkg: image_proc
          plugin: image_proc::RectifyNode
          name: rectify
          namespace: front
        - pkg: image_proc
          plugin: image_proc::ResizeNode
          name: rectify
          namespace: front
          if: $(var teleop_stream)
"""

LOAD_YAML = CONTAINER + "  - load_composable_node:\n      target: /front/camera_container\n" + COMPONENTS

CONTAINER_YAML = CONTAINER + COMPONENTS

LOAD_PY = """from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.conditions import IfCondition, UnlessCondition
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import LoadComposableNodes, Node
from launch_ros.descriptions import ComposableNode


def generate_launch_description():
    composed = LaunchConfiguration('use_composition')
    return LaunchDescription([
        DeclareLaunchArgument('use_composition', default_value='false'),
        LoadComposableNodes(
            target_container='/lidar/container',{load_condition}
            composable_node_descriptions=[
                ComposableNode(package='demo', plugin='demo::ScanFilter', name='scan_filter',
                               namespace='lidar', condition=IfCondition(composed)),
            ]),
        Node(package='demo', executable='scan_filter_node', name='scan_filter', namespace='lidar',
             condition=UnlessCondition(composed)),
    ])
"""


def _yaml(demo_findings, text: str, code: str, distro: str = "humble") -> list[tuple[int, str]]:
    return demo_findings({"launch/a.launch.yaml": text}, "launch/a.launch.yaml", code, distro)


def _py(demo_findings, code: str, distro: str = "humble", load_condition: str = "") -> list[tuple[int, str]]:
    text = LOAD_PY.format(load_condition=load_condition)
    return demo_findings({"launch/a.launch.py": text}, "launch/a.launch.py", code, distro)


def test_humble_loads_a_component_whose_condition_is_false(demo_findings):
    assert _yaml(demo_findings, LOAD_YAML, "L115") == [(19, (
        'the condition if="$(var teleop_stream)" of component "/front/rectify" is never evaluated on '
        "humble: LoadComposableNodes loads every composable node description it is given, so the "
        "component is loaded whatever the condition says"))]
    # both are loaded into one container under one name
    assert [line for line, _ in _yaml(demo_findings, LOAD_YAML, "N107")] == [15]


def test_later_distros_ask_the_condition(demo_findings):
    assert _yaml(demo_findings, LOAD_YAML, "L115", "jazzy") == []
    assert _yaml(demo_findings, LOAD_YAML, "N107", "jazzy") == []


def test_a_container_filters_its_own_descriptions_on_humble(demo_findings):
    assert _yaml(demo_findings, CONTAINER_YAML, "L115") == []
    assert _yaml(demo_findings, CONTAINER_YAML, "N107") == []


def test_python_component_beside_its_standalone_twin(demo_findings):
    # use_composition defaults to false: the standalone node runs, and on humble the component too
    (line, message), = _py(demo_findings, "L115")
    assert line == 17 and message.startswith('the condition of component "/lidar/scan_filter" is never')
    assert [line for line, _ in _py(demo_findings, "N101")] == [19]
    assert _py(demo_findings, "L115", "jazzy") == []
    assert _py(demo_findings, "N101", "jazzy") == []
    # what the condition reads is still read: no L102 for use_composition
    assert _py(demo_findings, "L102") == []


def test_not_reported_where_the_load_never_runs(demo_findings):
    load_condition = "\n            condition=IfCondition(composed),"
    assert _py(demo_findings, "L115", load_condition=load_condition) == []


def test_a_condition_the_load_carries_too_is_not_reported(demo_findings):
    # written on both: the one on the LoadComposableNodes is evaluated, so nothing is lost (true
    # by default here, so the load runs)
    text = LOAD_PY.format(load_condition="\n            condition=IfCondition(composed),").replace(
        "default_value='false'", "default_value='true'")
    assert demo_findings({"launch/a.launch.py": text}, "launch/a.launch.py", "L115") == []
    yaml = LOAD_YAML.replace('default: "false"', 'default: "true"')
    assert [line for line, _ in _yaml(demo_findings, yaml, "L115")] == [19]
    yaml = yaml.replace("  - load_composable_node:\n", "  - load_composable_node:\n      if: $(var teleop_stream)\n")
    assert _yaml(demo_findings, yaml, "L115") == []
