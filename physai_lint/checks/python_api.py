"""Python launch API misuse found in the file's syntax: L003 parameters-not-a-list,
L004 substitution-concatenation, L005 undefined-name, L006 missing-generate-launch-description,
L008 wrong-argument-type."""
from __future__ import annotations

import posixpath
from typing import Iterator

from physai_lint.checks._util import once, python_facts
from physai_lint.checks.base import CheckContext, rule
from physai_lint.checks.markup import PY_NEWER
from physai_lint.model.findings import Diagnostic
from physai_lint.model.launch import NameFact, TypeFact
from physai_lint.model.span import Span

NODE_CLASSES = ("launch_ros.actions.Node", "launch_ros.actions.LifecycleNode",
                "launch_ros.actions.ComposableNodeContainer", "launch_ros.descriptions.ComposableNode",
                "launch_ros.actions.node.Node", "launch_ros.actions.lifecycle_node.LifecycleNode")


@rule("L003", "parameters-not-a-list")
def parameters_not_a_list(ctx: CheckContext) -> Iterator[Diagnostic]:
    for path, facts in python_facts(ctx):
        for call in facts.calls:
            kinds = dict(call.value_kinds)
            kind = kinds.get("parameters")
            if kind not in ("dict", "str", "set") or not any(call.qualname.endswith(c.rsplit(".", 1)[-1])
                                                            for c in NODE_CLASSES):
                continue
            span = dict(call.kwargs).get("parameters", call.span)
            cls = call.qualname.rsplit(".", 1)[-1]
            yield Diagnostic(
                "L003", span,
                f"{cls}(parameters=...) is given a {kind}, not a list; launch_ros raises "
                f"\"TypeError: '{cls}' expected 'parameters' to be one of [<class 'list'>]\"",
                help="wrap it in a list: parameters=[{...}] (dicts and parameter file paths go in the list)",
                key=f"{cls}:parameters")


@rule("L005", "undefined-name")
def undefined_name(ctx: CheckContext) -> Iterator[Diagnostic]:
    from physai_lint.workspace.distro import launch_exports

    for path, facts in python_facts(ctx):
        used = {c.qualname for c in facts.calls}
        for module, name, span in getattr(facts, "imports", ()) if ctx.distro in _EXPORT_DISTROS else ():
            exports = launch_exports()
            table = exports.get(ctx.distro, {})
            if module not in table or name in table[module] or f"{module}.{name}" in used and \
                    f"{module}.{name}" in PY_NEWER:
                continue  # a newer substitution class the file uses: L114 reports it where it is used
            where = sorted(m for m, names in table.items() if name in names and m != module)
            newer = sorted(d for d, t in exports.items() if name in t.get(module, ()))
            if where:
                why, fix = f"it is in {where[0]}", f'import it from there: "from {where[0]} import {name}"'
            elif newer:
                why, fix = (f"{newer[0]} has it",
                            f'use what {ctx.distro} has, or target {newer[0]} with --distro')
            else:
                why, fix = "", "check the name and the distro"
            yield Diagnostic(
                "L005", span,
                f'{module} has no "{name}" in {ctx.distro}' + (f" ({why})" if why else "")
                + f"; loading the file raises ImportError: cannot import name '{name}'",
                help=fix, key=f"import:{module}:{name}")
        for fact in facts.undefined_names:
            when = (f"{fact.function}() raises NameError when it reaches this line" if fact.function
                    else "loading the file raises NameError")
            yield Diagnostic(
                "L005", fact.span,
                f'name "{fact.name}" is used but never imported or defined; {when}',
                help=_undefined_help(fact), key=fact.name)


# The distros whose launch exports are known (physai_lint/data/launch-exports.json): released
# branches; rolling and the distros made from it after the table was extracted are not checked.
_EXPORT_DISTROS = ("humble", "jazzy")


def _undefined_help(fact: NameFact) -> str:
    """Import the launch API of that name, or use the defined name it is close to."""
    from physai_lint.closematch import close_matches
    from physai_lint.frontends.python.api import KNOWN

    modules = sorted(k.rsplit(".", 1)[0] for k in KNOWN if k.rsplit(".", 1)[-1] == fact.name)
    if modules:
        return f'import it: "from {modules[0]} import {fact.name}"'
    near = close_matches(fact.name, fact.visible, 1, 0.75)
    if near:
        return f'did you mean "{near[0]}"? Otherwise import or define "{fact.name}"'
    return f'import "{fact.name}" from the module that provides it, or define it'


@rule("L006", "missing-generate-launch-description")
def missing_gld(ctx: CheckContext) -> Iterator[Diagnostic]:
    from physai_lint.model.span import Span

    for path, facts in python_facts(ctx):
        if facts.has_generate_launch_description or facts.is_launch_test:
            continue
        yield Diagnostic(
            "L006", Span.point(path, 1),
            "the launch file defines no generate_launch_description() function; ros2 launch cannot load it",
            help="define def generate_launch_description(): return LaunchDescription([...])",
            key="generate_launch_description")


@rule("L004", "substitution-concatenation")
def concatenation(ctx: CheckContext) -> Iterator[Diagnostic]:
    how_text = {
        "plus": "joined with + at description time",
        "os.path.join": "passed to os.path.join at description time",
        "path": "joined to a pathlib.Path with / at description time",
        "f-string": "put into an f-string at description time",
        "format": "formatted with str.format at description time",
        "percent": "formatted with % at description time",
        "str": "converted with str() at description time",
        "join": "joined into a str with str.join at description time",
        "get_package_share": "passed to get_package_share_directory() at description time",
        "get_package_prefix": "passed to get_package_prefix() at description time",
    }
    for path, facts in python_facts(ctx):
        for fact in facts.concatenations:
            lookup = fact.how.startswith("get_package_")
            yield Diagnostic(
                "L004", fact.span,
                f"substitution {fact.detail} is {how_text.get(fact.how, fact.how)}: it is an object, "
                "not a string, so this raises TypeError" + (
                    ' ("expected string or bytes-like object")' if lookup else " or produces its repr"),
                help="find the package when the launch runs: FindPackageShare(LaunchConfiguration('x')) "
                     "(FindPackagePrefix), or call it inside an OpaqueFunction with "
                     "LaunchConfiguration('x').perform(context)" if lookup else
                     "build the value as a list of parts ([LaunchConfiguration('x'), '.yaml']) or with "
                     "PathJoinSubstitution([...])",
                key=f"{fact.how}:{fact.detail}")
    for span, left, right, line in once(ctx, "glued_commands", lambda e: (e[0], _joint(e[1], e[2]))):
        yield _glued_command(span, left, right, line)


def _glued_command(span: Span, left: str, right: str, line: str) -> Diagnostic:
    """L004 for a ``Command([...])`` whose parts run two words together (``glued_words``)."""
    words = line.split()
    program = posixpath.basename(words[0]) if words else ""
    glued = _short(left + right)
    if ":=" in right:
        name = right.split(":=", 1)[0]
        what = f'"{_short(left)}" and "{_short(right)}" are the one argument "{glued}"'
        inputs = [w for w in words[1:] if not w.startswith("-") and ":=" not in w]
        if program in ("xacro", "xacro.py") and not inputs:
            what += ": xacro reads it as a mapping and finds no input file, so the command fails"
        else:
            what += ", where two were meant"
        help_ = f"put a space before the mapping: ' {name}:=' (or a ' ' part between the two)"
    else:
        what = (f'"{left}" and "{_short(right)}" are the one word "{glued}", a program that does not '
                "exist, so the command fails")
        help_ = f"put a space after the program: '{left} '"
    return Diagnostic(
        "L004", span,
        "Command(...) joins its parts with nothing between them and splits the result at spaces: "
        f"{what} (the command line is '{' '.join(_short(w) for w in words)}')",
        help=help_, key=_joint(left, right))


def _joint(left: str, right: str) -> str:
    """Which glued words at one place are the same finding: the mapping's name, or the program
    (two runs of an included file glue ``ns:=robot1`` and ``ns:=robot2`` at one place)."""
    return right.split(":=", 1)[0] if ":=" in right else left


def _short(text: str, most: int = 48) -> str:
    """``text``, or when longer than ``most`` its last path components after ".../" (what comes
    before its first ``/`` kept: the program of ``xacro/opt/ros/...``)."""
    if len(text) <= most:
        return text
    head = text[:text.index("/") + 1] if "/" in text[1:] and not text.startswith("/") else ""
    cut = text.find("/", len(text) - most + len(head) + 4)
    return head + ".../" + text[cut + 1:] if cut != -1 else "..." + text[-(most - 3):]


@rule("L011", "substitution-tested-in-python")
def substitution_tested(ctx: CheckContext) -> Iterator[Diagnostic]:
    for _path, facts in python_facts(ctx):
        for fact in facts.tested:
            help_ = ("decide when the launch runs: give the actions condition=IfCondition(...) or "
                     "LaunchConfigurationEquals(...), or read the value with .perform(context) in an "
                     "OpaqueFunction")
            if fact.how == "truth":
                message = (f"{fact.detail} is tested as a Python bool while the launch description is "
                           "built: a substitution is an object, and every object is true, so the launch "
                           "argument never decides this")
            elif fact.how == "condition":
                message = (f"{fact.detail} is tested as a Python bool while the launch description is "
                           "built: a condition object is always true (`if` always runs its body, `and` "
                           "gives the condition on its right, `or` this one), so this condition never "
                           "decides anything")
                help_ = ("combine the values in one condition: IfCondition(AndSubstitution(a, "
                         "NotSubstitution(b))), OrSubstitution, or IfCondition(PythonExpression([...]))")
            else:
                always = "false" if fact.how == "equals" else "true"
                message = (f"{fact.detail} compares the substitution object, not the value it names: it "
                           f"is always {always} while the launch description is built")
            yield Diagnostic("L011", fact.span, message, help=help_, key=f"{fact.how}:{fact.detail}")


@rule("L012", "call-argument-mismatch")
def call_argument_mismatch(ctx: CheckContext) -> Iterator[Diagnostic]:
    for _path, facts in python_facts(ctx):
        for fact in facts.call_errors:
            yield Diagnostic(
                "L012", fact.span,
                f"this call raises TypeError when it runs: {fact.detail}",
                help="pass the arguments the function's signature asks for, or give the parameter a "
                     "default value",
                key=fact.detail)


@rule("L013", "late-bound-variable")
def late_bound_variable(ctx: CheckContext) -> Iterator[Diagnostic]:
    """A function launch calls later (an OpaqueFunction's, an event handler's) reading a variable
    that the enclosing function rebinds after making it: Python looks the variable up when the body
    runs, after ``generate_launch_description`` has returned (``calls.late_bindings``)."""
    for _path, facts in python_facts(ctx):
        for f in facts.late_bound:
            values = f" is {f.now} by then, not {f.made} as when the function was made" \
                if f.made and f.now else " has another value by then than when the function was made"
            opaque = f.caller == "OpaqueFunction"
            when = "runs the OpaqueFunction" if opaque else f"runs the {f.caller} handler"
            if opaque:
                help_ = (f"bind the value when the function is made: a default argument (lambda context, "
                         f"{f.name}={f.name}: ...), OpaqueFunction(function=..., kwargs={{'{f.name}': "
                         f"{f.name}}}) or functools.partial(function, {f.name}={f.name})")
            else:  # launch calls a handler's function as on_event(event, context)
                help_ = (f"bind the value when the handler is made: a default argument after the event and "
                         f"the context (lambda event, context, {f.name}={f.name}: ...) or "
                         f"functools.partial(function, {f.name}={f.name})")
            yield Diagnostic(
                "L013", f.span,
                f'this function reads "{f.name}" when launch {when}, after generate_launch_description '
                f"has returned: {f.name}{values} (a Python closure reads the variable when it runs, not "
                "the value it had when the function was made)",
                help=help_, key=f.name)


@rule("L008", "wrong-argument-type")
def wrong_argument_type(ctx: CheckContext) -> Iterator[Diagnostic]:
    for _path, facts in python_facts(ctx):
        for f in facts.wrong_types:
            message, help_ = _wrong_type_text(f)
            yield Diagnostic("L008", f.span, message, help=help_, key=f"{f.call}:{f.value}")


def _joined_characters(shown: str) -> str:
    """What ``os.path.join(*text)`` makes of a string literal shown as ``'text'`` (a "/" among the
    characters starts the path again), shortened for a message."""
    import ast
    import posixpath

    try:
        text = ast.literal_eval(shown)
    except (ValueError, SyntaxError):
        return "one component per character"
    if not isinstance(text, str) or not text:
        return "one component per character"
    joined = posixpath.join(*text)
    return repr(joined if len(joined) <= 40 else joined[:37] + "...")


def _wrong_type_text(f: TypeFact) -> tuple[str, str]:
    """The message and help of an L008 finding."""
    if f.kind == "text":  # a bool, int or float (the frontend records nothing else here)
        example = "'true' or 'false'" if f.type == "bool" else f"'{f.value}'"
        message = (f"{f.call} is given the {f.type} {f.value}, where launch accepts only a string or "
                   f"substitutions; it raises \"TypeError: '{f.type}' object is not iterable\"")
        return message, f"write it as a string such as {example}"
    if f.kind == "part":
        article = "an" if f.type[:1] in "aeiou" else "a"
        message = (f"{f.call} is given {f.value}, {article} {f.type}, as one of its parts; launch accepts only "
                   "strings and substitutions there and raises \"TypeError: Failed to normalize given item "
                   f"of type '<class '{f.type}'>'\" when the description is built")
        help_ = ("a list inside the list is no substitution: write its parts into the outer list (its "
                 "parts are concatenated)" if f.type in ("list", "tuple") else "write it as a string")
        return message, help_
    if f.kind == "path-string":
        message = (f"{f.call} is given the string {f.value}, not a list of components: since "
                   "ros2/launch#838 (kilted, and humble's updates since mid-2025) each item is a path "
                   "component, and a string's items are its characters, so it yields "
                   f"{_joined_characters(f.value)} (older releases kept it whole)")
        return message, f"pass a list: PathJoinSubstitution([{f.value}]), or split it into its components"
    name = f.call.split("(", 1)[1].split("=", 1)[0]  # the keyword: "Node(shell=...)" -> "shell"
    if f.kind == "plain-bool":
        what = "a substitution object" if f.type == "substitution" else "a non-empty string"
        message = (f"{f.call} is given {f.value}, a {f.type}: launch uses it as a plain bool "
                   f"without evaluating it, and {what} is true, so {name} is always on")
        help_ = ("pass True or False; to choose at launch time, declare a launch argument named "
                 "'emulate_tty' (launch reads that configuration for every process)"
                 if name == "emulate_tty" else
                 "pass True or False; to choose at launch time, use two actions with "
                 "IfCondition / UnlessCondition")
        return message, help_
    if f.kind == "typed-bool":
        message = (f"{f.call} is given {f.value}, a {f.type}: launch accepts only a bool or substitutions "
                   "there (normalize_typed_substitution) and raises \"TypeError: value=... is not an "
                   "instance of <class 'bool'>\" when the description is built")
        return message, ("pass True or False; to choose at launch time, pass a substitution "
                         "(respawn=LaunchConfiguration('respawn'), whose value must be true or false)")
    if f.kind == "plain-number":
        message = (f"{f.call} is given {f.value}, a {f.type}: launch keeps it as is and compares it "
                   "with a number when the process exits and is respawned, which raises "
                   "TypeError ('>' or '<' not supported)")
        example = "respawn_delay=2.0" if name == "respawn_delay" else "respawn_max_retries=3"
        return message, f"pass a number, e.g. {example}; a launch argument cannot set it"
    if f.kind == "entities":
        if f.type == "string":
            when = ("when the process starts launch builds its OnProcessExit handler from it and raises "
                    "\"TypeError: expected all items in 'on_event' iterable to be of type "
                    "'LaunchDescriptionEntity'\"")
        else:
            when = ("when the process exits launch gets it back from its OnProcessExit handler and raises "
                    "\"RuntimeError: expected a LaunchDescriptionEntity from event_handler\"")
        message = f"{f.call} is given {f.value}, a {f.type}, where launch wants actions to run: {when}"
        return message, ("pass an action or a list of actions (on_exit=Shutdown(), on_exit=[LogInfo(...)]); "
                         "to choose at launch time, give those actions a condition")
    if f.kind == "pairs":
        message = (f"{f.call} is given a dict ({f.value}): launch iterates it as (name, value) pairs "
                   "and gets only its keys, so the include fails with \"ValueError: too many values "
                   "to unpack (expected 2)\" (a two-letter key silently sets another argument)")
        return message, "pass launch_arguments={...}.items(), or a list of (name, value) tuples"
    if f.kind == "period":
        message = (f"{f.call} is given the {f.type} {f.value}, where launch accepts only a float, a string or "
                   f"substitutions; building the launch description fails with \"TypeError: "
                   f"'TimerAction' expected 'period' to be one of [<class 'str'>, <class "
                   f"'launch.substitution.Substitution'>, <class 'collections.abc.Iterable'>, <class 'float'>], "
                   f"but got '{f.value}' of type '<class '{f.type}'>'\"")
        return message, (f"write it as a float: period={f.value}.0" if f.type == "int"
                         else "write the number of seconds as a float, e.g. period=3.0")
    if f.kind == "event":
        message = (f"{f.call} is given {f.value}, which is no event: EmitEvent raises \"RuntimeError: "
                   "EmitEvent() expected an event instance\" when the description is built")
        help_ = ("emit the event: from launch.events import Shutdown; EmitEvent(event=Shutdown()); or use "
                 "the launch.actions.Shutdown action itself, without EmitEvent"
                 if "Shutdown" in f.value else "pass an event instance (launch.events.Shutdown(), "
                 "launch_ros.events.lifecycle.ChangeState(...))")
        return message, help_
    if f.kind == "remap-bare":
        message = (f"{f.call} is given {f.value}, one rule without its list: launch_ros takes each string "
                   "for a rule and raises \"TypeError: Expected 'remap_rule' to be one of [<class 'tuple'>]\"")
        return message, "put the rule in a list: remappings=[('from', 'to')]"
    if f.type == "dict":
        what = f"a dict ({f.value}), whose keys launch_ros takes as the rules"
        help_ = "pass a list of (from, to) tuples, e.g. remappings=[('/in', '/out')] or {...}.items()"
    else:
        what, help_ = f"the rule {f.value} as a {f.type}", "write the rule as a tuple: ('from', 'to')"
    message = (f"{f.call} is given {what}; launch_ros accepts only (from, to) tuples and raises "
               f"\"TypeError: Expected 'remap_rule' to be one of [<class 'tuple'>]\"")
    return message, help_
