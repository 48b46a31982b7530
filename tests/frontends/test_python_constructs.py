"""Python launch frontend: each recognised construct maps to the IR."""
from __future__ import annotations

import textwrap

from physai_lint.frontends.python import parse_python_launch
from physai_lint.model import launch as L
from physai_lint.model import values as V

PATH = "/ws/src/pkg/launch/test.launch.py"


def parse(src: str, files: dict[str, str] | None = None, path: str = PATH):
    files = files or {}
    return parse_python_launch(path, textwrap.dedent(src), files.get)


def actions(src: str, files: dict[str, str] | None = None) -> tuple[L.Action, ...]:
    r = parse(src, files)
    assert r.launch is not None, r.diagnostics
    return r.launch.actions


def lit(v):
    return V.literal_of(v)


def test_node_fields_and_field_spans():
    (node,) = actions("""
        from launch import LaunchDescription
        from launch_ros.actions import Node as RosNode

        def generate_launch_description():
            return LaunchDescription([
                RosNode(package='move_group', executable='move_group', name='mg', namespace='arm',
                        arguments=['-d', 'x'], remappings=[('a', 'b')], exec_name='e'),
            ])
    """)
    assert isinstance(node, L.NodeAction) and node.kind == "node"
    assert (lit(node.package), lit(node.executable), lit(node.name), lit(node.namespace)) == ("move_group", "move_group", "mg", "arm")
    assert [lit(a) for a in node.arguments] == ["-d", "x"]
    assert [(lit(r.src), lit(r.dst)) for r in node.remappings] == [("a", "b")]
    assert node.id == "7:9"
    sp = node.span_of("package")
    assert (sp.line, sp.col, sp.end_col) == (7, 25, 37)  # the value "'move_group'"
    assert node.package[0].span == sp


def test_import_forms():
    acts = actions("""
        import launch
        import launch_ros
        import launch_ros.actions as lra
        from launch import actions
        from launch_ros.actions import PushROSNamespace

        def generate_launch_description():
            return launch.LaunchDescription([
                actions.DeclareLaunchArgument('a', default_value='1'),
                launch_ros.actions.Node(package='p', executable='e'),
                lra.LifecycleNode(package='p', executable='e', name='n', namespace=''),
                PushROSNamespace('ns'),
                launch_ros.actions.PushRosNamespace(namespace='ns2'),
            ])
    """)
    kinds = [type(a).__name__ for a in acts]
    assert kinds == ["DeclareArgument", "NodeAction", "NodeAction", "PushNamespace", "PushNamespace"]
    assert acts[2].kind == "lifecycle_node"
    assert lit(acts[4].namespace) == "ns2"


def test_declare_argument_and_configuration():
    a, s = actions("""
        from launch import LaunchDescription
        from launch.actions import DeclareLaunchArgument, SetLaunchConfiguration
        from launch.substitutions import LaunchConfiguration

        def generate_launch_description():
            return LaunchDescription([
                DeclareLaunchArgument('mode', default_value='fast', description='the mode', choices=['fast', 'slow']),
                SetLaunchConfiguration('x', LaunchConfiguration('mode', default='d')),
            ])
    """)
    assert isinstance(a, L.DeclareArgument)
    assert (a.name, lit(a.default), a.description, a.choices) == ("mode", "fast", "the mode", ("fast", "slow"))
    assert a.name_span is not None and a.name_span.col == 31
    assert isinstance(s, L.SetLaunchConfiguration)
    (lc,) = s.value
    assert isinstance(lc, V.LaunchConfig) and lit(lc.name) == "mode" and lit(lc.default) == "d"


def test_add_action_and_returned_list():
    acts = actions("""
        from launch import LaunchDescription
        from launch_ros.actions import Node

        def generate_launch_description():
            ld = LaunchDescription()
            ld.add_action(Node(package='a', executable='a'))
            ld.add_entity(Node(package='b', executable='b'))
            return ld
    """)
    assert [lit(a.package) for a in acts] == ["a", "b"]
    acts = actions("""
        from launch_ros.actions import Node
        def generate_launch_description():
            return [Node(package='a', executable='a')]
    """)
    assert len(acts) == 1


def test_include_sources_and_arguments():
    acts = actions("""
        from launch import LaunchDescription
        from launch.actions import IncludeLaunchDescription
        from launch.launch_description_sources import PythonLaunchDescriptionSource, AnyLaunchDescriptionSource
        from launch_xml.launch_description_sources import XMLLaunchDescriptionSource
        from launch.substitutions import PathJoinSubstitution, LaunchConfiguration
        from launch_ros.substitutions import FindPackageShare

        def generate_launch_description():
            path = PathJoinSubstitution([FindPackageShare('p'), 'launch', 'a.launch.py'])
            return LaunchDescription([
                IncludeLaunchDescription(PythonLaunchDescriptionSource(path),
                                         launch_arguments={'a': '1', 'b': LaunchConfiguration('x')}.items()),
                IncludeLaunchDescription(XMLLaunchDescriptionSource('/abs/b.launch.xml'),
                                         launch_arguments=[('c', 'd')]),
                IncludeLaunchDescription('/abs/c.launch.yaml', launch_arguments={'e': 'f'}),
                IncludeLaunchDescription(AnyLaunchDescriptionSource('/abs/d.launch'), launch_arguments=unknown()),
            ])
    """)
    a, b, c, d = acts
    assert a.source_kind == "python"
    (pj,) = a.path
    assert isinstance(pj, V.PathJoin)
    assert isinstance(pj.parts[0][0], V.FindPackage) and lit(pj.parts[0][0].package) == "p"
    assert [lit(p) for p in pj.parts[1:]] == ["launch", "a.launch.py"]
    assert [(x.name, lit(x.value)) for x in a.arguments] == [("a", "1"), ("b", None)]
    assert a.arguments[0].span.line == 13
    assert b.source_kind == "xml" and [(x.name, lit(x.value)) for x in b.arguments] == [("c", "d")]
    assert c.source_kind == "any" and lit(c.path) == "/abs/c.launch.yaml" and c.arguments[0].name == "e"
    assert d.arguments is None


def test_group_scoping_actions():
    (g,) = actions("""
        from launch import LaunchDescription
        from launch.actions import GroupAction
        from launch_ros.actions import PushRosNamespace, SetRemap, SetParameter, SetParametersFromFile, SetUseSimTime

        def generate_launch_description():
            return LaunchDescription([GroupAction([
                PushRosNamespace('r1'),
                SetRemap(src='a', dst='b'),
                SetParameter(name='use_sim_time', value=True),
                SetParametersFromFile('/p.yaml'),
                SetUseSimTime(True),
            ], scoped=False, forwarding=False, launch_configurations={'k': 'v'})])
    """)
    assert isinstance(g, L.Group) and not g.scoped and not g.forwarding
    assert [(lit(k), lit(v)) for k, v in g.launch_configurations] == [("k", "v")]
    ns, rm, sp, spf, sim = g.actions
    assert lit(ns.namespace) == "r1" and (lit(rm.src), lit(rm.dst)) == ("a", "b")
    assert lit(sp.name) == "use_sim_time" and sp.value == V.PLit(True, sp.value.span)
    assert lit(spf.path) == "/p.yaml" and lit(sim.value) == "True"


def test_conditions():
    acts = actions("""
        from launch import LaunchDescription
        from launch.actions import LogInfo
        from launch.conditions import IfCondition, UnlessCondition, LaunchConfigurationEquals, LaunchConfigurationNotEquals
        from launch.substitutions import LaunchConfiguration

        def generate_launch_description():
            return LaunchDescription([
                LogInfo(msg='a', condition=IfCondition(LaunchConfiguration('x'))),
                LogInfo(msg='b', condition=UnlessCondition('true')),
                LogInfo(msg='c', condition=LaunchConfigurationEquals('mode', 'fast')),
                LogInfo(msg='d', condition=LaunchConfigurationNotEquals('mode', 'fast')),
            ])
    """)
    a, b, c, d = acts
    assert a.condition.kind == "if" and isinstance(a.condition.value[0], V.LaunchConfig)
    assert b.condition.kind == "unless" and lit(b.condition.value) == "true"
    cmp = c.condition.value[0]
    assert isinstance(cmp, V.Compare) and cmp.op == "equals" and lit(cmp.left[0].name) == "mode" and lit(cmp.right) == "fast"
    assert d.condition.value[0].op == "not-equals"
    assert lit(a.message) == "a"


def test_substitutions():
    (log,) = actions("""
        from launch import LaunchDescription
        from launch.actions import LogInfo
        from launch.substitutions import (TextSubstitution, EnvironmentVariable, ThisLaunchFileDir, ThisLaunchFile,
            Command, PythonExpression, AnonName, NotSubstitution, AndSubstitution, OrSubstitution, AnySubstitution,
            AllSubstitution, EqualsSubstitution, NotEqualsSubstitution, IfElseSubstitution, FindExecutable,
            LaunchConfiguration)
        from launch_ros.substitutions import FindPackagePrefix, ExecutableInPackage

        def generate_launch_description():
            lc = LaunchConfiguration('a')
            return LaunchDescription([LogInfo(msg=[
                TextSubstitution(text='t'), EnvironmentVariable('HOME', default_value='h'), ThisLaunchFileDir(),
                ThisLaunchFile(), Command(['xacro ', 'f']), PythonExpression(['1 + ', lc]), AnonName('n'),
                NotSubstitution(lc), AndSubstitution(lc, 'true'), OrSubstitution(lc, lc), AnySubstitution(lc, 'x'),
                AllSubstitution(lc), EqualsSubstitution(lc, 'x'), NotEqualsSubstitution(lc, 'y'),
                IfElseSubstitution(lc, 'a', 'b'), FindExecutable(name='ls'), FindPackagePrefix('p'),
                ExecutableInPackage('exe', 'p'),
            ])])
    """)
    kinds = [type(s).__name__ for s in log.message]
    assert kinds == ["Text", "EnvVar", "ThisFileDir", "ThisFile", "Command", "PythonExpr", "Anon", "BoolOp",
                     "BoolOp", "BoolOp", "BoolOp", "BoolOp", "Compare", "Compare", "IfElse", "FindExecutable",
                     "FindPackage", "ExecInPackage"]
    m = log.message
    assert lit(m[1].default) == "h" and [s.op for s in m[7:12]] == ["not", "and", "or", "any", "all"]
    assert isinstance(m[5].expression[1], V.LaunchConfig)
    assert m[16].kind == "prefix" and not m[16].eager


def test_parameters():
    (node,) = actions("""
        from launch_ros.actions import Node
        from launch_ros.parameter_descriptions import ParameterValue, ParameterFile
        from launch.substitutions import LaunchConfiguration, Command

        def generate_launch_description():
            return [Node(package='p', executable='e', parameters=[
                '/cfg/a.yaml',
                ParameterFile('/cfg/b.yaml', allow_substs=True),
                {'a': {'b': 1, 'c': [1, 2]}, 'd': LaunchConfiguration('x'), 'e': 'str', 'f': 0.5,
                 'g': [LaunchConfiguration('y'), 'z'], 'h': ParameterValue(Command('xacro f'), value_type=str)},
                unknown_params,
            ])]
    """)
    f1, f2, d, u = node.parameters
    assert isinstance(f1, L.ParamFile) and lit(f1.path) == "/cfg/a.yaml" and not f1.allow_substs
    assert isinstance(f2, L.ParamFile) and f2.allow_substs
    assert isinstance(u, L.ParamsUnknown)
    entries = {e.name: e.value for e in d.entries}
    assert list(entries) == ["a.b", "a.c", "d", "e", "f", "g", "h"]
    assert entries["a.b"].value == 1 and entries["a.c"].value == (1, 2) and entries["e"].value == "str"
    assert isinstance(entries["d"], V.PSubst) and entries["d"].value_type is None
    # a substitution and strings: one string (launch_ros normalize_parameter_value)
    assert isinstance(entries["g"], V.PSubst) and len(entries["g"].value) == 2
    assert entries["h"].value_type == "str" and isinstance(entries["h"].value[0], V.Command)
    assert d.entries[0].span.line == 10


def test_parameters_dict_not_list_is_recorded():
    r = parse("""
        from launch_ros.actions import Node
        def generate_launch_description():
            params = {'a': 1}
            return [Node(package='p', executable='e', parameters={'device': 'x'}),
                    Node(package='p', executable='e', parameters=params)]
    """)
    n1, n2 = r.launch.actions
    assert isinstance(n1.parameters[0], L.ParamDict) and n1.parameters[0].entries[0].name == "device"
    assert isinstance(n2.parameters[0], L.ParamDict)
    kinds = [dict(c.value_kinds).get("parameters") for c in r.launch.python.calls if c.qualname.endswith("Node")]
    assert kinds == ["dict", "dict"]


def test_composition():
    acts = actions("""
        from launch_ros.actions import ComposableNodeContainer, LoadComposableNodes
        from launch_ros.descriptions import ComposableNode

        def generate_launch_description():
            container = ComposableNodeContainer(name='c', namespace='', package='rclcpp_components',
                executable='component_container', composable_node_descriptions=[
                    ComposableNode(package='a', plugin='a::A', name='a', remappings=[('x', 'y')],
                                   extra_arguments=[{'use_intra_process_comms': True}])])
            load = LoadComposableNodes(target_container=container, composable_node_descriptions=[
                ComposableNode(package='b', plugin='b::B', name='b', parameters=[{'k': 1}])])
            load2 = LoadComposableNodes(target_container='/c', composable_node_descriptions=[])
            return [container, load, load2]
    """)
    c, load, load2 = acts
    assert c.kind == "container" and len(c.composable_nodes) == 1
    cn = c.composable_nodes[0]
    assert lit(cn.plugin) == "a::A" and cn.extra_arguments[0][0] == "use_intra_process_comms" and cn.id == "8:13"
    assert load.target_id == c.id and load.target is None and lit(load.nodes[0].name) == "b"
    assert lit(load2.target) == "/c" and load2.target_id is None


def test_execute_process_timer_events():
    acts = actions("""
        from launch import LaunchDescription
        from launch.actions import (ExecuteProcess, TimerAction, RegisterEventHandler, EmitEvent, LogInfo,
            SetEnvironmentVariable, UnsetEnvironmentVariable, AppendEnvironmentVariable, Shutdown)
        from launch.event_handlers import OnProcessExit, OnProcessStart, OnShutdown, OnExecutionComplete, OnProcessIO
        from launch.events import Shutdown as ShutdownEvent
        from launch_ros.actions import RosTimer, LifecycleNode
        from launch_ros.event_handlers import OnStateTransition

        def generate_launch_description():
            proc = ExecuteProcess(cmd=['ls', '-l'], name='lister')
            lc = LifecycleNode(package='p', executable='e', name='n', namespace='')
            return LaunchDescription([
                proc, lc,
                TimerAction(period=3.0, actions=[LogInfo(msg='t')]),
                RosTimer(period='2', actions=[]),
                RegisterEventHandler(OnProcessExit(target_action=proc, on_exit=[Shutdown(reason='done')])),
                RegisterEventHandler(OnProcessStart(target_action=proc, on_start=lambda event, context: [LogInfo(msg='s')])),
                RegisterEventHandler(OnShutdown(on_shutdown=LogInfo(msg='bye'))),
                RegisterEventHandler(OnExecutionComplete(target_action=lambda a: True, on_completion=[])),
                RegisterEventHandler(OnProcessIO(target_action=proc, on_stdout=lambda ev: None)),
                RegisterEventHandler(OnStateTransition(target_lifecycle_node=lc, goal_state='active', start_state='activating', entities=[LogInfo(msg='a')])),
                EmitEvent(event=ShutdownEvent(reason='x')),
                SetEnvironmentVariable('A', 'b'), UnsetEnvironmentVariable('A'), AppendEnvironmentVariable('P', '/x'),
            ])
    """)
    proc, lc, timer, rtimer, h_exit, h_start, h_shut, h_done, h_io, h_st, emit, se, ue, ae = acts
    assert [lit(c) for c in proc.cmd] == ["ls", "-l"] and lit(proc.name) == "lister"
    assert lit(timer.period) == "3.0" and not timer.ros and isinstance(timer.actions[0], L.Log)
    assert rtimer.ros
    assert h_exit.event == "on_process_exit" and h_exit.target_id == proc.id and h_exit.target_known
    assert isinstance(h_exit.actions[0], L.Shutdown) and lit(h_exit.actions[0].reason) == "done"
    assert h_start.event == "on_process_start" and lit(h_start.actions[0].message) == "s"
    assert h_shut.target_id is None and h_shut.target_known and len(h_shut.actions) == 1
    assert not h_done.target_known
    assert h_io.event == "on_process_io"
    assert h_st.target_id == lc.id and h_st.goal_state == "active" and h_st.start_state == "activating"
    assert emit.event == "launch.events.Shutdown"
    assert (se.op, ue.op, ae.op) == ("set", "unset", "append") and lit(ae.value) == "/x"
