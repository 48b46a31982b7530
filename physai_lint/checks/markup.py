"""XML/YAML markup and substitutions: L002 unknown-attribute, L114 substitution-not-in-distro."""
from __future__ import annotations

import os
import re
from collections.abc import Iterator
from typing import Any

from physai_lint.checks._util import ir_objects, run_memo
from physai_lint.checks.base import CheckContext, rule
from physai_lint.frontends.substitutions import DISTRO_ONLY_SUBSTITUTIONS, LAUNCH_LOG_DIR_REASON
from physai_lint.frontends.tags import unknown_markup
from physai_lint.model.findings import Diagnostic
from physai_lint.model.values import BoolOp, Compare, FileContent, IfElse, Unknown


def markup_problems(ctx: CheckContext, path: str) -> list[tuple[Any, str, str | None]]:
    """What launch rejects in XML/YAML launch file ``path`` when it parses it (``unknown_markup``:
    tags and attributes it does not know), once per run; [] for any other file."""
    lf = ctx.launch_files.get(path)
    if lf is None or lf.format not in ("xml", "yaml") or lf.markup is None:
        return []
    memo = ctx.options.setdefault("_markup_problems", {})
    if path not in memo:
        memo[path] = unknown_markup(lf.markup, lf.format, lambda: _extension_tags(ctx), ctx.distro)
    return memo[path]  # type: ignore[no-any-return]


@rule("L002", "unknown-attribute")
def unknown_attribute(ctx: CheckContext) -> Iterator[Diagnostic]:
    for path in sorted(ctx.launch_files):
        lf = ctx.launch_files[path]
        for span, message, hint in markup_problems(ctx, path):
            if hint and " " not in hint:
                help_ = f'did you mean "{hint}"?'
            else:
                help_ = hint or "remove it; see the accepted tags and attributes in the launch docs"
            what = "key" if lf.format == "yaml" else "attribute"
            msg = message if lf.format == "xml" else message.replace("attribute", what)
            yield Diagnostic(
                "L002", span,
                f"{msg}; launch rejects it when it parses the file",
                help=help_, key=message)


_EXPOSE = re.compile(r"""@expose_action\(\s*['"]([\w.-]+)['"]""")
_ENTRY_POINT = "launch.frontend.launch_extension"


def _extension_tags(ctx: CheckContext) -> frozenset[str]:
    """The tags the launch extensions register: ``@expose_action('gz_server')`` in a Python
    package that declares a ``launch.frontend.launch_extension`` entry point, which launch loads
    before it parses a file: the workspace's, and the released ones of the distro
    (``RELEASED_EXTENSION_TAGS``). Read on the first unknown tag."""
    def build() -> frozenset[str]:
        from physai_lint.workspace.distro import DISTROS, released_packages

        released = released_packages(ctx.distro)
        rank = DISTROS.index(ctx.distro) if ctx.distro in DISTROS else len(DISTROS)
        bundled = {tag for tag, (package, since) in RELEASED_EXTENSION_TAGS.items()
                   if package in released and rank >= DISTROS.index(since)}
        return _scan_extensions(ctx.packages) | bundled

    return run_memo(ctx.options, "_extension_tags", ctx.launches, build)


# Tags that released packages register as launch extensions (@expose_action in a package with a
# launch.frontend.launch_extension entry point): tag -> (package, first distro that has it).
# Read from each package's source at its distro branches (ros2/ros2_tracing humble..rolling;
# gazebosim/ros_gz jazzy and ros2, none on humble).
RELEASED_EXTENSION_TAGS: dict[str, tuple[str, str]] = {
    "trace": ("tracetools_launch", "humble"),
    "gz_server": ("ros_gz_sim", "jazzy"),
    "gz_spawn_model": ("ros_gz_sim", "jazzy"),
    "ros_gz_bridge": ("ros_gz_bridge", "jazzy"),
}


def _scan_extensions(packages: Any) -> frozenset[str]:
    lazy = getattr(packages, "packages", None)
    reader = getattr(packages, "read_text", None)
    if lazy is None or reader is None:
        return frozenset()
    tags: set[str] = set()
    for name in sorted(lazy):
        root = lazy.dir_of(name)
        if not any(_ENTRY_POINT in (reader(os.path.join(root, f)) or "") for f in ("setup.cfg", "setup.py")):
            continue
        for dirpath, dirnames, files in os.walk(root):
            dirnames[:] = sorted(d for d in dirnames if not d.startswith(".") and d != "test")
            for f in sorted(files):
                if f.endswith(".py"):
                    tags.update(_EXPOSE.findall(reader(os.path.join(dirpath, f)) or ""))
    return frozenset(tags)


# The Python classes of those substitutions (launch.substitutions), by their frontend names.
PY_NEWER = {
    "launch.substitutions.EqualsSubstitution": "equals",
    "launch.substitutions.NotEqualsSubstitution": "not-equals",
    "launch.substitutions.IfElseSubstitution": "if",
    "launch.substitutions.AnySubstitution": "any",
    "launch.substitutions.AllSubstitution": "all",
    "launch.substitutions.FileContent": "file-content",
    "launch.substitutions.LaunchLogDir": "launch_log_dir",
}
_PY_NAME = {v: k.rsplit(".", 1)[-1] for k, v in PY_NEWER.items()}


def _subst_name(part: Any) -> str | None:
    if isinstance(part, Compare):
        return part.op
    if isinstance(part, IfElse):
        return "if"
    if isinstance(part, BoolOp) and part.op in ("any", "all"):
        return part.op
    if isinstance(part, FileContent):
        return "file-content"
    if isinstance(part, Unknown) and part.reason == LAUNCH_LOG_DIR_REASON:
        return "launch_log_dir"
    return None


@rule("L114", "substitution-not-in-distro")
def substitution_not_in_distro(ctx: CheckContext) -> Iterator[Diagnostic]:
    if ctx.distro != "humble":
        return
    seen: set[object] = set()
    for path in sorted(ctx.launch_files):
        lf = ctx.launch_files[path]
        found: list[tuple[str, Any]] = []
        if lf.format == "python":
            if lf.python is not None:
                found = [(PY_NEWER[c.qualname], c.span) for c in lf.python.calls if c.qualname in PY_NEWER]
        else:
            for obj in ir_objects(ctx, path):
                name = _subst_name(obj)
                span = getattr(obj, "span", None)
                if name is not None and span is not None:
                    found.append((name, span))
        for name, span in found:
            since = DISTRO_ONLY_SUBSTITUTIONS.get(name)
            if since is None or span in seen:
                continue
            seen.add(span)
            if lf.format == "python":
                cls = _PY_NAME[name]
                yield Diagnostic(
                    "L114", span,
                    f"{cls} does not exist in launch on {ctx.distro} (added in {since}); "
                    "the import fails with ImportError",
                    help=("on humble the directory is launch.logging.launch_config.log_dir, or "
                          "target a newer distro with --distro" if name == "launch_log_dir" else
                          "use PythonExpression([...]) / LaunchConfigurationEquals on humble, or "
                          "target a newer distro with --distro"),
                    key=cls)
            else:
                shown = f"$({name})" if name == "launch_log_dir" else f"$({name} ...)"
                yield Diagnostic(
                    "L114", span,
                    f'substitution "{shown}" does not exist on {ctx.distro} (added in {since}); '
                    f"launch fails with \"Unknown substitution: {name}\"",
                    help=("use $(log_dir) on humble (the same directory), or target a newer distro "
                          "with --distro" if name == "launch_log_dir" else
                          "use $(eval ...) on humble (e.g. $(eval \"'$(var mode)' == 'sim'\")), or "
                          "target a newer distro with --distro"),
                    key=name)
