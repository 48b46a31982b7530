"""Node, container, component and process instantiation (launch_ros ``Node._perform_substitutions``,
``load_composable_nodes.get_composable_node_load_request``)."""
from __future__ import annotations

from dataclasses import replace
from typing import TYPE_CHECKING, Any

from physai_lint.model import launch as ir
from physai_lint.model import values as v
from physai_lint.model.span import Span
from physai_lint.resolve import names
from physai_lint.resolve.evaluate import Scope, yaml_bool
from physai_lint.resolve.model import (
    LIFECYCLE_MANAGERS,
    EffRemap,
    NodeInstance,
    ParamSourceR,
    ResolvedParam,
    ResolvedParamDict,
    ResolvedParamFile,
    StartEdge,
    UnknownParams,
)
from physai_lint.resolve.params import rcl_cli_text, resolve_pvalue

if TYPE_CHECKING:
    from physai_lint.resolve.instantiate import Instantiator

NS, REMAPS, PARAMS = "ros_namespace", "ros_remaps", "global_params"
_ANON = "\0anon"  # launch's launch_configurations['anon'] (``NodeBuilder._anon``)
# rcl flags of a --ros-args section that take the next argument (rcl arguments.c)
_VALUE_FLAGS = frozenset({"-p", "--param", "--params-file", "--log-level", "--log-config-file",
                          "--log-file-name", "-e", "--enclave"})
_REMAP_FLAGS = frozenset({"-r", "--remap"})


def command_line_values(arguments: Any, ros_arguments: Any
                        ) -> list[tuple[str, str | None, Span | None]]:
    """What rcl reads from a node's command line (``rcl_parse_arguments``), in order: (flag, text,
    span) for the value after each flag of a ``--ros-args`` section that takes one (``-r``,
    ``-p``, ``--params-file``...; ``?`` after an unknown argument, which may be any of them), and
    ("", text, ...) for a bare ``from:=to`` outside one (the deprecated remap form rcl still
    reads). ``arguments`` and ``ros_arguments`` are (text or None, value) pairs; launch_ros puts
    ``--ros-args`` before ``ros_arguments``."""
    out: list[tuple[str, str | None, Span | None]] = []
    for section, start_in_ros in ((arguments, False), (ros_arguments, True)):
        in_ros, pending = start_in_ros, None
        for text, value in section:
            if pending is not None:
                out.append((pending, text, v.span_of(value)))
                pending = None
                continue
            if text is None:
                if in_ros:
                    pending = "?"  # an unknown flag: perhaps -r or -p, so the next may be its value
                continue
            if not in_ros:
                if text == "--ros-args":
                    in_ros = True
                elif ":=" in text:
                    out.append(("", text, v.span_of(value)))
                continue
            if text == "--":
                in_ros = False
            elif text in _REMAP_FLAGS or text in _VALUE_FLAGS:
                pending = text
    return out


def command_line_rules(arguments: Any, ros_arguments: Any
                       ) -> list[tuple[str | None, Span | None, bool]]:
    """The remap rules a node's command line gives it, in rcl order: ``-r``/``--remap RULE`` in a
    ``--ros-args`` section, and a bare ``from:=to`` outside one. Each rule comes with its span and
    whether it is in a ``--ros-args`` section (where rcl refuses a rule it cannot parse; outside,
    such a text is not a rule). A rule whose text is unknown is None: it may match anything."""
    return _rules(command_line_values(arguments, ros_arguments))


def _rules(values: list[tuple[str, str | None, Span | None]]
           ) -> list[tuple[str | None, Span | None, bool]]:
    out: list[tuple[str | None, Span | None, bool]] = []
    for flag, text, span in values:
        if flag in _REMAP_FLAGS or flag == "?":
            if text is None or ":=" in text:
                out.append((text, span, True))
        elif flag == "" and text is not None:
            out.append((text, span, False))
    return out


def rule_problem(src: str, dst: str) -> str | None:
    """Why rcl cannot parse the rule ``src:=dst`` (``_rcl_parse_remap_rule``), or None."""
    if src in ("__node", "__name"):
        return (names.validate_node_name(dst) and f'"{dst}" is not a valid node name') or \
            names.rule_lex_problem(dst)
    if src == "__ns":
        if not dst.startswith("/"):
            return f'"{dst}" is not a fully qualified namespace (it must start with "/")'
        return names.validate_namespace(dst) or names.rule_lex_problem(dst)
    for side in (src, dst):
        problem = (names.validate_full_topic_name(side) if side.startswith("/")
                   else names.validate_topic_name(side)) or names.rule_lex_problem(side)
        if problem:
            return f'"{side}": {problem}'
    return None


def split_rule(text: str) -> tuple[str | None, str, str]:
    """(node prefix, match, replacement) of ``[node:]match:=replacement``."""
    src, _, dst = text.partition(":=")
    prefix = None
    if ":" in src and not src.startswith("/") and "://" not in src:
        prefix, _, src = src.partition(":")
    return prefix, src, dst


class NodeBuilder:
    def __init__(self, inst: Instantiator) -> None:
        self.inst = inst
        self.count = 0
        self.anon_count = 0  # the AnonName keys given out (``_anon``)
        self.by_action: dict[str, list[str]] = {}  # "<file>#<action id>" -> node ids
        self.by_id: dict[str, NodeInstance] = {}  # every node registered, by id
        self.pending: list[tuple[str, str, str, Span, float | None]] = []  # key, node, reason, span, delay
        # LoadComposableNodes run before their target container action: (span, container key, file)
        self.early_loads: list[tuple[Span, str, str]] = []
        self.watched: list[tuple[ir.EventHandler, str | None, str]] = []

    # ---- helpers ------------------------------------------------------------------------------
    def _id(self) -> str:
        self.count += 1
        return f"n{self.count}"

    def _eval(self, value: v.Value | None, scope: Scope) -> tuple[str | None, bool]:
        """(evaluated, given): given False when the field was not written at all."""
        if value is None:
            return None, False
        return self.inst.ev.eval(value, scope), True

    def _anon(self, value: v.Value | None, scope: Scope) -> str | None:
        """``NodeInstance.anon`` of a name given as ``$(anon ID)`` alone. AnonName.perform keeps
        the name it generates for ID in ``launch_configurations['anon']``, a dict made where it is
        first needed: a scope pushed later copies the configurations shallowly and shares it, one
        made inside a scope is dropped with that scope. Kept here under a key no launch
        configuration can have, so the same sharing holds."""
        if value is None or len(value) != 1 or not isinstance(value[0], v.Anon):
            return None
        ident = self.inst.ev.eval(value[0].name, scope)
        if not ident:
            return None
        cache = scope.configs.get(_ANON)
        if not isinstance(cache, dict):
            cache = scope.configs[_ANON] = {}
        if ident not in cache:
            self.anon_count += 1
            cache[ident] = f"{ident}#{self.anon_count}"
        return str(cache[ident])

    def _namespace(self, raw: str | None, given: bool, scope: Scope) -> tuple[str | None, bool]:
        """(absolute namespace or None when unknown, whether launch specifies one)."""
        if (given and raw is None) or (NS in scope.configs and scope.configs[NS] is None):
            return None, True
        combined = names.make_namespace_absolute(names.prefix_namespace(scope.configs.get(NS), raw))
        return (combined, True) if combined is not None else ("/", False)

    def _locate(self, path: str | None) -> tuple[str | None, str]:
        if path is None:
            return None, "unknown"
        pk = self.inst.packages
        if pk is None:
            return None, "unknown"
        if not path.strip():
            return None, "missing"  # launch_ros: '' is not a file (skipped with a warning, or an error)
        loc = pk.locate(path)
        if loc.status == "ok" and loc.source and pk.is_dir(loc.source):
            return loc.source, "missing"  # a directory is not a parameter file
        return loc.source, loc.status

    def global_parameter(self, name: str, pvalue: v.PValue, scope: Scope, span: Span
                         ) -> tuple[ResolvedParam, ResolvedParam]:
        """A ``SetParameter``'s value as ``SetParameter.execute`` evaluates it (what a component's
        load request carries), and as a process gets it, through ``-p name:=text``."""
        rp = self._param(name, pvalue, scope, span)
        return rp, _cli_typed(rp)

    def _param(self, name: str, pvalue: v.PValue, scope: Scope, span: Span) -> ResolvedParam:
        """``resolve_pvalue``, with the command line of a value that is one ``Command``."""
        ev = self.inst.ev
        ev.last_command = None
        rp = resolve_pvalue(name, pvalue, lambda x: ev.eval(x, scope), span)
        if rp.value is None and rp.raw is None and ev.last_command is not None and \
                isinstance(pvalue, v.PSubst) and pvalue.value_type is None and len(pvalue.value) == 1 and \
                pvalue.value[0] is ev.last_command[0] and ev.last_command[1] is not None:
            rp = replace(rp, command=ev.last_command[1])
        return rp

    def _global_sources(self, scope: Scope, node_id: str, node_span: Span,
                        own: tuple[ir.ParamSource, ...], composable: bool = False
                        ) -> tuple[list[EffRemap], list[ParamSourceR]]:
        """The global remaps and parameters a node gets (``own``: its own parameters, for the
        scoped-group leaks that reach it). A process gets each SetParameter as ``-p name:=text``,
        which rcl types again; a component gets the evaluated value itself, normalized by
        launch_ros (``get_composable_node_load_request`` -> ``normalize_parameter_dict``)."""
        remaps: list[EffRemap] = []
        remap_list = scope.configs.get(REMAPS) or []
        for src, dst, span, reached in remap_list:
            remaps.append(EffRemap(src, dst, span, "global"))
            reached.append(node_id)
        params: list[ParamSourceR] = []
        param_list = scope.configs.get(PARAMS) or []
        for item in param_list:
            if item[0] == "param":
                _, name, rp, span, cli = item
                if name is None:
                    params.append(UnknownParams("SetParameter with an unknown name", span))
                else:
                    params.append(ResolvedParamDict((rp if composable else cli,), span, "global", "/**"))
            else:
                _, path, _, span = item
                params.append(self._file(path, span, "global", False, scope))
        if self.inst.leaks:
            self.inst.leaks_reaching(remap_list, node_id, node_span, _remap_matters)
            sets = {e.name for src in own if isinstance(src, ir.ParamDict) for e in src.entries}
            self.inst.leaks_reaching(param_list, node_id, node_span,
                                     lambda lst, i: _parameter_matters(lst, i, sets, self.inst.leaks))
        return remaps, params

    def _file(self, path: str | None, span: Span, origin: str, allow_substs: bool, scope: Scope
              ) -> ParamSourceR:
        """A params file source; a temporary file written by a substitution carries its model."""
        from physai_lint.resolve.nav2_common import VirtualFile, with_substitutions

        distro = getattr(self.inst.packages, "distro", "humble")
        virtual = self.inst.ev.virtual.get(path) if path is not None else None
        if virtual is not None:
            if allow_substs:
                derived = with_substitutions(self.inst.ev, path, span, scope)  # type: ignore[arg-type]
                virtual = virtual if derived is False else derived
            model = virtual.param_model(distro) if isinstance(virtual, VirtualFile) else None
            status = "ok" if model is not None else "unknown"
            return ResolvedParamFile(path, None, status, span, origin, allow_substs,  # type: ignore[arg-type]
                                     model=model, derived_from=virtual.source if virtual else None)
        source, status = self._locate(path)
        if allow_substs and status not in ("ok", "missing", "not_installed"):
            # launch_ros performs the $(var ...) of a file that cannot be read here (its path is
            # unknown, or outside the workspace): it may read any launch configuration, so an
            # includer's argument is not "ignored" nor a declared one "unused"
            self.inst.reads_every_configuration(span)
        if allow_substs and status == "ok" and path:
            derived = with_substitutions(self.inst.ev, path, span, scope)
            if derived is not False:
                model = derived.param_model(distro) if isinstance(derived, VirtualFile) else None
                if model is None:  # its $(...) cannot be performed statically: its values are unknown
                    return ResolvedParamFile(path, None, "unknown", span, origin, allow_substs,  # type: ignore[arg-type]
                                             derived_from=source)
                return ResolvedParamFile(path, source, "ok", span, origin, allow_substs,  # type: ignore[arg-type]
                                         model=model, derived_from=source)
        return ResolvedParamFile(path, source, status, span, origin, allow_substs)  # type: ignore[arg-type]

    def _unopened(self, value: v.Value, scope: Scope) -> ResolvedParamFile | None:
        """A RewrittenYaml / ReplaceString whose source file does not exist after install: launch
        fails when the substitution opens it."""
        if len(value) != 1 or not isinstance(value[0], (v.RewrittenYaml, v.ReplaceString)):
            return None
        part = value[0]
        path = self.inst.ev.eval(part.path, scope)
        if path is None or path not in self.inst.ev.unopened:
            return None
        status, source = self.inst.ev.unopened[path]
        span = part.span or v.span_of(part.path)
        if span is None:
            return None
        return ResolvedParamFile(path, source, status, span, "node",  # type: ignore[arg-type]
                                 opened_by=type(part).__name__)

    def _own_params(self, sources: tuple[ir.ParamSource, ...], scope: Scope, key: str
                    ) -> list[ParamSourceR]:
        out: list[ParamSourceR] = []
        for src in sources:
            if isinstance(src, ir.ParamFile):
                path = self.inst.ev.eval(src.path, scope)
                unopened = self._unopened(src.path, scope) if path is None else None
                out.append(unopened or self._file(path, src.span, "node", src.allow_substs, scope))
            elif isinstance(src, ir.ParamDict):
                params = tuple(self._param(e.name, e.value, scope, e.span) for e in src.entries)
                out.append(ResolvedParamDict(params, src.span, "node", key))
            else:
                out.append(UnknownParams(src.reason, src.span))
        return out

    def _remaps(self, remappings: tuple[ir.Remapping, ...], scope: Scope) -> list[EffRemap]:
        out = []
        for r in remappings:
            src, dst = self.inst.ev.eval(r.src, scope), self.inst.ev.eval(r.dst, scope)
            prefix = None
            if src is not None and ":" in src and not src.startswith("/"):
                prefix, _, src = src.partition(":")
            out.append(EffRemap(src, dst, r.span, "node", prefix))
        return out

    def _command_line_params(self, values: list[tuple[str, str | None, Span | None]], where: Span,
                             scope: Scope) -> list[ParamSourceR]:
        """The parameters a node's own command line gives it: ``-p [node:]name:=value`` (typed by
        rcl's YAML value parser, under node key ``/**`` or ``node``) and ``--params-file path``.
        launch_ros puts them before its own ``--ros-args`` section, so every SetParameter and
        ``parameters=`` entry overrides them (rcl merges all in command-line order)."""
        out: list[ParamSourceR] = []
        for flag, text, span in values:
            at = span or where
            if flag == "--params-file":
                out.append(self._file(text, at, "command_line", False, scope))
            elif flag == "?" and (text is None or ":=" in text):
                # after an argument not known statically: perhaps -p, perhaps -r
                out.append(UnknownParams("a command-line argument that may be -p", at))
            elif flag in ("-p", "--param"):
                if text is None:
                    out.append(UnknownParams("a command-line parameter with an unknown value", at))
                elif ":=" in text:
                    prefix, name, raw = split_rule(text)
                    if name:
                        distro = getattr(self.inst.packages, "distro", "humble")
                        out.append(ResolvedParamDict((_rcl_value_param(name, raw, at, distro),), at,
                                                     "node", prefix or "/**"))
        return out

    @staticmethod
    def _command_line_remaps(values: list[tuple[str, str | None, Span | None]], where: Span
                             ) -> list[EffRemap]:
        out = []
        for text, span, in_ros in _rules(values):
            if text is None:
                out.append(EffRemap(None, None, span or where, "node"))
                continue
            prefix, src, dst = split_rule(text)
            if not in_ros and rule_problem(src, dst) is not None:
                continue  # not a rule to rcl: an argument of the program
            out.append(EffRemap(src, dst, span or where, "node", prefix))
        return out

    def _register(self, inst_: NodeInstance, key: str | None, after: str | None = None) -> None:
        """Add a node with the timer and event handler it starts under; ``key``: the action an
        event handler's target_action names it by (None for a composable node: a handler naming
        its container or its LoadComposableNodes does not watch the component). ``after``: the
        container a component is loaded into, which already waits for what the component shares
        with it (plan delays add up along the container edge)."""
        fr = self.inst.frame
        res = self.inst.result
        res.nodes.append(inst_)
        self.by_id[inst_.id] = inst_
        if key is not None:
            self.by_action.setdefault(key, []).append(inst_.id)
        delay = fr.delay
        if after is not None and delay is not None:
            before = res.delays.get(after, 0.0)
            delay = None if before is None else max(0.0, delay - before)
        if fr.deferred == "timer" or fr.delay not in (0.0,):
            res.delays[inst_.id] = delay
        for tkey, reason, span in fr.trigger:
            if after is None or not any(p[0] == tkey and p[1] == after for p in self.pending):
                self.pending.append((tkey, inst_.id, reason, span, fr.delay))

    # ---- actions ------------------------------------------------------------------------------
    def node(self, a: ir.NodeAction, scope: Scope) -> None:
        fr = self.inst.frame
        package, package_from_config = self.inst.ev.eval_noting_configs(a.package, scope)
        executable, _ = self._eval(a.executable, scope)
        name, name_given = self._eval(a.name, scope)
        ns_raw, ns_given = self._eval(a.namespace, scope)
        args = tuple(self.inst.ev.eval(x, scope) for x in (a.arguments or ()))
        ros_args = tuple(self.inst.ev.eval(x, scope) for x in (a.ros_arguments or ()))
        # The user's rules come first on the command line: rcl applies the first that matches, so
        # they win over launch's -r __node:=/__ns: (name=, namespace=), SetRemap and remappings=.
        command_line = command_line_values(zip(args, a.arguments or ()),
                                           zip(ros_args, a.ros_arguments or ()))
        cl_remaps = self._command_line_remaps(command_line, a.span)
        renamed = next((r for r in cl_remaps if r.src in ("__node", "__name") and r.node_prefix is None), None)
        if renamed is not None and renamed.dst is not None:
            name, name_given = renamed.dst, True
        moved = next((r for r in cl_remaps if r.src == "__ns" and r.node_prefix is None), None)
        if moved is not None and moved.dst is not None:
            ns_raw, ns_given = moved.dst, True
        cl_params = self._command_line_params(command_line, a.span, scope)
        own_remaps = self._remaps(a.remappings, scope)
        keyed = name_given  # launch_ros keys a parameter dict by name= alone (node.py)
        if not name_given:
            # remappings=[('__node', 'x')]: launch puts them after its own -r __node:=<name>, so
            # they rename the node only when name= is not given (rcl: the first rule wins)
            rename = next((r for r in own_remaps if r.src == "__node" and r.node_prefix is None), None)
            if rename is not None:
                name, name_given = rename.dst, True
        namespace, ns_specified = self._namespace(ns_raw, ns_given, scope)
        fqn = names.join_fqn(namespace, name) if (namespace and name) else None
        anon = self._anon(a.name, scope) if name is None else None
        node_id = self._id()
        remaps, gparams = self._global_sources(scope, node_id, a.span, a.parameters)
        key = fqn if (keyed and ns_specified and fqn) else "/**"
        params = cl_params + gparams + self._own_params(a.parameters, scope, key)
        remaps = cl_remaps + remaps + own_remaps
        inst_ = NodeInstance(
            id=node_id, kind=a.kind, package=package, executable=executable, name=name,
            namespace=namespace, fqn=fqn, active=fr.active, remaps=remaps, param_sources=params,
            span=a.span, file=fr.file, action=a, action_id=f"{fr.file}#{a.id}",
            include_chain=fr.chain[:-1], name_explicit=name_given, namespace_explicit=ns_specified,
            arguments=args, in_timer=fr.deferred is not None, timer_lost=fr.lost,
            spans={k: s for k, s in a.field_spans}, package_from_config=package_from_config, anon=anon,
        )
        self._register(inst_, inst_.action_id)
        self._note_run(inst_)
        for value in a.other:
            self.inst.ev.eval(value, scope)
        self._respawn(a.respawn, scope, inst_.spans.get("respawn"))
        for cn in a.composable_nodes:
            self.component(cn, scope, inst_.fqn, inst_.id, inst_.namespace, inst_.action_id)

    def component(self, cn: ir.ComposableNode, scope: Scope, container: str | None,
                  container_id: str | None, container_ns: str | None, key: str,
                  honours_condition: bool = True, load_condition: ir.Condition | None = None) -> None:
        """``honours_condition``: False where launch_ros never evaluates the description's
        condition (humble's LoadComposableNodes: the component is loaded whatever it says);
        ``load_condition``: the condition of the action loading it."""
        fr = self.inst.frame
        active = fr.active
        ignored = cn.condition is not None and not honours_condition
        from physai_lint.resolve.instantiate import combine

        for c in (cn.branch, cn.condition):
            if c is None:
                continue
            # evaluated even where launch_ros ignores it: what it reads stays read (no L102 on
            # top of L115), and it is how the file means to be run once the condition is moved
            cond = self.inst.ev.condition(c.kind, c.value, scope, c.span)
            if c is cn.branch or not ignored:
                active = combine(active, cond)
        package, package_from_config = self.inst.ev.eval_noting_configs(cn.package, scope)
        plugin, _ = self._eval(cn.plugin, scope)
        name, name_given = self._eval(cn.name, scope)
        ns_raw, ns_given = self._eval(cn.namespace, scope)
        namespace, specified = self._namespace(ns_raw, ns_given, scope)
        # rclcpp_components loads a component with use_global_arguments(false): the container's own
        # command line (-r __ns:=, --params-file) reaches it only with extra_arguments
        # forward_global_arguments: true (component_manager.cpp :: create_node_options)
        extra = tuple(resolve_pvalue(key, value, lambda x: self.inst.ev.eval(x, scope), span)
                      for key, value, span in cn.extra_arguments)  # read when it is loaded
        forward = _forwards_global_arguments(extra)
        if not specified:
            # otherwise launch sends no namespace and the node gets its constructor's default, the
            # root namespace
            if forward is None:  # unknown: known only when both ways give the root namespace
                namespace = "/" if container_ns == "/" else None
            else:
                namespace = container_ns if forward else "/"
        fqn = names.join_fqn(namespace, name) if (namespace and name) else None
        node_id = self._id()
        remaps, gparams = self._global_sources(scope, node_id, cn.span, cn.parameters,
                                               composable=True)
        params = self._forwarded(container_id, forward, cn.span) + gparams + \
            self._own_params(cn.parameters, scope, fqn or "/**")
        inst_ = NodeInstance(
            id=node_id, kind="composable_node", package=package, executable=plugin, name=name,
            namespace=namespace, fqn=fqn, active=active, remaps=remaps + self._remaps(cn.remappings, scope),
            param_sources=params, span=cn.span, file=fr.file, action=cn,
            action_id=f"{fr.file}#{cn.id or cn.span.line}", include_chain=fr.chain[:-1],
            name_explicit=name_given, namespace_explicit=specified, container=container,
            container_id=container_id, package_from_config=package_from_config, extra_args=extra,
        )
        if ignored and active is not False and not _same_condition(cn.condition, load_condition):
            raw = cn.condition.raw if not cn.condition.raw.endswith("(...)") else ""  # type: ignore[union-attr]
            self.inst.result.ignored_conditions.append((cn.condition.span, raw, fqn))  # type: ignore[union-attr]
        # loaded when the action loading it runs: after the timer or the event that runs that
        self._register(inst_, None, container_id)
        if container_id is not None:
            self.inst.add_edge(container_id, node_id, "container", cn.span, None)

    def _forwarded(self, container_id: str | None, forward: bool | None, span: Span
                   ) -> list[ParamSourceR]:
        """The container's parameter sources a component reads with forward_global_arguments:
        rclcpp resolves the context's global arguments (the container's --params-file and -p,
        read by rcl) before the load request's parameters (``resolve_parameter_overrides``)."""
        if container_id is None or forward is False:
            return []
        sources = self._node(container_id).param_sources
        if not sources:
            return []
        if forward is None:
            return [UnknownParams("the container's parameters, if forward_global_arguments is set", span)]
        return [replace(s, origin="forwarded") if isinstance(s, (ResolvedParamFile, ResolvedParamDict))
                else s for s in sources]

    def load(self, a: ir.LoadComposableNodes, scope: Scope) -> None:
        container: str | None = None
        container_id: str | None = None
        container_ns: str | None = None
        if a.target_id is not None:
            key = f"{self.inst.frame.file}#{a.target_id}"
            ids = self.by_action.get(key, [])
            if ids:
                node = self._node(ids[-1])
                container, container_id, container_ns = node.fqn, node.id, node.namespace
            fr = self.inst.frame
            if fr.active is not False and fr.deferred is None and \
                    all(self._node(i).active is False for i in ids):
                # LoadComposableNodes.execute reads the container action's node_name, set only
                # once that action has executed: in the synchronous first pass, only an action
                # visited before this one has
                self.early_loads.append((a.span, key, fr.file))
        elif a.target is not None:
            text = self.inst.ev.eval(a.target, scope)
            if text is not None:
                container = names.make_namespace_absolute(text)
                for n in self.inst.result.nodes:
                    if n.kind == "container" and n.fqn == container:
                        container_id, container_ns = n.id, n.namespace
        # humble's LoadComposableNodes.execute loads every description, never asking its condition
        # (ComposableNodeContainer.execute filters its own by theirs); iron and later ask
        # (ros2/launch_ros#339, load_composable_nodes.py :: get_composable_node_load_request)
        honours = getattr(self.inst.packages, "distro", "humble") != "humble"
        for cn in a.nodes:
            self.component(cn, scope, container, container_id, container_ns,
                           f"{self.inst.frame.file}#{a.id}", honours, a.condition)

    def _respawn(self, value: v.Value | None, scope: Scope, span: Span | None = None) -> None:
        """``respawn=`` as text or substitutions: ``ExecuteLocal.prepare`` types what it substitutes
        with ``perform_typed_substitution(context, respawn, bool)`` (yaml.safe_load), which raises
        ValueError for anything but a YAML boolean ('0' and '1' included, unlike IfCondition).
        ``span``: the ``respawn=`` argument, where the value itself is written elsewhere (a
        variable holding a LaunchConfiguration)."""
        if value is None:
            return
        ev = self.inst.ev
        text = ev.eval(value, scope)
        if text is not None and yaml_bool(text) is None and ev.on_bad_condition is not None:
            ev.on_bad_condition(span or v.span_of(value), text, "respawn")  # L109, with the conditions

    def process(self, a: ir.ExecuteProcess, scope: Scope) -> None:
        fr = self.inst.frame
        cmd = tuple(self.inst.ev.eval(x, scope) for x in (a.cmd or ()))
        for value in a.other:
            self.inst.ev.eval(value, scope)
        self._respawn(a.respawn, scope, a.respawn_span)
        executable = cmd[0] if cmd else None
        inst_ = NodeInstance(
            id=self._id(), kind="process", package=None, executable=executable, name=None,
            namespace=None, fqn=None, active=fr.active, remaps=self._ros2_run_remaps(cmd, a),
            param_sources=[], span=a.span,
            file=fr.file, action=None, action_id=f"{fr.file}#{a.id}", include_chain=fr.chain[:-1],
            arguments=cmd[1:], in_timer=fr.deferred == "timer",
        )
        self._register(inst_, inst_.action_id)
        self._note_run(inst_)

    def _note_run(self, inst_: NodeInstance) -> None:
        """``LaunchResult.repeated``: a process action object run again in the same load of its
        file (``ExecuteLocal.execute`` raises "executed more than once"); ``at_shutdown``: one an
        OnShutdown handler runs."""
        fr = self.inst.frame
        if fr.active is not False and fr.at_shutdown:
            self.inst.result.at_shutdown.append((inst_.id, fr.ran_by))
        if fr.active is not False:
            first = self.inst.executed.setdefault((fr.load, inst_.action_id), inst_.id)
            if first != inst_.id:
                again = fr.ran_by if fr.deferred not in (None, "timer") else None
                self.inst.result.repeated.append((first, inst_.id, again))

    def _ros2_run_remaps(self, cmd: tuple[str | None, ...], a: ir.ExecuteProcess) -> list[EffRemap]:
        """The remap rules of ``ros2 run <package> <executable> [args]``: the arguments after the
        executable reach it as its command line (``--ros-args -r __ns:=...``), which rcl parses
        like a Node's. Other commands: none known."""
        if len(cmd) < 5 or cmd[0] is None or cmd[0].rsplit("/", 1)[-1] != "ros2" or cmd[1] != "run" \
                or any(w is None or w.startswith("-") for w in cmd[2:4]):
            return []
        return self._command_line_remaps(command_line_values(zip(cmd[4:], (a.cmd or ())[4:]), ()), a.span)

    def watch(self, h: ir.EventHandler, key: str | None, fr: Any) -> None:
        if key is not None and fr.active is not False:  # disabled by its own condition: never registered
            self.watched.append((h, key, fr.file))

    def _node(self, node_id: str) -> NodeInstance:
        return self.by_id[node_id]

    def finish(self) -> None:
        res = self.inst.result
        opaque_files = {s.file for s, _ in res.opaque}
        for key, after, reason, span, delay in self.pending:
            befores = self.by_action.get(key, [])
            for before in befores:
                res.edges.append(StartEdge(before, after, reason, span, delay))
            if not befores and self.inst.visited.get(key, "never") == "never" and span.file not in opaque_files:
                res.unstartable.append(after)  # its handler's target never runs: no edge to wait on
        for h, key, file in self.watched:
            assert key is not None
            seen = self.inst.visited.get(key, "never")
            if file in opaque_files:
                continue
            if seen == "never":
                why = "never added to the launch description"
            elif seen is False:
                why = "disabled by its condition"
            else:
                continue
            res.never_started.append((h.span, f"the target action of its {_EVENT_CLASS.get(h.event, h.event)} is {why}"))
        for span, key, file in self.early_loads:
            if file in opaque_files:
                continue
            seen = self.inst.visited.get(key, "never")
            ids = self.by_action.get(key, [])
            line = self._node(ids[0]).span.line if ids else None
            if seen == "never":
                why = "is never added to the launch description"
            elif seen is False:
                why = "is disabled by its condition"
            elif not ids:
                continue
            elif key in self.inst.first_pass:
                why = "comes after it in the launch description"
            else:
                why = "only runs later (from an event handler or a timer)"
            res.early_loads.append((span, line, why))
        for late in self.inst.late_handlers.values():
            for h in late:
                res.never_started.append((h.span, LATE_COMPLETION))
        if self.inst.triggered and not opaque_files:
            self._trigger_cycles()

    def _trigger_cycles(self) -> None:
        """``LaunchResult.trigger_cycles``: actions visited only in event handlers' actions whose
        targets, through an action that is no node, wait for each other. (The resolver walks a
        handler's actions as if its event came; a cycle of nodes alone is the plan's.)"""
        from physai_lint.resolve.roots import nodes_on_cycles

        inst = self.inst
        started = set(inst.free)
        waiting = dict(inst.triggered)
        self._transition_waits(waiting)
        changed = True
        while changed:  # an action starts once every target of one of its visits has
            changed = False
            for key, (_, visits) in list(waiting.items()):
                if key in started or any(all(t[0] in started for t in visit) for visit in visits):
                    started.add(key)
                    del waiting[key]
                    changed = True
        inst.result.blocked.extend(nid for key in sorted(waiting) for nid in self.by_action.get(key, ())
                                   if self._node(nid).active is not False)
        graph: dict[str, dict[str, tuple[str, Span]]] = {}
        for key, (_, visits) in waiting.items():
            for visit in visits:
                for tkey, event, span in visit:
                    if tkey in waiting:
                        graph.setdefault(key, {}).setdefault(tkey, (event, span))
        on_cycles = nodes_on_cycles({k: set(v) for k, v in graph.items()})
        done: set[str] = set()
        for key in sorted(on_cycles):
            if key in done or key in self.by_action:
                continue  # a cycle is reported from its first member that is no node
            path = _cycle_through(key, graph, on_cycles)
            if path is None:
                continue
            done.update(path)
            steps, spans, requests = [], [], []
            for a, b in zip(path, path[1:] + path[:1]):
                event, span = graph[a][b]
                if event == _CHANGE_REQUEST:
                    steps.append(f"{self._label(a)} changes state only when {self._label(b)} requests it")
                    requests.append(span)
                else:
                    steps.append(f"{self._label(a)} waits for {EVENT_VERB.get(event, event)} of {self._label(b)}")
                    spans.append(span)
            text = " -> ".join(self._label(k) for k in [*path, path[0]])
            # reported at a handler of the cycle; the EmitEvents that request transitions are related
            order = sorted(set(spans), key=lambda s: (s.file, s.line, s.col)) + \
                sorted(set(requests) - set(spans), key=lambda s: (s.file, s.line, s.col))
            inst.result.trigger_cycles.append((order[0], text, ", ".join(steps), tuple(order[1:]),
                                               any(k.endswith("@transitions") for k in path)))

    def _transition_waits(self, waiting: dict[str, Any]) -> None:
        """Lifecycle state transitions the launch itself requests, as actions of ``waiting``: when
        the launch emits ChangeState for a lifecycle node and nothing else manages it (a lifecycle
        manager; a LifecycleTransition is opaque), its transitions come only from those
        EmitEvents. An OnStateTransition handler for it then also waits for the transitions
        (``<node key>@transitions``), which wait for an EmitEvent that does not itself wait for
        them: the first transition cannot come from a handler of a later one."""
        inst = self.inst
        # a ChangeState whose target is not known (matches_node_name, a lambda) may be any node's
        if not inst.change_requests or any(t is None for t, _ in inst.result.lifecycle_changes) or any(
                (n.package, n.executable) in LIFECYCLE_MANAGERS and n.active is not False
                for n in inst.result.nodes):
            return
        for key, (action, visits) in list(waiting.items()):
            extended = []
            for visit in visits:
                more = tuple((f"{t}@transitions", event, span) for t, event, span in visit
                             if event == "on_state_transition" and t in inst.change_requests)
                extended.append(visit + more)
            waiting[key] = (action, extended)
        for target, emits in inst.change_requests.items():
            if any(isinstance(self._node(i).action, ir.NodeAction) and
                   self._node(i).action.autostart is not False  # type: ignore[union-attr]
                   for i in self.by_action.get(target, ())):
                continue  # LifecycleNode(autostart=True) (jazzy on) brings itself up
            pseudo = f"{target}@transitions"
            sources = [((ekey, _CHANGE_REQUEST, span),) for ekey, span in emits
                       if not all(any(t[0] == pseudo for t in v) for v in waiting.get(ekey, (None, [()]))[1])]
            waiting[pseudo] = (None, sources)

    def _label(self, key: str) -> str:
        """An action of a trigger cycle, for messages: a node by its name, else its class and line."""
        if key.endswith("@transitions"):
            return self._label(key[:-len("@transitions")])
        ids = self.by_action.get(key)
        if ids:
            n = self._node(ids[0])
            return f'"{n.fqn or n.executable or n.package}"'
        a = self.inst.triggered[key][0]
        return f"{_ACTION_CLASS.get(type(a).__name__, type(a).__name__)} (line {a.span.line})"


# Why an OnExecutionComplete handler registered after its target never fires (checks/startup.py
# gives it its own help).
LATE_COMPLETION = ("its target action was already run when the handler was registered, and launch "
                   "only emits ExecutionComplete for an action visited while a handler for it exists "
                   "(Action.visit)")
# The lifecycle state machine rcl_lifecycle publishes TransitionEvents for (its state labels;
# rcl_lifecycle/src/default_state_machine.c :: rcl_lifecycle_init_default_state_machine): each
# transition goes from a primary state to a transition state, then to the state it ends in.
LIFECYCLE_STEPS: dict[str, tuple[str, ...]] = {
    "unconfigured": ("configuring", "shuttingdown"),
    "inactive": ("cleaningup", "activating", "shuttingdown"),
    "active": ("deactivating", "shuttingdown"),
    "finalized": (),
    "configuring": ("inactive", "unconfigured", "errorprocessing"),
    "cleaningup": ("unconfigured", "inactive", "errorprocessing"),
    "activating": ("active", "inactive", "errorprocessing"),
    "deactivating": ("inactive", "active", "errorprocessing"),
    "shuttingdown": ("finalized", "errorprocessing"),
    "errorprocessing": ("unconfigured", "finalized"),
}


NO_TRANSITION = "no TransitionEvent goes"
NO_LABEL = "is no lifecycle state label"


def lifecycle_mismatch(start: str | None, goal: str | None) -> str | None:
    """Why ``OnStateTransition(start_state=start, goal_state=goal)`` matches no TransitionEvent
    (it compares the event's state labels with the strings given), or None."""
    for what, label in (("start_state", start), ("goal_state", goal)):
        if label is not None and label not in LIFECYCLE_STEPS:
            return (f'its {what} "{label}" {NO_LABEL} (they are '
                    f'{", ".join(sorted(LIFECYCLE_STEPS))}), and OnStateTransition compares labels')
    if start is None or goal is None or goal in LIFECYCLE_STEPS[start]:
        return None
    via = [m for m in LIFECYCLE_STEPS[start] if goal in LIFECYCLE_STEPS[m]]
    hint = f' (it passes through "{via[0]}": "{start}" -> "{via[0]}", then "{via[0]}" -> "{goal}")' if via else ""
    return f'{NO_TRANSITION} from "{start}" to "{goal}"{hint}'



def never_fires_help(why: str) -> str:
    """The help of S102 for a handler that never fires because of ``why``
    (``LaunchResult.never_started``)."""
    if why == LATE_COMPLETION:
        return "register the handler before its target action (put the RegisterEventHandler first in the " \
               "launch description)"
    if why.startswith(NO_TRANSITION):
        return "give goal_state alone (the state the transition ends in), or a start_state and goal_state " \
               "one step apart in the lifecycle state machine"
    if NO_LABEL in why:
        return "use a state label: unconfigured, inactive, active, finalized, or a transition state"
    return "add the target action to the launch description, or register the handler under the same " \
           "condition as its target"


# A lifecycle node's transitions wait for an EmitEvent(ChangeState) (``_transition_waits``).
_CHANGE_REQUEST = "change_request"

# What a handler of each event waits for, in messages ('"b" waits for start of "a"').
EVENT_VERB = {"on_process_start": "start", "on_process_exit": "exit", "on_execution_complete": "completion",
              "on_state_transition": "a state transition"}
_ACTION_CLASS = {"Timer": "TimerAction", "Group": "GroupAction", "Include": "IncludeLaunchDescription",
                 "NodeAction": "Node", "EventHandler": "RegisterEventHandler",
                 "OpaqueAction": "OpaqueFunction"}


def _same_condition(a: ir.Condition | None, b: ir.Condition | None) -> bool:
    """The same condition written twice (kind and value, wherever each was written)."""
    return a is not None and b is not None and a.kind == b.kind and _unspanned(a.value) == _unspanned(b.value)


def _unspanned(x: Any) -> Any:
    """A model value as nested tuples without its positions."""
    import dataclasses

    if dataclasses.is_dataclass(x) and not isinstance(x, type):
        return (type(x).__name__, *(_unspanned(getattr(x, f.name)) for f in dataclasses.fields(x)
                                    if f.name != "span"))
    if isinstance(x, tuple):
        return tuple(_unspanned(i) for i in x)
    return x


def _cycle_through(key: str, graph: dict[str, dict[str, Any]], members: set[str]) -> list[str] | None:
    """A shortest cycle from ``key`` back to it along ``graph`` (breadth first, targets sorted)."""
    parent: dict[str, str] = {}
    frontier = [key]
    while frontier:
        nxt = []
        for k in frontier:
            for t in sorted(graph.get(k, ())):
                if t == key:
                    path = [k]
                    while path[-1] != key:
                        path.append(parent[path[-1]])
                    return path[::-1]
                if t in members and t not in parent:
                    parent[t] = k
                    nxt.append(t)
        frontier = nxt
    return None


# The handler classes behind ``EventHandler.event`` (launch.event_handlers, launch_ros's
# OnStateTransition), for messages.
_EVENT_CLASS = {"on_process_start": "OnProcessStart", "on_process_exit": "OnProcessExit",
                "on_execution_complete": "OnExecutionComplete", "on_process_io": "OnProcessIO",
                "on_state_transition": "OnStateTransition", "on_shutdown": "OnShutdown",
                "on_include_launch_description": "OnIncludeLaunchDescription"}


def _remap_matters(lst: list[Any], i: int) -> bool:
    """Whether global remap ``i`` can change a node: rcl applies the first rule that matches, so
    not when an earlier rule has the same (known) source name."""
    src = lst[i][0]
    return src is None or not any(lst[j][0] == src for j in range(i))


def _parameter_matters(lst: list[Any], i: int, own: set[str], leaks: dict[int, Any]) -> bool:
    """Whether global parameter item ``i`` can change what a node gets. A parameter file always
    may. A SetParameter does not when the node sets that name itself (its own parameters come
    after the global ones), when a later SetParameter sets it (the last wins), or when the last one
    before it for that name that is not itself a leak gave the same known value."""
    item = lst[i]
    if item[0] != "param" or item[1] is None:
        return True
    name = item[1]
    if name in own or any(lst[j][0] == "param" and lst[j][1] == name for j in range(i + 1, len(lst))):
        return False
    for j in range(i - 1, -1, -1):
        if lst[j][0] == "file":
            return True  # the file may have set it in between
        if lst[j][1] == name and id(lst[j]) not in leaks:
            before, value = lst[j][2].value, item[2].value
            return before is None or value is None or (type(before), before) != (type(value), value)
    return True


def _rcl_value_param(name: str, text: str, span: Span, distro: str) -> ResolvedParam:
    """``-p name:=text`` as ``rcl_parse_yaml_value`` reads it: the text is a YAML value (a flow
    list is an array, a quoted text a string), typed by rcl's rules; None when rcl rejects it (a
    mapping is no value to it)."""
    from physai_lint.params.loader import load_param_file

    if "\n" in text or "\r" in text:
        return ResolvedParam(name, None, span, text, "rcl")
    model = load_param_file("<command line>", f"n:\n  ros__parameters:\n    p: {text}\n", distro)
    value = None
    if model.ok and model.blocks and len(model.blocks[0].params) == 1 \
            and model.blocks[0].params[0].name == "p":
        value = model.blocks[0].params[0].value
    return ResolvedParam(name, value, span, text, "rcl")


def _cli_typed(rp: ResolvedParam) -> ResolvedParam:
    """``SetParameter`` goes through ``-p name:=str(value)``: rcl types that text again."""
    text = rcl_cli_text(rp.value)
    if text is None:
        return rp
    try:
        from physai_lint.params.typing import rcl_type_scalar

        _, value = rcl_type_scalar(text, False, None, "humble")
    except Exception:  # the params package is optional for this conversion
        return rp
    return ResolvedParam(rp.name, value, rp.span, text, "yaml")


def _forwards_global_arguments(extra: tuple[ResolvedParam, ...]) -> bool | None:
    """extra_arguments forward_global_arguments, as typed for the load request (False when absent;
    None when unknown). rclcpp reads the last one given; one that is not a bool makes the container
    refuse the component (component_manager.cpp :: create_node_options; S205 reports it)."""
    for rp in reversed(extra):
        if rp.name == "forward_global_arguments":
            return rp.value if isinstance(rp.value, bool) else None
    return False
