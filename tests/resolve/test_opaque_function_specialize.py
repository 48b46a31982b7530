"""OpaqueFunctions whose body loops over (or branches on) what they perform are evaluated again at
resolution, with the values their substitutions have for that include: what ``launch`` does when
``OpaqueFunction.execute`` calls the function with the context of that moment."""
from __future__ import annotations

import json
import textwrap

from physai_lint import api
from physai_lint.engine import CheckOptions

CAMERAS = textwrap.dedent('''\
    import yaml
    from launch import LaunchDescription
    from launch.actions import DeclareLaunchArgument, OpaqueFunction
    from launch.substitutions import LaunchConfiguration
    from launch_ros.actions import Node


    def camera_node(ns):
        return Node(package="demo", executable="relay", name="relay", namespace=f"/cams/{ns}")


    def setup(context, *args, **kwargs):
        names = yaml.safe_load(LaunchConfiguration("cameras").perform(context))
        return [Node(package="demo", executable="hub", name="hub"), *[camera_node(n) for n in names]]


    def generate_launch_description():
        return LaunchDescription([
            DeclareLaunchArgument("cameras", default_value="[front, rear]"),
            OpaqueFunction(function=setup),
        ])
    ''')


def fqns(demo_package, tmp_path, files: dict[str, str], entry: str, **launch_args: str) -> list[str]:
    """The fully qualified names of the nodes ``src/demo/<entry>`` starts, sorted."""
    path = str(demo_package(files) / entry)
    opts = CheckOptions(paths=[path], launch_args=launch_args, workspace=str(tmp_path))
    return sorted(n["fqn"] for n in json.loads(api.graph(opts, path, "json"))["nodes"])


def test_a_loop_over_a_list_argument_unrolls_with_its_value(demo_package, tmp_path):
    files = {"launch/cams.launch.py": CAMERAS}
    assert fqns(demo_package, tmp_path, files, "launch/cams.launch.py") == \
        ["/cams/front/relay", "/cams/rear/relay", "/hub"]
    assert fqns(demo_package, tmp_path, files, "launch/cams.launch.py", cameras="[side]") == \
        ["/cams/side/relay", "/hub"]


def test_each_include_evaluates_the_function_with_its_own_arguments(demo_package, tmp_path):
    top = textwrap.dedent('''\
        <launch>
          <include file="$(find-pkg-share demo)/launch/cams.launch.py">
            <arg name="cameras" value="[left]"/>
          </include>
          <group>
            <push-ros-namespace namespace="two"/>
            <include file="$(find-pkg-share demo)/launch/cams.launch.py">
              <arg name="cameras" value="[a, b, c]"/>
            </include>
          </group>
        </launch>
        ''')
    files = {"launch/cams.launch.py": CAMERAS, "launch/top.launch.xml": top}
    assert fqns(demo_package, tmp_path, files, "launch/top.launch.xml") == \
        ["/cams/a/relay", "/cams/b/relay", "/cams/c/relay", "/cams/left/relay", "/hub", "/two/hub"]


def test_a_file_named_by_an_argument_is_read_where_launch_would_find_it(demo_graph):
    # Autoware's component_state_monitor: the rows of a YAML file (named by a launch argument,
    # under the package's installed share directory) filtered by another argument
    launch = textwrap.dedent('''\
        from pathlib import Path
        import yaml
        from launch import LaunchDescription
        from launch.actions import DeclareLaunchArgument, OpaqueFunction
        from launch.substitutions import LaunchConfiguration, PathJoinSubstitution
        from launch_ros.actions import Node
        from launch_ros.substitutions import FindPackageShare


        def setup(context):
            mode = LaunchConfiguration("mode").perform(context)
            rows = yaml.safe_load(Path(LaunchConfiguration("file").perform(context)).read_text())
            rows = [row for row in rows if mode in row["mode"]]
            return [Node(package="demo", executable="monitor", name="monitor_" + row["name"]) for row in rows]


        def generate_launch_description():
            return LaunchDescription([
                DeclareLaunchArgument("mode", default_value="online"),
                DeclareLaunchArgument("file", default_value=PathJoinSubstitution(
                    [FindPackageShare("demo"), "config", "topics.yaml"])),
                OpaqueFunction(function=setup),
            ])
        ''')
    rows = "- {name: a, mode: [online]}\n- {name: b, mode: [replay]}\n- {name: c, mode: [online, replay]}\n"
    files = {"launch/mon.launch.py": launch, "config/topics.yaml": rows}
    assert sorted(demo_graph(files, "launch/mon.launch.py")) == ["monitor_a", "monitor_c"]
    assert sorted(demo_graph(files, "launch/mon.launch.py", mode="replay")) == ["monitor_b", "monitor_c"]


def test_a_value_not_known_at_resolution_leaves_the_function_opaque(demo_findings, demo_package, tmp_path):
    # the argument comes from the environment: nothing to evaluate the loop with; the function
    # stays opaque and the rules stay quiet about what it may start or read
    launch = CAMERAS.replace('default_value="[front, rear]"',
                             'default_value=EnvironmentVariable("CAMERAS")').replace(
        "LaunchConfiguration\n", "LaunchConfiguration, EnvironmentVariable\n")
    files = {"launch/cams.launch.py": launch}
    assert fqns(demo_package, tmp_path, files, "launch/cams.launch.py") == []  # nothing invented
    assert demo_findings(files, "launch/cams.launch.py", "X003") == []
    assert demo_findings(files, "launch/cams.launch.py", "L102") == []


def test_nodes_of_an_unrolled_loop_are_checked(demo_findings):
    # a node the loop makes names a package that does not exist: found once the loop unrolls
    launch = CAMERAS.replace('Node(package="demo", executable="relay"', 'Node(package="demo_missing", executable="relay"')
    found = demo_findings({"launch/cams.launch.py": launch}, "launch/cams.launch.py", "U101")
    assert found and all('"demo_missing"' in message for _, message in found)


def test_itertools_chain_of_known_lists_is_evaluated(demo_graph):
    launch = textwrap.dedent('''\
        from itertools import chain
        from launch import LaunchDescription
        from launch_ros.actions import Node


        def generate_launch_description():
            groups = [[Node(package="demo", executable="x", name=f"n{i}{j}") for j in range(2)] for i in range(2)]
            more = [[Node(package="demo", executable="x", name="m")]]
            return LaunchDescription(list(chain(*groups)) + list(chain.from_iterable(more)))
        ''')
    assert sorted(demo_graph({"launch/c.launch.py": launch}, "launch/c.launch.py")) == ["m", "n00", "n01", "n10", "n11"]


def test_a_crash_while_evaluating_again_is_a_finding_not_a_traceback(demo_findings, monkeypatch):
    import physai_lint.frontends.python as frontend

    def crash(*_args, **_kwargs):
        raise RuntimeError("boom")

    monkeypatch.setattr(frontend, "specialize", crash)
    found = demo_findings({"launch/cams.launch.py": CAMERAS}, "launch/cams.launch.py", "X003")
    assert [message for _, message in found] == [
        "internal error in python frontend (OpaqueFunction evaluated with its arguments): RuntimeError: boom"]


def test_eval_of_set_operations_decides_groups(demo_graph):
    # Autoware's pose_twist_estimator.launch.xml picks its pose estimators this way
    launch = textwrap.dedent('''\
        <launch>
          <arg name="pose_source" default="ndt_yabloc"/>
          <let name="srcs" value="$(eval &quot;list(set('$(var pose_source)'.split('_')).intersection(['ndt', 'yabloc', 'eagleye']))&quot;)"/>
          <group if="$(eval &quot;'ndt' in $(var srcs)&quot;)"><node pkg="demo" exec="x" name="ndt"/></group>
          <group if="$(eval &quot;'eagleye' in $(var srcs)&quot;)"><node pkg="demo" exec="x" name="eagleye"/></group>
          <group if="$(eval &quot;len($(var srcs)) > 1&quot;)"><node pkg="demo" exec="x" name="arbiter"/></group>
        </launch>
        ''')
    nodes = demo_graph({"launch/pose.launch.xml": launch}, "launch/pose.launch.xml")
    assert {name: n["active"] for name, n in nodes.items()} == {"ndt": True, "eagleye": False, "arbiter": True}


LIDAR = textwrap.dedent('''\
    from launch import LaunchDescription
    from launch.actions import DeclareLaunchArgument, OpaqueFunction
    from launch.substitutions import LaunchConfiguration
    from launch_ros.actions import ComposableNodeContainer
    from launch_ros.descriptions import ComposableNode


    def lidar_make(model):
        if model[:6].lower() == "pandar":
            return "Hesai"
        elif model.lower() in ["helios", "bpearl"]:
            return "Robosense"
        return "Velodyne"


    def setup(context):
        make = lidar_make(LaunchConfiguration("sensor_model").perform(context))
        driver = ComposableNode(package="demo", plugin=make + "Wrapper", name=make.lower() + "_driver")
        filters = [ComposableNode(package="demo", plugin="demo::Filter", name="filter")]
        if LaunchConfiguration("crop").perform(context) == "true":
            filters.append(ComposableNode(package="demo", plugin="demo::Crop", name="crop"))
        return [ComposableNodeContainer(name="lidar", namespace="", package="rclcpp_components",
                                        executable="component_container", composable_node_descriptions=[driver, *filters])]


    def generate_launch_description():
        return LaunchDescription([
            DeclareLaunchArgument("sensor_model", default_value="Pandar64"),
            DeclareLaunchArgument("crop", default_value="false"),
            OpaqueFunction(function=setup),
        ])
    ''')


def test_a_function_that_branches_on_what_it_performs_is_evaluated_with_its_values(demo_package, tmp_path):
    # nebula_node_container.launch.py (Autoware's sensor kits): the body evaluates at parse time,
    # but the driver's name hangs on an ``if`` over a performed argument, and so does a component;
    # evaluated again with the include's values, launch's names and components come out
    files = {"launch/lidar.launch.py": LIDAR}
    assert fqns(demo_package, tmp_path, files, "launch/lidar.launch.py") == ["/filter", "/hesai_driver", "/lidar"]
    assert fqns(demo_package, tmp_path, files, "launch/lidar.launch.py", sensor_model="VLP16", crop="true") == \
        ["/crop", "/filter", "/lidar", "/velodyne_driver"]


def test_a_branch_on_a_value_unknown_at_resolution_stays_undecided(demo_package, tmp_path):
    # the model comes from the environment: the driver's name stays unknown (no name invented);
    # the other argument is known, and decides its own branch (no crop component)
    launch = LIDAR.replace('default_value="Pandar64"', 'default_value=EnvironmentVariable("MODEL")').replace(
        "LaunchConfiguration\n", "LaunchConfiguration, EnvironmentVariable\n")
    path = str(demo_package({"launch/lidar.launch.py": launch}) / "launch/lidar.launch.py")
    opts = CheckOptions(paths=[path], workspace=str(tmp_path))
    nodes = json.loads(api.graph(opts, path, "json"))["nodes"]
    assert sorted((n["fqn"], n["active"]) for n in nodes if n["fqn"]) == [("/filter", True), ("/lidar", True)]
    assert [(n["package"], n["active"]) for n in nodes if not n["fqn"]] == [("demo", True)]  # the driver


def test_a_lookup_without_default_of_an_unset_configuration_is_no_error(demo_findings):
    # context.launch_configurations.get("extra") gives None when nothing set it: launch does not
    # fail there, unlike LaunchConfiguration("extra").perform(context) or [...]["extra"]
    launch = textwrap.dedent('''\
        from launch import LaunchDescription
        from launch.actions import DeclareLaunchArgument, OpaqueFunction
        from launch.substitutions import LaunchConfiguration
        from launch_ros.actions import Node


        def setup(context):
            extra = context.launch_configurations.get("extra")
            must = context.launch_configurations["must"]
            name = "a" if LaunchConfiguration("mode").perform(context)[:1] == "f" else "b"
            return [Node(package="demo", executable="x", name=name)]


        def generate_launch_description():
            return LaunchDescription([
                DeclareLaunchArgument("mode", default_value="fast"),
                OpaqueFunction(function=setup),
            ])
        ''')
    found = demo_findings({"launch/a.launch.py": launch}, "launch/a.launch.py", "L101")
    assert [message.split(";")[0] for _, message in found] == [
        'launch configuration "must" is read but never declared or set']
