"""A Python ``str`` in a launch parameter dict stays a string (``normalize_parameter_dict``
yaml.dump-s it), even when its text is only known at launch time (``.perform(context)``); a
substitution's text is typed as YAML. zed-ros2-wrapper passes ``serial_numbers.perform(context)``
(default ``'[]'``): a string for launch, not an empty list."""
from physai_lint.engine import CheckOptions, run_check

LAUNCH = """
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, OpaqueFunction
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node

def setup(context):
    serials = LaunchConfiguration('serials').perform(context)
    return [Node(package='demo', executable='n', name='n1',
                 parameters=[{'literal': '[]', 'performed': serials,
                              'port': LaunchConfiguration('port').perform(context),
                              'subst': LaunchConfiguration('serials'),
                              'subst_port': LaunchConfiguration('port')}])]

def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('serials', default_value='[]'),
        DeclareLaunchArgument('port', default_value='5000'),
        OpaqueFunction(function=setup),
    ])
"""


def test_python_strings_stay_strings(demo_graph):
    (node,) = demo_graph({"launch/a.launch.py": LAUNCH}, "launch/a.launch.py").values()
    params = node["parameters"]
    assert params["literal"] == "[]" and params["performed"] == "[]" and params["port"] == "5000"
    assert params["subst_port"] == 5000  # a substitution: YAML-typed


def test_only_the_substitution_is_an_empty_list(tmp_path, demo_package):
    pkg = demo_package({"launch/a.launch.py": LAUNCH})
    opts = CheckOptions(paths=[str(pkg / "launch/a.launch.py")], workspace=str(tmp_path), cache=False)
    found = [f for f in run_check(opts).findings if f.code == "P106"]
    assert [(f.span.line, f.message.split('"')[1]) for f in found] == [(12, "subst")]
    assert "is an empty list" in found[0].message


GUARDED = """
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, OpaqueFunction
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node

def setup(context):
    override = LaunchConfiguration('override')
    params = [{'rate': 2.0}]
    if override.perform(context) != '':
        params.append(override)
    return [Node(package='demo', executable='n', name='n1', parameters=params)]

def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('override', default_value=''),
        OpaqueFunction(function=setup),
    ])
"""


def test_a_file_added_under_a_guard_is_not_an_empty_path(tmp_path, demo_package):
    # zed-ros2-wrapper: the override file is added only when its argument is not empty
    pkg = demo_package({"launch/a.launch.py": GUARDED})
    opts = CheckOptions(paths=[str(pkg / "launch/a.launch.py")], workspace=str(tmp_path), cache=False)
    assert [f.message for f in run_check(opts).findings if f.code == "P101"] == []
    unguarded = GUARDED.replace("    if override.perform(context) != '':\n        params.append(override)",
                                "    params.append(override)")
    pkg = demo_package({"launch/a.launch.py": unguarded})
    assert [f.code for f in run_check(opts).findings if f.code == "P101"] == ["P101"]
