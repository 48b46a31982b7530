"""Fixtures shared by test folders."""
from __future__ import annotations

import json
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest

DEMO_PACKAGE_XML = """<package format="3"><name>demo</name><version>0.0.0</version><description>d</description>
<maintainer email="m@example.com">a</maintainer><license>MIT</license>
<export><build_type>ament_cmake</build_type></export></package>
"""
DEMO_CMAKE = "project(demo)\ninstall(DIRECTORY launch config DESTINATION share/${PROJECT_NAME})\n"


@pytest.fixture
def demo_package(tmp_path: Path) -> Callable[[dict[str, str]], Path]:
    """Write the ament_cmake package ``src/demo`` (installing launch/ and config/) with ``files``
    (paths relative to the package); returns the package folder. The workspace is ``tmp_path``."""

    def write(files: dict[str, str]) -> Path:
        pkg = tmp_path / "src" / "demo"
        for rel, text in {"package.xml": DEMO_PACKAGE_XML, "CMakeLists.txt": DEMO_CMAKE, **files}.items():
            (pkg / rel).parent.mkdir(parents=True, exist_ok=True)
            (pkg / rel).write_text(text)
        return pkg

    return write


@pytest.fixture
def demo_nodes(demo_package: Callable[[dict[str, str]], Path]) -> Callable[..., Path]:
    """``demo_nodes(sources, files)``: the demo package building one executable per entry of
    ``sources`` (name -> C++ text, in ``src/<name>.cpp``) into lib/demo, with ``files``."""

    def write(sources: dict[str, str], files: dict[str, str]) -> Path:
        exes = " ".join(sources)
        cmake = "project(demo)\n" + "".join(f"add_executable({e} src/{e}.cpp)\n" for e in sources) + (
            f"install(TARGETS {exes} DESTINATION lib/${{PROJECT_NAME}})\n"
            "install(DIRECTORY launch DESTINATION share/${PROJECT_NAME})\n")
        return demo_package({"CMakeLists.txt": cmake, **{f"src/{e}.cpp": t for e, t in sources.items()}, **files})

    return write


@pytest.fixture
def demo_graph(tmp_path: Path, demo_package: Callable[[dict[str, str]], Path]
               ) -> Callable[..., dict[str, dict[str, Any]]]:
    """``demo_graph(files, entry, distro=..., **launch_args)``: the graph JSON nodes of
    ``src/demo/<entry>`` by name, in a workspace holding only the demo package with ``files``."""
    from physai_lint import api
    from physai_lint.engine import CheckOptions

    def graph(files: dict[str, str], entry: str, distro: str = "humble", **launch_args: str
              ) -> dict[str, dict[str, Any]]:
        path = str(demo_package(files) / entry)
        opts = CheckOptions(paths=[path], launch_args=launch_args, workspace=str(tmp_path), distro=distro)
        return {n["name"]: n for n in json.loads(api.graph(opts, path, "json"))["nodes"]}

    return graph


@pytest.fixture
def demo_findings(tmp_path: Path, demo_package: Callable[[dict[str, str]], Path]
                  ) -> Callable[..., list[tuple[int, str]]]:
    """``demo_findings(files, entry, code, distro="humble")``: (line, message) of the ``code``
    findings, sorted, of checking ``src/demo/<entry>`` in a workspace holding only the demo package
    with ``files``."""
    from physai_lint.engine import CheckOptions, run_check

    def check(files: dict[str, str], entry: str, code: str, distro: str = "humble") -> list[tuple[int, str]]:
        opts = CheckOptions(paths=[str(demo_package(files) / entry)], workspace=str(tmp_path), cache=False,
                            distro=distro)
        return sorted((f.span.line, f.message) for f in run_check(opts).findings if f.code == code)

    return check


COMPONENT_LAUNCH = """from launch import LaunchDescription
from launch.substitutions import PathJoinSubstitution
from launch_ros.actions import ComposableNodeContainer, Node
from launch_ros.descriptions import ComposableNode
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    params = PathJoinSubstitution([FindPackageShare('demo'), 'config', 'cam.yaml'])
    return LaunchDescription([
        ComposableNodeContainer(
            name='container', namespace='{namespace}', package='rclcpp_components',
            executable='component_container'{container},
            composable_node_descriptions=[
                ComposableNode({component}),
            ]),{after}
    ])
"""


@pytest.fixture
def component_launch() -> Callable[..., str]:
    """``component_launch(component, namespace='', container='', after='')``: a ``.launch.py`` starting
    ``/<namespace>/container`` with one ``ComposableNode(<component>)``; ``params`` names the demo
    package's installed ``config/cam.yaml``, ``container`` adds keyword arguments to the container
    (", parameters=[params]") and ``after`` actions after it."""

    def text(component: str, namespace: str = "", container: str = "", after: str = "") -> str:
        return COMPONENT_LAUNCH.format(component=component, namespace=namespace, container=container,
                                       after=after)

    return text
