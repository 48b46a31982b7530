import os

import pytest

from physai_lint.workspace import UsageError, discover, find_workspace_root, is_launch_file


def rel(root, paths):
    return [os.path.relpath(p, root).replace(os.sep, "/") for p in paths]


def test_is_launch_file():
    assert is_launch_file("a.launch.py") and is_launch_file("a_launch.py")
    assert is_launch_file("x.launch.xml") and is_launch_file("launch.yaml") and is_launch_file("x.launch.yml")
    assert not is_launch_file("launch.py.bak") and not is_launch_file("a.py")


def test_discover_finds_launch_params_manifests(ws):
    d = discover([str(ws)])
    assert rel(ws, d.launch_files) == [
        "src/old_pkg/launch/sim.launch.py",
        "src/py_pkg/launch/demo.launch.py",
        "src/py_pkg/launch/other_launch.py",
    ]
    # XML and YAML launch files may be ROS 1 files or test data: their text decides
    assert rel(ws, d.undecided) == [
        "src/cpp_pkg/launch/bringup.launch.xml",
        "src/cpp_pkg/launch/bringup.launch.yaml",
        "src/py_pkg/launch/x.launch.xml",
    ]
    # only YAML mentioning ros__parameters; b.json is not YAML
    assert rel(ws, d.param_files) == ["src/cpp_pkg/config/driver.yaml", "src/py_pkg/config/a.yaml"]
    assert "src/cpp_pkg/package.xml" in rel(ws, d.package_xmls)
    assert all(p.startswith("/") and "\\" not in p for p in d.launch_files)
    assert d.explicit == []


def test_ignore_markers_and_skipped_dirs(ws):
    for sub in ("build/x", "install/x", "log/x", ".git/x"):
        (ws / sub).mkdir(parents=True)
        (ws / sub / "c.launch.py").write_text("# l")
    d = discover([str(ws)])
    names = rel(ws, d.launch_files)
    assert not any(n.startswith(("build/", "install/", "log/", ".git/", ".hidden/")) for n in names)
    assert not any("ignored" in n or "amentignored" in n for n in names)
    # CATKIN_IGNORE too, and the marker hides everything below
    (ws / "src/py_pkg/CATKIN_IGNORE").write_text("")
    assert not any("py_pkg" in n for n in rel(ws, discover([str(ws)]).launch_files))


def test_explicit_files_and_missing_path(ws):
    f = ws / "src/py_pkg/extra/unused.yaml"
    d = discover([str(f), str(ws / "src/py_pkg/launch/demo.launch.py")])
    assert rel(ws, d.undecided) == ["src/py_pkg/extra/unused.yaml"]  # a parameter or a launch file
    assert rel(ws, d.launch_files) == ["src/py_pkg/launch/demo.launch.py"]
    assert len(d.explicit) == 2
    with pytest.raises(UsageError) as exc:
        discover([str(ws / "nope")])
    assert "nope" in exc.value.message and "\n" not in exc.value.message


def test_gitignore(ws):
    (ws / ".git").mkdir()
    (ws / ".gitignore").write_text("# comment\n*.launch.xml\n!x.launch.xml\n/src/old_pkg/\nextra/\n")
    (ws / "src/cpp_pkg/.gitignore").write_text("config/\n")
    (ws / ".git/info").mkdir()
    (ws / ".git/info/exclude").write_text("other_launch.py\n")
    d = discover([str(ws)])
    names = rel(ws, d.launch_files + d.undecided)
    assert "src/cpp_pkg/launch/bringup.launch.xml" not in names
    assert "src/py_pkg/launch/x.launch.xml" in names  # negated
    assert "src/py_pkg/launch/other_launch.py" not in names  # info/exclude
    assert not any(n.startswith("src/old_pkg") for n in names)  # anchored dir
    assert "src/cpp_pkg/config/driver.yaml" not in rel(ws, d.param_files)  # nested .gitignore
    # switched off
    assert "src/cpp_pkg/launch/bringup.launch.xml" in rel(ws, discover([str(ws)], respect_gitignore=False).undecided)


def test_gitignore_above_the_walked_folder(ws):
    # the checkout's root and its .gitignore lie above the folder given: still read
    (ws / ".git").mkdir()
    (ws / ".gitignore").write_text("bringup.launch.xml\n")
    (ws / "src/cpp_pkg/.gitignore").write_text("config/\n")
    d = discover([str(ws / "src/cpp_pkg")])
    assert "src/cpp_pkg/launch/bringup.launch.xml" not in rel(ws, d.undecided)
    assert not any(n.startswith("src/cpp_pkg/config/") for n in rel(ws, d.param_files))
    assert rel(ws, d.undecided)  # the rest is found


def test_gitignore_outside_checkout_is_ignored(ws):
    (ws / ".gitignore").write_text("*.launch.py\n")  # no .git: not a checkout
    assert "src/py_pkg/launch/demo.launch.py" in rel(ws, discover([str(ws)]).launch_files)


def test_symlink_loop(ws):
    os.symlink(str(ws / "src"), str(ws / "src/py_pkg/loop"))
    os.symlink(str(ws / "src/cpp_pkg"), str(ws / "src/cpp_pkg/launch/self"))
    d = discover([str(ws)])
    # each real directory is visited once: no duplicates through the links
    reals = [os.path.realpath(p) for p in d.launch_files + d.undecided]
    assert len(reals) == len(set(reals))
    assert len(reals) == 6


def test_deterministic(ws):
    assert discover([str(ws / "src"), str(ws)]) == discover([str(ws)])


def test_find_workspace_root(ws, tmp_path, monkeypatch):
    f = ws / "src/py_pkg/launch/demo.launch.py"
    assert find_workspace_root([str(f)]) == str(ws)
    assert find_workspace_root([str(ws)]) == str(ws)
    # cpp_pkg has a src/ folder of C++ sources: not a workspace
    assert find_workspace_root([str(ws / "src/cpp_pkg/src/driver.cpp")]) == str(ws)
    lone = tmp_path / "lone"
    lone.mkdir()
    (lone / "a.launch.py").write_text("")
    monkeypatch.chdir(lone)
    assert find_workspace_root([str(lone / "a.launch.py")]) == str(lone)


def test_python_files_in_a_launch_folder_are_launch_files_when_they_define_the_entry(tmp_path):
    """``ros2 launch pkg file`` runs a file of any name: in a launch folder, a Python file that
    defines generate_launch_description is checked (and so includes it makes are not roots); a
    helper module there, or a generator that writes the function in a string, is not."""
    from physai_lint.engine import CheckOptions, run_check

    launch = tmp_path / "src" / "demo" / "launch"
    launch.mkdir(parents=True)
    (tmp_path / "src" / "demo" / "package.xml").write_text(
        '<package format="3"><name>demo</name><version>0.0.1</version><description>d</description>'
        '<maintainer email="a@b.c">m</maintainer><license>MIT</license>'
        '<export><build_type>ament_python</build_type></export></package>\n')
    (launch / "talker_launch.py").write_text(
        "from launch import LaunchDescription\n"
        "from launch.actions import LogInfo\n"
        "from launch.substitutions import LaunchConfiguration\n\n\n"
        "def generate_launch_description():\n"
        "    return LaunchDescription([LogInfo(msg=LaunchConfiguration('params_file'))])\n")
    (launch / "bringup_main.py").write_text(
        "import os\n"
        "from launch import LaunchDescription\n"
        "from launch.actions import DeclareLaunchArgument, IncludeLaunchDescription\n"
        "from launch.launch_description_sources import PythonLaunchDescriptionSource\n\n\n"
        "def generate_launch_description():\n"
        "    here = os.path.dirname(__file__)\n"
        "    return LaunchDescription([\n"
        "        DeclareLaunchArgument('params_file', default_value='a.yaml'),\n"
        "        IncludeLaunchDescription(PythonLaunchDescriptionSource(os.path.join(here, 'talker_launch.py'))),\n"
        "    ])\n")
    (launch / "helpers.py").write_text("def node_list():\n    return []\n")
    (launch / "writer.py").write_text(
        "TEMPLATE = '''\ndef generate_launch_description():\n    return None\n'''\n")
    d = discover([str(tmp_path)])
    assert rel(tmp_path, d.undecided) == ["src/demo/launch/bringup_main.py", "src/demo/launch/helpers.py",
                                          "src/demo/launch/writer.py"]
    report = run_check(CheckOptions(paths=[str(tmp_path / "src")], workspace=str(tmp_path), cache=False))
    assert sorted(rel(tmp_path, report.files)) == ["src/demo/launch/bringup_main.py",
                                                   "src/demo/launch/talker_launch.py"]
    # talker_launch.py reads params_file, which its includer declares: no L101, no L006 anywhere
    assert [f.code for f in report.findings if f.code in ("L101", "L006")] == []


def test_a_python_module_only_named_like_a_launch_file_is_left_out(tmp_path):
    """A ``launch.py`` that neither defines generate_launch_description nor imports launch (a
    deploy tool's task, ros2launch's own command module) is no launch file in a directory scan;
    named on the command line, it is checked as ros2 launch would load it."""
    from physai_lint.engine import CheckOptions, run_check

    tasks = tmp_path / "scripts" / "tasks"
    tasks.mkdir(parents=True)
    (tasks / "launch.py").write_text("import subprocess\n\n\ndef launch(host):\n    subprocess.run(['ssh', host])\n")
    (tasks / "broken_launch.py").write_text("from launch import LaunchDescription\n\n\ndef generate():\n"
                                             "    return LaunchDescription([])\n")
    report = run_check(CheckOptions(paths=[str(tmp_path / "scripts")], workspace=str(tmp_path), cache=False))
    assert [(os.path.basename(f.span.file), f.code) for f in report.findings] == [("broken_launch.py", "L006")]
    report = run_check(CheckOptions(paths=[str(tasks / "launch.py")], workspace=str(tmp_path), cache=False))
    assert [f.code for f in report.findings] == ["L006"]


def test_a_launch_helper_module_of_a_python_package_is_left_out(tmp_path):
    """``vrx_gz/launch.py`` beside an ``__init__.py`` imports launch and builds actions for the
    package's launch files to call: a module, not a file ros2 launch runs (no L006). A launch file
    in such a folder that defines the entry is still checked."""
    from physai_lint.engine import CheckOptions, run_check

    pkg = tmp_path / "src" / "sim" / "src" / "sim"
    pkg.mkdir(parents=True)
    (pkg / "__init__.py").write_text("")
    (pkg / "launch.py").write_text("from launch_ros.actions import Node\n\n\ndef spawn(name):\n"
                                   "    return [Node(package='sim', executable=name)]\n")
    (pkg / "demo_launch.py").write_text("from launch import LaunchDescription\n\n\ndef generate():\n"
                                        "    return LaunchDescription([])\n")
    report = run_check(CheckOptions(paths=[str(tmp_path / "src")], workspace=str(tmp_path), cache=False))
    assert [(os.path.basename(f.span.file), f.code) for f in report.findings] == [("demo_launch.py", "L006")]
