"""Command lines a node's own program refuses: L117 invalid-node-arguments.

What a launch file passes in ``arguments=`` / ``args=`` reaches the program after
``rclcpp::init_and_remove_ros_arguments`` has taken the ``--ros-args`` sections out; a program that
parses the rest itself and refuses it prints its usage and exits. Only programs whose parser is
mirrored here are checked, and only command lines known word for word."""
from __future__ import annotations

import re
from collections.abc import Iterator

from physai_lint.checks._util import all_nodes
from physai_lint.checks.base import CheckContext, rule
from physai_lint.interfaces.arguments import argument_spans, own_arguments
from physai_lint.model.findings import Diagnostic

# std::stod: leading white space, then a decimal or hexadecimal number, "inf"/"infinity" or "nan";
# the rest of the word is ignored ("1.5m" reads as 1.5)
_STOD = re.compile(r"\s*[+-]?(?:(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?|inf|nan)", re.IGNORECASE)

# tf2_ros static_transform_broadcaster_program.cpp :: parse_args, the option table
_STATIC_TF_OPTIONS = {
    "--qx": "quaternion", "--qy": "quaternion", "--qz": "quaternion", "--qw": "quaternion",
    "--roll": "euler", "--pitch": "euler", "--yaw": "euler",
    "--x": "translation", "--y": "translation", "--z": "translation",
    "--frame-id": "frame", "--child-frame-id": "frame", "--help": "help", "-h": "help",
}


def static_tf_problem(args: list[str]) -> tuple[str, int | None, int] | None:
    """What ``static_transform_publisher`` says of its arguments ``args`` (after the program name)
    when it refuses them, the index of the word at fault (None when no one word is) and how many
    words were neither options nor their values; None when it takes them. Mirrors ``parse_args``
    step by step."""
    no_flag: list[tuple[int, str]] = []
    saw: set[str] = set()
    frame = child = ""
    help_ = False
    i = 0
    while i < len(args):
        word = args[i]
        kind = _STATIC_TF_OPTIONS.get(word)
        if kind is None:
            no_flag.append((i, word))
        elif kind == "help":
            help_ = True
        else:
            if i == len(args) - 1:
                return f"Not enough arguments for {word}", i, len(no_flag)
            i += 1
            value = args[i]
            if kind == "frame":
                frame, child = (value, child) if word == "--frame-id" else (frame, value)
            elif not _STOD.match(value):
                return f"Failed to parse {word} argument as float", i, len(no_flag)
            saw.add(kind)
        i += 1
    if help_:
        return None  # prints its usage and exits 0
    if {"euler", "quaternion"} <= saw:
        return "Cannot specify both quaternion and Euler rotations", None, len(no_flag)
    if len(no_flag) in (8, 9):
        if saw & {"frame", "translation", "quaternion"}:
            return "Cannot specify both new-style (flags) and old-style (arguments)", no_flag[0][0], len(no_flag)
        names = ("x", "y", "z", "yaw", "pitch", "roll") if len(no_flag) == 8 else ("x", "y", "z", "qx", "qy", "qz", "qw")
        for (index, word), name in zip(no_flag, names):
            if not _STOD.match(word):
                return f"Failed to parse {name} argument as float", index, len(no_flag)
        frame, child = no_flag[-2][1], no_flag[-1][1]
    elif no_flag:
        return "Extra unparsed arguments on command-line", no_flag[0][0], len(no_flag)
    if frame == "":
        return "Frame id must not be empty", None, len(no_flag)
    if child == "":
        return "Child frame id must not be empty", None, len(no_flag)
    return None


def _static_tf_hint(message: str, args: list[str], index: int | None, count: int) -> str:
    """A word on what went wrong, for the finding."""
    word = args[index] if index is not None else None
    if word is not None and word.startswith("-") and word.replace("_", "-") in _STATIC_TF_OPTIONS:
        return f'"{word}" is not one of its options; it is spelled {word.replace("_", "-")}'
    if word is not None and len(word.split()) > 1:
        return (f'"{word}" is one argument: launch passes each item of arguments= as one word; give '
                "each value as its own item")
    if message.startswith("Failed to parse"):
        return f'"{word}" is not a number'
    if message.startswith("Cannot specify both new-style"):
        return ("it takes either flags (--x ... --frame-id F --child-frame-id C) or the old positional "
                "form (x y z yaw pitch roll frame child, or x y z qx qy qz qw frame child), not both")
    if message.startswith("Extra unparsed"):
        return (f"{count} {'word is' if count == 1 else 'words are'} neither options nor their values; "
                "the old positional form has 8 "
                "(x y z yaw pitch roll frame child) or 9 (x y z qx qy qz qw frame child), without flags")
    if message.endswith("must not be empty"):
        return "--frame-id and --child-frame-id are required"
    return ""


@rule("L117", "invalid-node-arguments")
def invalid_node_arguments(ctx: CheckContext) -> Iterator[Diagnostic]:
    seen: set[object] = set()
    for _launch, node in all_nodes(ctx, include_inactive=False):
        if (node.package, node.executable) != ("tf2_ros", "static_transform_publisher"):
            continue
        own = own_arguments(node.arguments)
        if own is None:
            continue
        args = [a for _, a in own]
        if any("'" in a or '"' in a for a in args):
            continue  # XML/YAML args are split by shlex, which the words here may not show
        problem = static_tf_problem(args)
        if problem is None:
            continue
        message, index, count = problem
        spans = argument_spans(node)
        span = None
        if index is not None and spans:
            span = spans[own[index][0]]
        span = span or node.spans.get("arguments") or node.span
        if (span, message) in seen:
            continue
        seen.add((span, message))
        hint = _static_tf_hint(message, args, index, count)
        yield Diagnostic(
            "L117", span,
            f'static_transform_publisher refuses its arguments: "{message}"'
            + (f" ({hint})" if hint else "")
            + "; it prints its usage and exits with status 1, so the transform is never published",
            help="give the transform as flags: --x X --y Y --z Z --roll R --pitch P --yaw Y (or --qx ... "
                 "--qw) --frame-id PARENT --child-frame-id CHILD",
            key=message)
