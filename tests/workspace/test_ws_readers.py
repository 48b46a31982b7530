"""The static readers on their own: CMake tokenizer/interpreter, setup.py evaluation, globbing."""
from physai_lint.workspace._glob import glob_files
from physai_lint.workspace.cmake import read_cmake_package, tokenize
from physai_lint.workspace.setup_py import read_setup_py


def test_tokenize_comments_quotes_brackets_lines():
    cmds = tokenize(
        'project(p) # c\n'
        '#[==[ block\ninstall(FILES x DESTINATION y)\n]==]\n'
        'set(A "a b\\"c" [[raw ${X}]] unq\\ uoted)\n'
        'if((A AND B) OR C)\nendif()\n'
        'message("multi\nline")\nfoo ( bar )\n')
    assert [c.name for c in cmds] == ["project", "set", "if", "endif", "message", "foo"]
    s = cmds[1]
    assert [a.value for a in s.args] == ["A", 'a b"c', "raw ${X}", "unq uoted"]
    assert [a.quoted for a in s.args] == [False, True, True, False]
    assert s.line == 5 and cmds[2].line == 6 and cmds[5].line == 10
    assert [a.value for a in cmds[2].args] == ["(", "A", "AND", "B", ")", "OR", "C"]


def test_tokenize_never_raises_on_garbage():
    for text in ["project(", 'set(A "unterminated', "#[[ open", ")))(((", "[[", "\\"]:
        tokenize(text)


def _cmake(tmp_path, text, files=()):
    for f in files:
        p = tmp_path / f
        p.parent.mkdir(parents=True, exist_ok=True)
        p.write_text("x")
    return read_cmake_package(str(tmp_path), "pkg", text)


def test_cmake_variables_lists_and_foreach(tmp_path):
    info = _cmake(tmp_path, """
project(pkg)
set(NODES a;b)
list(APPEND NODES c)
set(CACHED x CACHE STRING "doc")
foreach(n ${NODES})
  add_executable(${n}_node src/${n}.cpp)
  install(TARGETS ${n}_node DESTINATION lib/${PROJECT_NAME})
endforeach()
foreach(d IN ITEMS launch config)
  install(DIRECTORY ${d} DESTINATION share/${PROJECT_NAME}/)
endforeach()
install(TARGETS ${UNKNOWN_VAR} DESTINATION lib/${PROJECT_NAME})
""")
    assert info.executables == {"a_node", "b_node", "c_node"}
    assert not info.executables_complete  # the unknown target
    assert [(r.dest, r.source.rsplit("/", 1)[-1]) for r in info.rules] == [
        ("share/pkg", "launch"), ("share/pkg", "config")]
    assert info.complete


def test_cmake_autoware_ament_auto_package_installs_to_share(tmp_path):
    # autoware_cmake's drop-in replacement for ament_auto_package (autoware_core uses it)
    info = _cmake(tmp_path, "project(pkg)\nament_auto_add_executable(n src/n.cpp)\n"
                            "autoware_ament_auto_package(INSTALL_TO_SHARE config launch)\n")
    assert [(r.dest, r.source, r.contents_only) for r in info.rules if r.kind == "directory"] == [
        ("share/pkg", str(tmp_path / "config"), False), ("share/pkg", str(tmp_path / "launch"), False)]
    assert any(r.source == str(tmp_path / "package.xml") for r in info.rules)
    assert info.executables == {"n"}


def test_cmake_project_name_differs_from_package(tmp_path):
    # launch looks in lib/<package name>: a different project() name installs elsewhere
    info = _cmake(tmp_path, "project(other)\nadd_executable(n x.cpp)\n"
                            "install(TARGETS n DESTINATION lib/${PROJECT_NAME})\n")
    assert info.executables == set()


def test_cmake_user_function_and_subdirectory(tmp_path):
    (tmp_path / "sub").mkdir()
    (tmp_path / "sub/CMakeLists.txt").write_text("install(DIRECTORY cfg/ DESTINATION share/pkg/cfg)\n")
    info = _cmake(tmp_path, "project(pkg)\nadd_subdirectory(sub)\n"
                            "function(my_install)\n install(DIRECTORY x DESTINATION share)\nendfunction()\n")
    assert [(r.dest, r.source, r.contents_only) for r in info.rules] == [
        ("share/pkg/cfg", str(tmp_path / "sub/cfg"), True)]
    assert info.complete
    info2 = _cmake(tmp_path, "function(my_install)\n install(DIRECTORY x DESTINATION share)\nendfunction()\nmy_install()\n")
    assert not info2.complete


def test_cmake_install_prefix_destination(tmp_path):
    info = _cmake(tmp_path, "project(pkg)\ninstall(FILES a.yaml DESTINATION ${CMAKE_INSTALL_PREFIX}/share/pkg/ RENAME b.yaml)\n")
    r = info.rules[0]
    assert (r.dest, r.rename) == ("share/pkg", "b.yaml")


def test_setup_py_variants(tmp_path):
    files = frozenset({"launch/a.launch.py", "launch/.hidden.launch.py", "config/x.yaml",
                       "setup.py", "mod/node.py"})
    text = """
from os import path
import glob as g
from setuptools import setup
pkg = 'pkg'
extra = [('share/{}/cfg'.format(pkg), g.glob('config/*'))]
setup(
    name=pkg,
    data_files=[
        (path.join('share', pkg), g.glob('launch/*')),
        ('share/%s' % pkg, ['package.xml']),
        *extra,
    ] + [(f'share/{pkg}/more', [p]) for p in ['config/x.yaml']],
    entry_points={'console_scripts': 'node = mod.node:main'},
)
"""
    info = read_setup_py(str(tmp_path), "pkg", files, text)
    got = sorted((r.dest, r.source[len(str(tmp_path)) + 1:]) for r in info.rules)
    assert got == [("share/pkg", "launch/a.launch.py"), ("share/pkg", "package.xml"),
                   ("share/pkg/cfg", "config/x.yaml"), ("share/pkg/more", "config/x.yaml")]
    assert info.complete
    assert info.executables_in_bin == {"node"}  # no setup.cfg


def test_setup_py_unknown_data_files_is_incomplete(tmp_path):
    text = """
import os
from setuptools import setup
data_files = []
for root, dirs, files in os.walk('launch'):
    data_files.append((root, files))
setup(name='pkg', data_files=data_files)
"""
    assert not read_setup_py(str(tmp_path), "pkg", frozenset(), text).complete
    assert not read_setup_py(str(tmp_path), "pkg", frozenset(), "setup(name=\n").complete
    helper = "from setuptools import setup\nsetup(name='pkg', data_files=get_files())\n"
    assert not read_setup_py(str(tmp_path), "pkg", frozenset(), helper).complete


def test_glob_files():
    files = frozenset({"launch/a.launch.py", "launch/b.launch.xml", "launch/sub/c.launch.py",
                       "launch/.d.launch.py", "config/x.yaml"})
    assert glob_files("launch/*.launch.py", files) == ["launch/a.launch.py"]
    assert glob_files("launch/*launch.[pxy][yma]*", files) == ["launch/a.launch.py", "launch/b.launch.xml"]
    assert glob_files("launch/**/*.py", files, recursive=True) == ["launch/a.launch.py", "launch/sub/c.launch.py"]
    assert glob_files("launch/**/*.py", files, recursive=False) == ["launch/sub/c.launch.py"]
    assert glob_files("./config/x.yaml", files) == ["config/x.yaml"]
    assert glob_files("launch/.*", files) == ["launch/.d.launch.py"]


def test_cmake_subdirectory_scope_does_not_leak_project_name(tmp_path):
    # slam_toolbox-style: a vendored library with its own project() in a subdirectory must not
    # rename the parent's ${PROJECT_NAME} (CMake gives a subdirectory a copy of the scope).
    (tmp_path / "lib/sdk").mkdir(parents=True)
    (tmp_path / "lib/sdk/CMakeLists.txt").write_text(
        "project(sdk)\nset(EXTRA yes)\ninstall(DIRECTORY include/ DESTINATION include)\n")
    info = _cmake(tmp_path, "project(pkg)\nadd_subdirectory(lib/sdk)\n"
                            "add_executable(node_a src/a.cpp)\n"
                            "install(TARGETS node_a RUNTIME DESTINATION lib/${PROJECT_NAME})\n"
                            "install(DIRECTORY config DESTINATION share/${PROJECT_NAME})\n")
    assert info.executables == {"node_a"}
    assert ("share/pkg", str(tmp_path / "config")) in [(r.dest, r.source) for r in info.rules]


def test_cmake_output_name_renames_the_installed_executable(tmp_path):
    info = _cmake(tmp_path, """
project(pkg)
add_executable(${PROJECT_NAME}_node src/joy.cpp)
set_target_properties(${PROJECT_NAME}_node PROPERTIES OUTPUT_NAME teleop_node PREFIX "")
add_executable(runner src/run.cpp)
set_property(TARGET runner PROPERTY RUNTIME_OUTPUT_NAME run)
set_target_properties(runner PROPERTIES OUTPUT_NAME ignored SUFFIX .bin)
add_executable(plain src/plain.cpp)
install(TARGETS ${PROJECT_NAME}_node runner plain DESTINATION lib/${PROJECT_NAME})
""", ("src/joy.cpp", "src/run.cpp", "src/plain.cpp"))
    assert info.executables == {"teleop_node", "run.bin", "plain"}
    assert info.executables_complete
    assert {exe: [p.rsplit("/", 1)[-1] for p in srcs] for exe, srcs in info.sources.items()} == {
        "teleop_node": ["joy.cpp"], "run.bin": ["run.cpp"], "plain": ["plain.cpp"]}


def test_cmake_unknown_output_name_makes_the_executables_incomplete(tmp_path):
    info = _cmake(tmp_path, """
project(pkg)
add_executable(node src/a.cpp)
set_target_properties(node PROPERTIES OUTPUT_NAME ${NAME_FROM_CACHE})
install(TARGETS node DESTINATION lib/${PROJECT_NAME})
""")
    assert info.executables == set() and not info.executables_complete


def test_cmake_target_properties_as_cmake_applies_them(tmp_path):
    info = _cmake(tmp_path, """
project(pkg)
add_executable(pre src/a.cpp)
set_target_properties(pre PROPERTIES PREFIX lib_)
add_executable(grown src/a.cpp)
set_target_properties(grown PROPERTIES OUTPUT_NAME x)
set_property(TARGET grown APPEND_STRING PROPERTY OUTPUT_NAME _y)
add_executable(unset src/a.cpp)
set_target_properties(unset PROPERTIES OUTPUT_NAME gone)
set_property(TARGET unset PROPERTY OUTPUT_NAME)
add_executable(empty src/a.cpp)
set_target_properties(empty PROPERTIES RUNTIME_OUTPUT_NAME "" OUTPUT_NAME other)
add_executable(tool src/a.cpp)
set_target_properties(tool PROPERTIES OUTPUT_NAME tool_cpp)
install(TARGETS pre grown unset empty tool DESTINATION lib/${PROJECT_NAME})
install(PROGRAMS scripts/tool DESTINATION lib/${PROJECT_NAME})
""", ("src/a.cpp", "scripts/tool"))
    assert info.executables == {"lib_pre", "x_y", "unset", "empty", "tool_cpp", "tool"}
    assert info.executables_complete


def test_cmake_a_list_output_name_makes_the_executables_incomplete(tmp_path):
    info = _cmake(tmp_path, """
project(pkg)
add_executable(node src/a.cpp)
set_target_properties(node PROPERTIES OUTPUT_NAME x)
set_property(TARGET node APPEND PROPERTY OUTPUT_NAME y)
install(TARGETS node DESTINATION lib/${PROJECT_NAME})
""")
    assert info.executables == set() and not info.executables_complete


def test_cmake_tells_an_executables_own_sources_from_its_libraries(tmp_path):
    info = _cmake(tmp_path, """
project(pkg)
add_library(core src/filter.cpp src/gps.cpp)
add_executable(filter_node src/filter_node.cpp)
target_link_libraries(filter_node core)
add_library(procs SHARED src/rectify.cpp)
target_link_libraries(procs core)
rclcpp_components_register_node(procs PLUGIN "pkg::Rectify" EXECUTABLE rectify_node)
ament_add_gtest_executable(test_filter test/test_filter.cpp)
target_link_libraries(test_filter core)
install(TARGETS filter_node test_filter DESTINATION lib/${PROJECT_NAME})
""")
    def names(paths):
        return [p.rsplit("/", 1)[-1] for p in paths]

    assert {k: names(v) for k, v in info.sources.items()} == {
        "filter_node": ["filter_node.cpp", "filter.cpp", "gps.cpp"],
        "rectify_node": ["rectify.cpp", "filter.cpp", "gps.cpp"],
        "pkg::Rectify": ["rectify.cpp", "filter.cpp", "gps.cpp"],
        "test_filter": ["test_filter.cpp", "filter.cpp", "gps.cpp"]}
    # what a linked library brings (for a component: all), and the class known to run
    assert {k: names(v) for k, v in info.library_sources.items()} == {
        "filter_node": ["filter.cpp", "gps.cpp"], "test_filter": ["filter.cpp", "gps.cpp"],
        "rectify_node": ["rectify.cpp", "filter.cpp", "gps.cpp"],
        "pkg::Rectify": ["rectify.cpp", "filter.cpp", "gps.cpp"]}
    assert info.source_roots == {"rectify_node": ["pkg::Rectify"], "pkg::Rectify": ["pkg::Rectify"]}


def test_setup_py_ros_version_branches(tmp_path):
    # a package shared with ROS 1 calls setup() in both branches: colcon on ROS 2 runs the second
    for test in ("ROS_VERSION == 2", "int(os.environ['ROS_VERSION']) == 2", "os.getenv('ROS_VERSION') == '2'",
                 "ROS_VERSION != 1"):
        text = f"""
import os
from glob import glob
ROS_VERSION = int(os.environ['ROS_VERSION'])
if ROS_VERSION == 1 and False:
    pass
if {test}:
    from setuptools import setup
    package_name = 'pkg'
    setup(name=package_name, packages=[package_name],
          data_files=[(os.path.join('share', package_name, 'launch'), glob('launch/*.launch.py'))])
else:
    from distutils.core import setup
    setup(name='pkg', packages=['pkg'], package_dir={{'': 'src'}})
"""
        info = read_setup_py(str(tmp_path), "pkg", frozenset({"launch/a.launch.py"}), text)
        assert info.complete, test
        got = sorted((r.dest, r.source[len(str(tmp_path)) + 1:]) for r in info.rules)
        assert got == [("share/pkg/launch", "launch/a.launch.py")], test


def test_ament_python_install_package_installs_setup_cfg_scripts_to_its_destination(tmp_path):
    # controller_manager: ament_python_install_package(... SCRIPTS_DESTINATION lib/${PROJECT_NAME})
    # installs the console scripts of the package's setup.cfg (setup.py install_scripts) there
    (tmp_path / "setup.cfg").write_text(
        "[options.entry_points]\nconsole_scripts =\n    spawner = pkg.spawner:main\n"
        "    unspawner = pkg.unspawner:main\n")
    info = _cmake(tmp_path, "project(pkg)\n"
                            "ament_python_install_package(${PROJECT_NAME} SCRIPTS_DESTINATION lib/${PROJECT_NAME})\n"
                            "ament_package()\n")
    assert {"spawner", "unspawner"} <= info.executables and info.executables_complete
    info = _cmake(tmp_path, "project(pkg)\nament_python_install_package(${PROJECT_NAME} "
                            "SCRIPTS_DESTINATION bin)\nament_package()\n")
    assert "spawner" not in info.executables  # not where ros2 run looks
    info = _cmake(tmp_path, "project(pkg)\nament_python_install_package(${PROJECT_NAME})\nament_package()\n")
    assert "spawner" not in info.executables  # without a destination no script is installed


def test_cmake_files_installed_with_execute_permission_are_programs(tmp_path):
    info = _cmake(tmp_path, """
project(pkg)
install(FILES scripts/service_node.py scripts/run_demo
        DESTINATION lib/${PROJECT_NAME}
        PERMISSIONS OWNER_EXECUTE OWNER_WRITE OWNER_READ GROUP_EXECUTE GROUP_READ)
install(FILES scripts/helper.py DESTINATION lib/${PROJECT_NAME})
install(PROGRAMS scripts/tool.sh DESTINATION lib/${PROJECT_NAME})
""", ("scripts/service_node.py", "scripts/run_demo", "scripts/helper.py", "scripts/tool.sh"))
    # a plain install(FILES) keeps mode 644: launch cannot run it
    assert info.executables == {"service_node.py", "run_demo", "tool.sh"}
    # Python code (by extension, or a script without one whose first line the store reads) is
    # the interface's source; a shell script is not
    assert sorted(info.sources) == ["run_demo", "service_node.py"]
