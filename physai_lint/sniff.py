"""What a file is, from its name and its text: the frontend that loads it.

``ros2 launch`` loads a file of any name (launch ``launch_description_sources/
any_launch_file_utilities.py :: get_launch_description_from_any_launch_file``): a ``.py`` file
with the Python loader first, any other with the frontend parsers first (those claiming the
extension, then the rest: ``frontend/parser.py :: Parser.load``; launch_xml and launch_yaml both
claim ``.launch``) and Python last. ``launch_format`` decides the same from the text.

Everything here is a pure function of the text the file store has read anyway, made of regular
expression searches and no parse (each file is parsed once, by its frontend).
"""
from __future__ import annotations

import re
from typing import Literal

Format = Literal["python", "xml", "yaml"]

_BY_EXTENSION: dict[str, Format] = {".py": "python", ".xml": "xml", ".yaml": "yaml", ".yml": "yaml"}

_MARKUP = re.compile(r"\ufeff?\s*<")
_YAML_LAUNCH = re.compile(r"""^(?:launch|'launch'|"launch")[ \t]*:(?:[ \t]|$)""", re.MULTILINE)


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


def is_fallback_python(path: str, text: str) -> bool:
    """Loaded as Python only because neither frontend parser can take it."""
    return format_by_name(path) is None and format_by_text(text) is None
