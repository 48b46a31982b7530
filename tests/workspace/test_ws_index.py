import os
import time

import pytest

from physai_lint.workspace import UsageError, build_package_index, released_packages


@pytest.fixture
def idx(ws):
    return build_package_index(str(ws))


def test_workspace_packages_and_ignore(idx, ws):
    assert sorted(idx.packages) == ["broken_pkg", "cpp_pkg", "invalid_pkg", "old_pkg", "py_nocfg", "py_pkg"]
    assert not idx.has_package("hidden_pkg")  # below COLCON_IGNORE
    p = idx.workspace_package("py_pkg")
    assert p.path == str(ws / "src/py_pkg") and p.package_xml == str(ws / "src/py_pkg/package.xml")
    assert p.build_type == "ament_python" and p.format == 3
    assert idx.origin("py_pkg") == "workspace"


def test_exec_depends_with_lines(idx):
    deps = idx.exec_depends("py_pkg")
    assert deps == {"rclpy": 8, "launch_ros": 9}  # conditional ROS 1 dep dropped, build deps ignored
    assert idx.exec_depends("old_pkg") == {"rclpy": 8}  # format 1 run_depend
    assert idx.exec_depends("nope") == {}


def test_broken_package_xml_is_a_problem_not_a_crash(idx, ws):
    assert not any("broken_pkg" in p for p, _, _ in idx.problems)  # packages are read when asked for
    idx.read_packages_holding([str(ws / "src/broken_pkg/launch/x.launch.py"), str(ws / "src/invalid_pkg/x")])
    probs = {os.path.basename(os.path.dirname(p)): (m, line) for p, m, line in idx.problems}
    assert "broken_pkg" in probs and "invalid xml" in probs["broken_pkg"][0].lower()
    assert probs["broken_pkg"][1] >= 1
    assert "invalid_pkg" in probs
    # still known by name (fewer follow-on unknown-package findings), marked invalid
    assert idx.has_package("broken_pkg") and not idx.workspace_package("broken_pkg").valid
    assert idx.exec_depends("invalid_pkg") == {"rclcpp": 6}


def test_ament_python_executables(idx):
    assert idx.executables("py_pkg") == frozenset({"talker", "listener"})
    p = idx.workspace_package("py_nocfg")
    # without setup.cfg console scripts land in bin/: launch cannot find them
    assert idx.executables("py_nocfg") == frozenset()
    assert p.executables_in_bin == frozenset({"runner"})
    assert not p.registers_in_index and idx.workspace_package("py_pkg").registers_in_index
    assert idx.plugins("py_pkg") == frozenset()


def test_data_files_install_mapping(idx, ws):
    share = idx.share_dir("py_pkg")
    assert share == str(ws / "install/py_pkg/share/py_pkg")
    assert idx.prefix_dir("py_pkg") == str(ws / "install/py_pkg")
    src = str(ws / "src/py_pkg")
    loc = idx.locate(share + "/launch/demo.launch.py")
    assert (loc.status, loc.source, loc.package) == ("ok", src + "/launch/demo.launch.py", "py_pkg")
    assert idx.locate(share + "/launch/x.launch.xml").status == "ok"  # [pxy][yma] glob
    assert idx.locate(share + "/config/a.yaml").source == src + "/config/a.yaml"
    assert idx.locate(share + "/package.xml").status == "ok"
    # recursive glob flattens into the destination
    assert idx.locate(share + "/all/c.yaml").source == src + "/config/nested/c.yaml"
    # config/*.yaml does not descend
    loc = idx.locate(share + "/config/nested/c.yaml")
    assert loc.status == "not_installed" and loc.source == src + "/config/nested/c.yaml"
    assert "data_files" in loc.install_hint and "'config', 'nested'" in loc.install_hint
    loc = idx.locate(share + "/extra/unused.yaml")
    assert loc.status == "not_installed"
    assert loc.install_hint == ("add (os.path.join('share', package_name, 'extra'), "
                                "glob('extra/*.yaml')) to data_files in setup.py")
    assert idx.locate(share + "/config/b.json").status == "not_installed"
    assert idx.locate(share + "/config/zzz.yaml").status == "missing"


def test_cmake_executables_plugins(idx):
    assert idx.executables("cpp_pkg") == frozenset({"driver_node", "filter_node", "tool.py", "fancy"})
    assert idx.plugins("cpp_pkg") == frozenset({"cpp_pkg::Filter", "cpp_pkg::Other"})
    # ament_cmake_auto: executables installed by ament_auto_package
    assert idx.executables("old_pkg") == frozenset({"auto_node"})


def test_cmake_install_mapping(idx, ws):
    share = idx.share_dir("cpp_pkg")
    src = str(ws / "src/cpp_pkg")
    assert idx.locate(share + "/launch/bringup.launch.xml").source == src + "/launch/bringup.launch.xml"
    assert idx.locate(share + "/config/driver.yaml").status == "ok"
    assert idx.locate(share + "/config").status == "ok"  # a directory
    assert idx.locate(share + "/rviz/view.rviz").source == src + "/rviz/view.rviz"
    assert idx.locate(share + "/package.xml").source == src + "/package.xml"  # ament_package()
    # trailing slash installs the contents; FILES_MATCHING / EXCLUDE
    assert idx.locate(share + "/robot/robot.urdf").source == src + "/urdf/robot.urdf"
    assert idx.locate(share + "/urdf/robot.urdf").status == "not_installed"
    assert idx.locate(share + "/robot/robot.xacro").status == "missing"
    assert idx.locate(share + "/robot/meshes/base.urdf").status == "missing"
    loc = idx.locate(share + "/maps/map.yaml")
    assert loc.status == "not_installed" and loc.source == src + "/maps/map.yaml"
    assert loc.install_hint == 'add "maps" to install(DIRECTORY ... DESTINATION share/${PROJECT_NAME}) in CMakeLists.txt'
    assert "install(FILES top.yaml" in idx.locate(share + "/top.yaml").install_hint
    assert idx.locate(share + "/launch/nope.launch.py").status == "missing"
    # generated file: the destination is unknown territory
    assert idx.locate(share + "/gen/generated.yaml").status == "unknown"
    # foreach over directories with trailing slash
    assert idx.locate(idx.share_dir("old_pkg") + "/meshes/a.stl").status == "ok"
    assert idx.locate(idx.share_dir("old_pkg") + "/launch/sim.launch.py").status == "ok"
    assert idx.locate(str(ws / "install/cpp_pkg/lib/cpp_pkg/tool.py")).source == src + "/scripts/tool.py"


def test_locate_source_tree_and_elsewhere(idx, ws, tmp_path):
    assert idx.locate(str(ws / "src/py_pkg/config/a.yaml")) == idx.locate(str(ws / "src/py_pkg/config/../config/a.yaml"))
    loc = idx.locate(str(ws / "src/py_pkg/config/a.yaml"))
    assert (loc.status, loc.package) == ("ok", "py_pkg")
    assert idx.locate(str(ws / "src/py_pkg/config/none.yaml")).status == "missing"
    assert idx.locate("/opt/ros/humble/share/nav2_bringup/params/nav2_params.yaml").status == "unknown"
    assert idx.locate("/opt/ros/humble/share/nav2_bringup/x").package == "nav2_bringup"
    assert idx.locate(str(tmp_path / "nowhere.yaml")).status == "unknown"


def test_parameter_yaml_linkage(idx, ws):
    src = str(ws / "src/cpp_pkg")
    assert idx.parameter_yaml_for("cpp_pkg", "driver_node") == [src + "/params/driver.yaml"]
    assert idx.parameter_yaml_for("cpp_pkg", "filter_node") == [src + "/params/filter.yaml"]
    assert idx.parameter_yaml_for("cpp_pkg", "cpp_pkg::Filter") == [src + "/params/filter.yaml"]
    assert idx.parameter_yaml_for("cpp_pkg", "helper") == []
    # generate_parameter_module, linked through the console script's module
    assert idx.parameter_yaml_for("py_pkg", "talker") == [str(ws / "src/py_pkg/params/talker.yaml")]
    assert idx.parameter_yaml_for("py_pkg", "listener") == []
    assert idx.workspace_package("py_pkg").parameter_modules == (
        ("talker_parameters", str(ws / "src/py_pkg/params/talker.yaml")),)


def test_distro_lookup(idx):
    assert not idx.has_package("move_group")
    assert idx.origin("moveit_ros_move_group") == "distro"
    assert idx.share_dir("moveit_ros_move_group") == "/opt/ros/humble/share/moveit_ros_move_group"
    assert idx.executables("moveit_ros_move_group") is None and idx.plugins("nav2_amcl") is None
    assert idx.has_package("nav2_amcl")
    assert "nav2_amcl" not in released_packages("rolling")
    assert "nav2_amcl" in released_packages("jazzy")
    rolling = build_package_index(str(idx.workspace_root), distro="rolling")
    assert not rolling.has_package("nav2_amcl") and rolling.has_package("py_pkg")
    assert idx.origin("definitely_not_a_pkg") is None and idx.share_dir("definitely_not_a_pkg") is None
    with pytest.raises(UsageError):
        build_package_index(str(idx.workspace_root), distro="noetic")


def test_suggest(idx):
    assert idx.suggest("py_pgk")[0] == "py_pkg"
    assert "moveit_ros_move_group" in idx.suggest("moveit_ros_movegroup")
    names = idx.package_names()
    assert list(names) == sorted(set(names)) and "py_pkg" in names and "rclcpp" in names
    assert idx.package_names() is names  # one tuple while the names stay the same


def _fake_prefix(root, name, exes=(), plugins=()):
    (root / "share/ament_index/resource_index/packages").mkdir(parents=True, exist_ok=True)
    (root / "share/ament_index/resource_index/packages" / name).write_text("")
    (root / "share" / name / "config").mkdir(parents=True)
    (root / "share" / name / "config/p.yaml").write_text("a: 1\n")
    lib = root / "lib" / name
    lib.mkdir(parents=True)
    for e in exes:
        (lib / e).write_text("#!/bin/sh\n")
        os.chmod(lib / e, 0o755)
    (lib / "data.txt").write_text("not executable")
    if plugins:
        (root / "share/ament_index/resource_index/rclcpp_components").mkdir(parents=True, exist_ok=True)
        (root / "share/ament_index/resource_index/rclcpp_components" / name).write_text(
            "".join(f"{p};lib/libx.so\n" for p in plugins))


def test_ament_prefix_path(ws, tmp_path):
    over, under = tmp_path / "over", tmp_path / "under"
    _fake_prefix(over, "my_driver", exes=("driver",), plugins=("my::Driver",))
    _fake_prefix(under, "my_driver", exes=("old",))
    _fake_prefix(under, "py_pkg")  # the workspace overlays installed packages
    idx = build_package_index(str(ws), ament_prefix_path=os.pathsep.join([str(over), str(under), ""]))
    assert idx.origin("my_driver") == "installed" and idx.origin("py_pkg") == "workspace"
    assert idx.share_dir("my_driver") == str(over / "share/my_driver")
    assert idx.prefix_dir("my_driver") == str(over)
    assert idx.executables("my_driver") == frozenset({"driver"})
    assert idx.plugins("my_driver") == frozenset({"my::Driver"})
    assert idx.locate(str(over / "share/my_driver/config/p.yaml")).status == "ok"
    assert idx.locate(str(over / "share/my_driver/config/q.yaml")).status == "missing"
    assert idx.locate(str(over / "share/my_driver/config/q.yaml")).package == "my_driver"
    assert "my_driver" in idx.package_names()


def test_read_text(idx, ws, tmp_path):
    p = ws / "src/py_pkg/config/a.yaml"
    assert "ros__parameters" in idx.read_text(str(p))
    b = tmp_path / "bin.yaml"
    b.write_bytes(b"a: 1\x00\n")
    assert idx.read_text(str(b)) is None
    bad = tmp_path / "latin.yaml"
    bad.write_bytes(b"a: \xff\n")
    assert idx.read_text(str(bad)) is None
    assert idx.read_text(str(tmp_path / "none")) is None
    p.write_text("changed")
    assert "ros__parameters" in idx.read_text(str(p))  # cached for the run


def test_index_speed_100_packages(tmp_path):
    src = tmp_path / "big/src"
    for i in range(100):
        d = src / f"pkg_{i:03d}"
        (d / "launch").mkdir(parents=True)
        (d / "config").mkdir()
        (d / "launch/a.launch.py").write_text("#\n")
        (d / "config/p.yaml").write_text("/**:\n  ros__parameters: {}\n")
        bt = "ament_python" if i % 2 else "ament_cmake"
        (d / "package.xml").write_text(
            f'<package format="3"><name>pkg_{i:03d}</name><version>1.0.0</version><description>d</description>'
            f'<maintainer email="dev@example.com">m</maintainer><license>MIT</license><depend>rclcpp</depend>'
            f'<exec_depend>launch_ros</exec_depend><export><build_type>{bt}</build_type></export></package>')
        if i % 2:
            (d / "setup.cfg").write_text(f"[develop]\nscript_dir=$base/lib/pkg_{i:03d}\n")
            (d / "setup.py").write_text(
                "import os\nfrom glob import glob\nfrom setuptools import setup\n"
                f"package_name = 'pkg_{i:03d}'\n"
                "setup(name=package_name, data_files=[('share/' + package_name, ['package.xml']),"
                "(os.path.join('share', package_name, 'launch'), glob('launch/*.launch.py'))],"
                "entry_points={'console_scripts': ['n = p.n:main']})\n")
        else:
            (d / "CMakeLists.txt").write_text(
                f"project(pkg_{i:03d})\nadd_executable(n src/n.cpp)\n"
                "install(TARGETS n DESTINATION lib/${PROJECT_NAME})\n"
                "install(DIRECTORY launch config DESTINATION share/${PROJECT_NAME})\nament_package()\n")
    build_package_index(str(tmp_path / "big"))  # warm imports (catkin_pkg pulls in pyparsing)
    t = time.perf_counter()
    idx = build_package_index(str(tmp_path / "big"))
    dt = time.perf_counter() - t
    print(f"\nbuild_package_index: 100 packages in {dt * 1000:.1f} ms")
    assert len(idx.packages) == 100
    assert idx.executables("pkg_001") == frozenset({"n"}) and idx.executables("pkg_000") == frozenset({"n"})


def test_suggest_executable_taken_for_package(idx):
    assert idx.suggest("move_group")[0] == "moveit_ros_move_group"
    assert idx.suggest("rviz")[0] == "rviz2"


def test_hint_names_where_a_file_is_installed_instead(idx, tmp_path):
    share = idx.share_dir("cpp_pkg")
    # install(DIRECTORY urdf/ DESTINATION share/${PROJECT_NAME}/robot): robot/robot.urdf, not urdf/
    hint = idx.locate(share + "/urdf/robot.urdf").install_hint
    assert hint.startswith('it is installed as "share/cpp_pkg/robot/robot.urdf" instead (CMakeLists.txt:')
    assert hint.endswith('install it to "share/cpp_pkg/urdf"')
    ws = tmp_path / "w"
    xml = ('<package format="3"><name>{0}</name><version>0.0.0</version><description>d</description>'
           '<maintainer email="m@example.com">m</maintainer><license>MIT</license>'
           '<export><build_type>{1}</build_type></export></package>')
    (ws / "src/c/config").mkdir(parents=True)
    (ws / "src/c/package.xml").write_text(xml.format("c", "ament_cmake"))
    (ws / "src/c/config/p.yaml").write_text("a: 1\n")
    (ws / "src/c/CMakeLists.txt").write_text(
        "cmake_minimum_required(VERSION 3.8)\nproject(c)\nfind_package(ament_cmake REQUIRED)\n"
        "install(DIRECTORY config/ DESTINATION share/${PROJECT_NAME})\nament_package()\n")
    (ws / "src/p/p/config").mkdir(parents=True)
    (ws / "src/p/package.xml").write_text(xml.format("p", "ament_python"))
    (ws / "src/p/config").mkdir()
    (ws / "src/p/config/q.yaml").write_text("a: 1\n")
    (ws / "src/p/setup.py").write_text(
        "from glob import glob\nfrom setuptools import setup\npackage_name = 'p'\n"
        "setup(name=package_name, data_files=[\n"
        "    ('share/' + package_name, ['package.xml'] + glob('config/*.yaml')),\n])\n")
    index = build_package_index(str(ws))
    loc = index.locate(index.share_dir("c") + "/config/p.yaml")
    assert loc.status == "not_installed"
    assert loc.install_hint == (
        'it is installed as "share/c/p.yaml" instead: install(DIRECTORY config/ ...) at CMakeLists.txt:4 '
        'installs what is in "config" (the trailing slash), not the folder; write "config" without the slash')
    loc = index.locate(index.share_dir("p") + "/config/q.yaml")
    assert loc.status == "not_installed"
    assert loc.install_hint == ('it is installed as "share/p/q.yaml" instead (data_files at setup.py:4): '
                                "install it to os.path.join('share', package_name, 'config')")
