"""What a file is, from its name and its text: the frontend that loads it, and whether a file its
name does not decide is a ROS 2 launch file, a parameter file or neither.

``ros2 launch`` loads a file of any name (launch ``launch_description_sources/
any_launch_file_utilities.py :: get_launch_description_from_any_launch_file``): a ``.py`` file
with the Python loader first, any other with the frontend parsers first (those claiming the
extension, then the rest: ``frontend/parser.py :: Parser.load``; launch_xml and launch_yaml both
claim ``.launch``) and Python last. ``launch_format`` decides the same from the text.

A directory holds more than launch files: ``*.launch`` files are mostly ROS 1 roslaunch XML (root
``<launch>`` as well), and a ``*_launch.yaml`` may be a test matrix. ``classify`` takes such a file
only when its text says it is ROS 2 launch; an explicitly named file is taken unless it is ROS 1.

Everything here is a pure function of the text the file store has read anyway, made of regular
expression searches and no parse (each file is parsed once, by its frontend).
"""
from __future__ import annotations

import re
from collections.abc import Iterator
from dataclasses import dataclass
from typing import Literal

Format = Literal["python", "xml", "yaml"]
Kind = Literal["launch", "params"]

# Named like a launch file: ros2launch ``api.py :: is_launch_file`` takes every extension its
# parsers claim ("launch.py", "launch.xml", "launch.yaml", "launch.yml", "xml", "yaml", ...).
LAUNCH_SUFFIXES = ("launch.py", "launch.xml", "launch.yaml", "launch.yml")
YAML_SUFFIXES = (".yaml", ".yml")

# A ``ros__parameters`` mapping key (rcl's parser takes any key starting with it: parse.c ::
# PARAMS_KEY, compared with strncmp), in block style at the start of a line or in flow style after
# ``{`` or ``,``; not the word in a comment (``# In ComposableNode ros__parameters are not
# supported``) or in a value.
_PARAMS_KEY = r"""['"]?ros__parameters[^\s:'"]*['"]?[ \t]*:(?:[ \t\r]|$)"""
# block style, or flow style on a line that no comment has started
_PARAMS_RX = (r"(?m)^[ \t]*(?:-[ \t]+)*(?:\?[ \t]+)?" + _PARAMS_KEY + "|" +
              r"^[^#\n]*[{,][ \t]*" + _PARAMS_KEY)
_PARAMS = re.compile(_PARAMS_RX)
_PARAMS_B = re.compile(_PARAMS_RX.encode())


def has_params_key(data: str | bytes) -> bool:
    """Whether YAML text has a ``ros__parameters`` key: what makes a YAML file a parameter file."""
    if isinstance(data, bytes):
        return b"ros__parameters" in data and _PARAMS_B.search(data) is not None
    return "ros__parameters" in data and _PARAMS.search(data) is not None


_BY_EXTENSION: dict[str, Format] = {".py": "python", ".xml": "xml", ".yaml": "yaml", ".yml": "yaml"}

_MARKUP = re.compile(r"\ufeff?\s*<")
_YAML_LAUNCH = re.compile(r"""^(?:launch|'launch'|"launch")[ \t]*:(?:[ \t]|$)""", re.MULTILINE)
_PROLOG = re.compile(r"\s+|<\?.*?\?>|<!--.*?-->|<!DOCTYPE[^>]*>", re.DOTALL)
_ROOT = re.compile(r"<([A-Za-z_][\w.:-]*)")
# ROS 2 has <node exec=>, $(var) and the launch_ros tags; ROS 1 has <node type=>, $(find), $(arg),
# $(optenv), <rosparam>, <machine> and <test> (roslaunch XML; SEMANTICS.md 5 and 6). One pass,
# linear in the text even on hostile input: a comment or a node's start tag is consumed whole (to
# the end of the text when it is not closed), so nothing is scanned twice.
_SUBST_ROS2 = r"\$\((?:var|find-pkg-share|find-pkg-prefix|exec-in-pkg|find-exec)\s"
_SUBST_ROS1 = r"\$\((?:find|arg|optenv)\s"
_MARKERS = re.compile(rf"""
    <!--(?:.*?-->|.*)
  | <(?:node|node_container)\b(?P<node>[^>]*)
  | (?P<ros2> {_SUBST_ROS2}
      | <(?:let|executable|push-ros-namespace|push_ros_namespace|set_remap|set_parameter
          |set_parameters_from_file|composable_node|load_composable_node|set_env|unset_env
          |append_env|timer|ros_timer|set_use_sim_time)[\s/>] )
  | (?P<ros1> {_SUBST_ROS1} | <(?:rosparam|machine|test)[\s/>] )
""", re.DOTALL | re.VERBOSE)
_IN_NODE = re.compile(rf"(?P<ros2>\sexec\s*=|{_SUBST_ROS2})|(?P<ros1>\stype\s*=|{_SUBST_ROS1})")


def format_by_name(path: str) -> Format | None:
    """The frontend a file's extension names, or None (``.launch``, no or another extension)."""
    dot = path.rfind(".")
    if dot <= path.rfind("/"):
        return None
    return _BY_EXTENSION.get(path[dot:].lower())


def format_by_text(text: str) -> Format | None:
    """"xml" for markup, "yaml" for a top-level ``launch:`` key, else None."""
    if _MARKUP.match(text):
        return "xml"
    if _YAML_LAUNCH.search(text) and "generate_launch_description" not in text:
        return "yaml"
    return None


def launch_format(path: str, text: str | None = None) -> Format | None:
    """The frontend that loads ``path`` as ``ros2 launch`` would: by extension, else by ``text``
    (the XML parser first, then YAML, then Python); None for an unknown extension and no text."""
    fmt = format_by_name(path)
    if fmt is not None or text is None:
        return fmt
    return format_by_text(text) or "python"


def xml_root(text: str) -> str | None:
    """The tag of the first element, past the XML declaration, comments and a DOCTYPE."""
    pos = 1 if text.startswith("\ufeff") else 0
    while (m := _PROLOG.match(text, pos)) is not None and m.end() > pos:
        pos = m.end()
    m = _ROOT.match(text, pos)
    return m.group(1) if m is not None else None


@dataclass(frozen=True, slots=True)
class Generation:
    """Which ROS launch format the markup is written for: ``ros2`` when it has a ROS 2-only marker,
    ``ros1`` the first ROS 1-only marker before it (what it is, its 1-based line), if any."""

    ros2: bool
    ros1: tuple[str, int] | None


def _shown(marker: str) -> str:
    """How a ROS 1 marker is quoted: ``$(arg ...)``, ``<rosparam>``, ``<node type=...>``."""
    if marker.startswith("$("):
        return marker.strip() + " ...)"
    if marker.startswith("<"):
        return marker[:-1] + ">" if marker[-1] in " \t\r\n/>" else marker + ">"
    return "<node type=...>"


def _markers(text: str) -> Iterator[tuple[str, int, str]]:
    """(generation "ros1"/"ros2", offset, text) of each marker, in order; comments are skipped."""
    for m in _MARKERS.finditer(text):
        attrs = m.group("node")
        if attrs is not None:
            for n in _IN_NODE.finditer(attrs):
                yield n.lastgroup or "", m.start("node") + n.start(), n.group()
        elif m.lastgroup is not None:
            yield m.lastgroup, m.start(), m.group()


def generation(text: str) -> Generation:
    """Scans up to the first ROS 2 marker only: in a ROS 2 file, one of the first lines (the whole
    text took 46 ms for the 378 XML launch files of a 1,180-file workspace; this takes 4 ms)."""
    ros1 = None
    for group, offset, marker in _markers(text):
        if group == "ros2":
            return Generation(True, ros1)
        if ros1 is None:
            ros1 = (_shown(marker.lstrip()), text.count("\n", 0, offset) + 1)
    return Generation(False, ros1)


@dataclass(frozen=True, slots=True)
class Verdict:
    """What to check a file as (None: not at all) and, when it is not checked, why."""

    kind: Kind | None
    reason: str = ""


def _def_of(name: str) -> re.Pattern[str]:
    """A module-level ``def <name>(`` line."""
    return re.compile(rf"^(?:async[ \t]+)?def[ \t]+{name}[ \t]*\(", re.MULTILINE)


# A module-level ``def generate_launch_description(`` (not one a code generator writes in a string).
_DEFINES_ENTRY = _def_of("generate_launch_description")


# ``import launch``, ``from launch_ros.actions import Node``, ``from launch import ...``
_IMPORTS_LAUNCH = re.compile(r"^[ \t]*(?:from|import)[ \t]+launch(?:_ros|_xml|_yaml|_testing)?\b", re.MULTILINE)


def only_named_launch(text: str) -> bool:
    """A Python file named ``*launch.py`` that is no launch file: it neither defines
    ``generate_launch_description`` nor imports a launch package (ros2launch's own
    ``command/launch.py``, a deploy tool's ``tasks/launch.py``)."""
    return not defines_entry(text) and not _IMPORTS_LAUNCH.search(text)


# launch_testing's entry point (``launch_test FILE``): checked when named on the command line.
_DEFINES_TEST_ENTRY = _def_of("generate_test_description")


def defines_entry(text: str, pattern: re.Pattern[str] = _DEFINES_ENTRY) -> bool:
    """Whether Python ``text`` defines ``generate_launch_description`` (or the entry point
    ``pattern`` matches) at module level: a line
    starting with its ``def``, outside a triple-quoted string (the file's triple quotes before it
    pair up; a launch file generator writes one in its template)."""
    for m in pattern.finditer(text):
        before = text[: m.start()]
        if before.count('"""') % 2 == 0 and before.count("'''") % 2 == 0:
            return True
    return False


def classify(name: str, text: str | None, explicit: bool) -> Verdict:
    """Launch file, parameter file or neither, for a file its name does not decide.

    ``explicit`` files were named on the command line: they are checked the way ``ros2 launch``
    would load them (a YAML file as a parameter file unless it is a launch file), except ROS 1
    launch files, whose every line would be a wrong finding, and Python (or any other text) that
    defines no ``generate_launch_description`` and is not named ``*launch.py`` (``setup.py``, a
    README: what ``git diff --name-only | xargs physai-lint`` hands over). Found in a directory, a file named
    ``*launch.xml`` is taken unless it is ROS 1, a ``*.launch`` file only when it is clearly ROS 2,
    and a ``*launch.yaml`` only with a top-level ``launch`` key (else as a parameter file when it
    holds ``ros__parameters``, like any YAML file)."""
    named = name.endswith(LAUNCH_SUFFIXES)
    if text is None:  # unreadable: reported as a launch file when its name or the user says so
        return Verdict("launch" if explicit or named else None)
    if name.lower().endswith(YAML_SUFFIXES):
        if (explicit and named) or format_by_text(text) == "yaml":
            return Verdict("launch")
        if explicit or has_params_key(text):
            return Verdict("params")
        return Verdict(None)
    fmt = launch_format(name, text)
    if fmt == "xml":
        gen = generation(text)
        if gen.ros1 is not None and not gen.ros2:
            marker, line = gen.ros1
            return Verdict(None, f"a ROS 1 (roslaunch) launch file ({marker} on line {line}), "
                                 "which ros2 launch cannot load")
        return Verdict("launch" if explicit or named or (gen.ros2 and xml_root(text) == "launch") else None)
    if named or fmt == "yaml" or defines_entry(text) or (explicit and name.endswith(".launch")) \
            or (explicit and defines_entry(text, _DEFINES_TEST_ENTRY)):
        return Verdict("launch")
    if explicit:  # setup.py or a README among the changed files a script hands over
        return Verdict(None, "not a launch file: no launch frontend takes it, and as Python it defines "
                             "no generate_launch_description")
    return Verdict(None)
