"""The Python frontend turns nav2_common.launch helpers into known substitutions."""
from __future__ import annotations

from test_python_constructs import actions

from physai_lint.model import values as V


def test_rewritten_yaml_and_launch_config_as_bool_are_substitutions():
    acts = actions("""
        from launch.conditions import IfCondition
        from launch.substitutions import PythonExpression
        from launch_ros.actions import Node
        from nav2_common.launch import LaunchConfigAsBool, RewrittenYaml

        def generate_launch_description():
            comp = LaunchConfigAsBool('use_composition')
            params = RewrittenYaml(source_file='/p.yaml', root_key='', param_rewrites='',
                                   convert_types=True)
            return [Node(package='p', executable='e', parameters=[params],
                         condition=IfCondition(PythonExpression(['not ', comp])))]
    """)
    node = acts[0]
    rw = node.parameters[0].path[0]
    assert isinstance(rw, V.RewrittenYaml)
    assert rw.param_rewrites == () and rw.convert_types is True  # nav2 iterates "" as no rewrites
    expr = node.condition.value[0]
    assert isinstance(expr, V.PythonExpr)
    assert any(isinstance(p, V.LaunchConfigAsBool) for p in expr.expression)
