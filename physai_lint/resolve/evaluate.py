"""Substitution evaluation: ``Value`` -> ``str`` (known) or ``None`` (unknown), as launch performs it.

Nothing is executed: ``Command``/``$(command)`` and environment variables are unknown (the linter's
own environment says nothing about the robot's); ``PythonExpression``/``$(eval)`` go through the
safe evaluator. Every launch-configuration read is reported to ``on_read`` so rules can see reads
of configurations that nothing defines.
"""
from __future__ import annotations

import posixpath
import re
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

from physai_lint.model import values as v
from physai_lint.model.span import Span

if TYPE_CHECKING:
    from physai_lint.workspace import PackageIndex

TRUE_WORDS = ("true", "1")
FALSE_WORDS = ("false", "0")


@dataclass
class Scope:
    """Launch configurations (``configs``) and locals, mirroring ``LaunchContext``.

    ``configs`` maps names to a known string, ``None`` (defined, value unknown) or, for the special
    keys ``ros_remaps`` and ``global_params``, to list objects that are *shared* between scopes the
    way ``dict.copy()`` shares them in ``_push_launch_configurations`` (SEMANTICS §3).
    """

    configs: dict[str, Any] = field(default_factory=dict)
    locals: dict[str, Any] = field(default_factory=dict)

    def copy_configs(self) -> dict[str, Any]:
        return dict(self.configs)


ReadHook = Callable[[str, Span | None, bool, bool], None]  # name, span, defined, has_default
# name, span, named by a launch configuration (its name when it alone gave the value)
PackageHook = Callable[[str, Span | None, "bool | str"], None]


# What ``yaml.safe_load`` reads as a bool (YAML 1.1, PyYAML's resolver): the boolean substitutions
# (NotSubstitution, AndSubstitution, $(not) ...) type their operands with
# ``perform_typed_substitution(context, value, bool)``, which fails on anything else ('0', '1', '')
_YAML_BOOLS = {**dict.fromkeys(("yes", "Yes", "YES", "true", "True", "TRUE", "on", "On", "ON"), True),
               **dict.fromkeys(("no", "No", "NO", "false", "False", "FALSE", "off", "Off", "OFF"), False)}


def yaml_bool(text: str) -> bool | None:
    """``coerce_to_type(text, bool)``: True/False, or None when launch raises ValueError."""
    return _YAML_BOOLS.get(text.strip())


def condition_truth(text: str) -> bool | None:
    """``evaluate_condition_expression``: True/False, or None when the text is not a valid value."""
    t = text.strip().lower()
    if t in TRUE_WORDS:
        return True
    if t in FALSE_WORDS:
        return False
    return None


def _as_bool_or_float(text: str) -> Any:
    t = text.strip().lower()
    if t in ("true", "false"):
        return t == "true"
    try:
        return float(t)
    except ValueError:
        return text


class Evaluator:
    def __init__(
        self,
        packages: PackageIndex | None,
        on_read: ReadHook | None = None,
        on_package: PackageHook | None = None,
        on_bad_condition: Callable[[Span | None, str, str], None] | None = None,
    ) -> None:
        self.packages = packages
        self.on_read = on_read
        self.on_package = on_package
        # a value a condition or a boolean substitution refuses: (where, the value, "condition" or
        # the substitution's operator)
        self.on_bad_condition = on_bad_condition
        # a PythonExpression / $(eval) that raises with the text it gets: (where, text, why)
        self.on_bad_expression: Callable[[Span | None, str, str], None] | None = None
        # a Command whose parts run together into one word (``glued_words``): (where, the left
        # word, the right word, the command line)
        self.on_glued_command: Callable[[Span | None, str, str, str], None] | None = None
        # a RewrittenYaml param_rewrites key that rewrites nothing: (its span, the key, the source)
        self.on_unused_rewrite: Callable[[Span, str, str], None] | None = None
        self.on_dirname: Callable[[Span | None, Scope], None] | None = None
        # temporary files that substitutions (nav2_common RewrittenYaml ...) write: path -> file
        self.virtual: dict[str, Any] = {}
        # Files a substitution opens (nav2_common RewrittenYaml/ReplaceString) that do not exist
        # after install: path -> (status "missing"/"not_installed", workspace source or None).
        self.unopened: dict[str, tuple[str, str | None]] = {}
        # what those substitutions computed, by their inputs (nav2 hands one file to every server)
        self.file_memo: dict[tuple[Any, ...], Any] = {}
        self.env_set: set[str | None] = set()  # variables a SetEnvironmentVariable wrote (None: unknown)
        # launch configurations looked up so far: a value whose evaluation moves it depends on one
        self.config_lookups = 0
        # the last Command evaluated, with its command line when known (never run: its output is
        # unknown; rules may look at the file it prints)
        self.last_command: tuple[v.Command, str | None] | None = None

    def eval_noting_configs(self, value: v.Value | None, scope: Scope) -> tuple[str | None, bool | str]:
        """(``eval``, whether it looked up a launch configuration: ``$(var model)_description``;
        the configuration's name when the value is that one configuration alone)."""
        before = self.config_lookups
        out = self.eval(value, scope)
        if self.config_lookups == before:
            return out, False
        only = value[0] if value is not None and len(value) == 1 else None
        if isinstance(only, v.LaunchConfig) and len(only.name) == 1 and isinstance(only.name[0], v.Text):
            return out, only.name[0].text
        return out, True

    def eval(self, value: v.Value | None, scope: Scope) -> str | None:
        if value is None:
            return None
        out: list[str] = []
        unknown = False
        for part in value:
            s = self._part(part, scope)
            if s is None:
                unknown = True  # keep evaluating: later parts may record reads
            else:
                out.append(s)
        return None if unknown else "".join(out)

    def _part(self, p: v.Subst, scope: Scope) -> str | None:
        if isinstance(p, v.Text):
            return p.text
        if isinstance(p, v.LaunchConfig):
            return self._config(p, scope)
        if isinstance(p, v.FindPackage):
            return self._find_package(p, scope)
        if isinstance(p, v.PathJoin):
            parts = [self.eval(x, scope) for x in p.parts]
            if any(x is None for x in parts):
                return None
            return posixpath.join(*[x for x in parts if x is not None]) if parts else ""
        if isinstance(p, v.ThisFileDir):
            if self.on_dirname is not None:
                self.on_dirname(p.span, scope)
            d = scope.locals.get("current_launch_file_directory")
            return d if isinstance(d, str) else None
        if isinstance(p, v.ThisFile):
            f = scope.locals.get("current_launch_file_path")
            return f if isinstance(f, str) else None
        if isinstance(p, v.ExecInPackage):
            exe = self.eval(p.executable, scope)
            pkg, from_config = self.eval_noting_configs(p.package, scope)
            if pkg is not None and self.on_package:
                self.on_package(pkg, p.span, from_config)
            prefix = self.packages.prefix_dir(pkg) if (self.packages and pkg) else None
            return posixpath.join(prefix, "lib", pkg or "", exe) if (prefix and exe and pkg) else None
        if isinstance(p, v.PythonExpr):
            return self._python_expr(p, scope)
        if isinstance(p, v.BoolOp):
            return self._bool_op(p, scope)
        if isinstance(p, v.Compare):
            left, right = self.eval(p.left, scope), self.eval(p.right, scope)
            if left is None or right is None:
                return None
            equal = _as_bool_or_float(left) == _as_bool_or_float(right)
            return str(equal if p.op == "equals" else not equal).lower()
        if isinstance(p, v.StrMethod):
            inner = self.eval(p.value, scope)
            return None if inner is None else getattr(inner, p.method)()
        if isinstance(p, v.IfElse):
            cond = self.eval(p.condition, scope)
            truth = condition_truth(cond) if cond is not None else None
            if truth is None:
                self.eval(p.if_value, scope)
                self.eval(p.else_value, scope)
                return None
            return self.eval(p.if_value if truth else p.else_value, scope)
        if isinstance(p, (v.RewrittenYaml, v.ReplaceString, v.LaunchConfigAsBool, v.HasNodeParams)):
            from physai_lint.resolve import nav2_common

            return nav2_common.evaluate(self, p, scope)
        if isinstance(p, v.EnvVar):
            name = self.eval(p.name, scope)
            if p.default is not None:
                self.eval(p.default, scope)
            # The one variable a linter run knows: the distro it checks against (--distro), unless
            # the launch sets it (or a variable whose name is unknown) before this point.
            if name == "ROS_DISTRO" and self.packages is not None and not self.env_set & {"ROS_DISTRO", None}:
                return getattr(self.packages, "distro", None)
            return None
        if isinstance(p, (v.ParamRef, v.FileContent, v.Anon)):
            for sub in (getattr(p, "name", None), getattr(p, "default", None), getattr(p, "path", None)):
                if sub is not None:
                    self.eval(sub, scope)
            return None
        # Command, FindExecutable, Unknown: never known statically.
        if isinstance(p, v.Command):
            self.last_command = (p, self._command_line(p.command, scope, p.span))
        return None

    def _command_line(self, command: v.Value, scope: Scope, span: Span | None = None) -> str | None:
        """A command's text, ``FindExecutable(name=x)`` standing for its name ``x`` (where on PATH
        it is found does not matter to what the command prints); None when unknown."""
        out: list[str | None] = [self.eval(part.name, scope) if isinstance(part, v.FindExecutable)
                                 else self._part(part, scope) for part in command]  # every part read
        line = None if None in out else "".join(out)  # type: ignore[arg-type]
        if line is not None and self.on_glued_command is not None:
            for where, left, right in glued_words(command, out):  # type: ignore[arg-type]
                self.on_glued_command(where or span, left, right, line)
        return line

    def _config(self, p: v.LaunchConfig, scope: Scope) -> str | None:
        name = self.eval(p.name, scope)
        if name is None:
            return None
        self.config_lookups += 1
        if name in scope.configs:
            if self.on_read:
                self.on_read(name, p.span, True, p.default is not None)
            value = scope.configs[name]
            return value if isinstance(value, str) else None
        if self.on_read:
            self.on_read(name, p.span, False, p.default is not None)
        if p.default is not None:
            return self.eval(p.default, scope)
        return None

    def _find_package(self, p: v.FindPackage, scope: Scope) -> str | None:
        pkg, from_config = self.eval_noting_configs(p.package, scope)
        if pkg is None:
            return None
        if self.on_package:
            self.on_package(pkg, p.span, from_config)
        if self.packages is None:
            return None
        if p.kind == "share":
            return self.packages.share_dir(pkg)
        return self.packages.prefix_dir(pkg)

    def _python_expr(self, p: v.PythonExpr, scope: Scope) -> str | None:
        modules = p.modules
        if p.modules_value is not None:  # $(eval EXPR $(var mods)): read, and known when its value is
            text = self.eval(p.modules_value, scope)
            modules = None if text is None else tuple(m.strip() for m in text.split(",") if m.strip())
        expr = self.eval(p.expression, scope)
        if expr is None:
            return None
        from physai_lint.resolve.safe_eval import SafeEvalError, SafeEvalUnknown, safe_eval

        result = safe_eval(expr, modules)
        if isinstance(result, SafeEvalUnknown):
            if isinstance(result, SafeEvalError) and self.on_bad_expression is not None:
                self.on_bad_expression(p.span, expr, result.reason)
            return None
        return str(result)

    def _bool_op(self, p: v.BoolOp, scope: Scope) -> str | None:
        vals: list[bool | None] = []
        for operand in p.operands:
            text = self.eval(operand, scope)
            truth = None if text is None else yaml_bool(text)
            if text is not None and truth is None and self.on_bad_condition:
                self.on_bad_condition(p.span or v.span_of(operand), text, p.op)
            vals.append(truth)
        if p.op == "not":
            return None if vals[0] is None else str(not vals[0]).lower()
        if p.op in ("and", "all"):
            if any(x is False for x in vals):
                return "false"
            return None if any(x is None for x in vals) else "true"
        if any(x is True for x in vals):
            return "true"
        return None if any(x is None for x in vals) else "false"

    def truth(self, text: str, value: v.Value | None, span: Span | None = None) -> bool | None:
        result = condition_truth(text)
        if result is None and self.on_bad_condition:
            self.on_bad_condition(span or v.span_of(value), text, "condition")
        return result

    def condition(self, kind: str, value: v.Value, scope: Scope, span: Span | None = None) -> bool | None:
        """``IfCondition``/``UnlessCondition``: whether the action runs (None: unknown). ``span``:
        where the condition is written, where a refused value is reported (the value itself may be
        a LaunchConfiguration made lines before, and used elsewhere too)."""
        text = self.eval(value, scope)
        if text is None:
            return None
        truth = self.truth(text, value, span)
        if truth is None:
            return None
        return truth if kind == "if" else not truth


# ``name:=value`` (a xacro mapping, a ROS remap or parameter) at the start of a word.
_MAPPING_START = re.compile(r"[A-Za-z_][\w./-]*:=")
# A word that names a program (``xacro``, ``cat``, ``ros2``): letters, digits and ``_.+-`` only.
_PROGRAM_WORD = re.compile(r"[\w.+-]*[A-Za-z][\w.+-]*")


def glued_words(command: v.Value, texts: list[str]) -> list[tuple[Span | None, str, str]]:
    """Where ``Command([...])`` (``$(command ...)``) runs two words together: launch concatenates
    the parts' values with nothing between them and splits the result with ``shlex``
    (``Command.perform``), so a missing space joins what the parts' kinds say are separate words.
    ``texts``: each part's value. (span of the part inside the command: the literal, or None;
    the word's text before the joint; its text after) for a path or a mapping's value followed
    by a ``name:=...`` literal (``'xacro ', file, 'ns:=', ns``: the file and the mapping are one
    word), and for the program followed by a substitution giving an absolute path (``'xacro',
    file``: the program ``xacro/opt/...``). Empty parts are skipped (the word before them is the
    one joined); two literals are never judged: they are written side by side on purpose."""
    line = "".join(texts)
    found: list[tuple[Span | None, str, str]] = []
    prev: int | None = None
    at = 0  # where texts[i] starts in line
    for i, text in enumerate(texts):
        start, at = at, at + len(text)
        if not text:
            continue
        if prev is not None and not texts[prev][-1].isspace() and not text[0].isspace():
            left, right = command[prev], command[i]
            words_before = line[:start].split()
            after = line[start:].split()[0]
            if _joins_two_words(left, right, words_before, after):
                found.append(((right if isinstance(right, v.Text) else left).span, words_before[-1], after))
        prev = i
    return found


def _joins_two_words(left: v.Subst, right: v.Subst, words_before: list[str], after: str) -> bool:
    """Whether parts ``left`` and ``right``, written with no space between them, make the one
    word ``words_before[-1] + after`` of two the author meant (``glued_words``)."""
    before = words_before[-1]
    if isinstance(right, v.Text):
        # a mapping literal right after a substitution ending a path or a mapping's value (not
        # the start of a mapping's name: ' ', side, '_arm:=true' is one word on purpose)
        return not isinstance(left, v.Text) and _MAPPING_START.match(after) is not None and \
            ("/" in before or ":=" in before)
    # the program (written, or FindExecutable) right before a substitution's absolute path (an
    # option is not: ``-p/path`` is the option's value)
    return isinstance(left, (v.Text, v.FindExecutable)) and not isinstance(right, v.FindExecutable) \
        and after.startswith("/") and len(words_before) == 1 and _PROGRAM_WORD.fullmatch(before) is not None
