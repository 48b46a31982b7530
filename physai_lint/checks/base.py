"""The rule contract: a rule is a function of the ``CheckContext`` yielding ``Diagnostic``s.

Rules never touch the filesystem, the network, the environment or subprocesses: everything they
need (parsed files, resolved launches, the package index, parameter files, node interfaces) is in
the context, built by the engine. Tests hand in small contexts built from fixture workspaces.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any, Callable, Iterable, Iterator

from physai_lint.model.findings import Diagnostic

if TYPE_CHECKING:
    from physai_lint.interfaces.store import InterfaceStore
    from physai_lint.model.launch import LaunchFile
    from physai_lint.params.model import ParamFileModel
    from physai_lint.resolve.model import LaunchResult
    from physai_lint.workspace import PackageIndex


@dataclass
class CheckContext:
    """What a rule may read.

    - ``launch_files``: every parsed launch file (path -> IR), entries and included files alike;
    - ``param_files``: every parsed parameter file (path -> located model);
    - ``launches``: one resolved ``LaunchResult`` per entry launch file;
    - ``targets``: the files the user asked about: findings elsewhere are dropped by the engine;
    - ``options``: per-rule options from the configuration, by rule code.
    """

    launch_files: dict[str, "LaunchFile"]
    param_files: dict[str, "ParamFileModel"]
    launches: list["LaunchResult"]
    packages: "PackageIndex"
    interfaces: "InterfaceStore"
    distro: str = "humble"
    targets: frozenset[str] = frozenset()
    options: dict[str, dict[str, Any]] = field(default_factory=dict)

    def option(self, code: str, key: str, default: Any) -> Any:
        return self.options.get(code, {}).get(key, default)


RuleFunc = Callable[[CheckContext], Iterable[Diagnostic]]


@dataclass(frozen=True)
class RuleImpl:
    code: str
    name: str
    func: RuleFunc


REGISTRY: dict[str, RuleImpl] = {}


def rule(code: str, name: str) -> Callable[[RuleFunc], RuleFunc]:
    """Register a check. ``code``/``name`` must match the catalog entry ``rules/<L>/<code>-<name>.md``."""

    def deco(func: RuleFunc) -> RuleFunc:
        if code in REGISTRY:
            raise ValueError(f"rule code {code} registered twice")
        REGISTRY[code] = RuleImpl(code, name, func)
        return func

    return deco


def load_all() -> dict[str, RuleImpl]:
    """Import every check module so that its rules register themselves."""
    import importlib
    import pkgutil

    import physai_lint.checks as pkg

    for mod in sorted(m.name for m in pkgutil.iter_modules(pkg.__path__)):
        if mod not in ("base",) and not mod.startswith("_"):
            importlib.import_module(f"physai_lint.checks.{mod}")
    return REGISTRY


def diag(code: str, span: Any, message: str, **kw: Any) -> Diagnostic:
    return Diagnostic(code=code, span=span, message=message, **kw)


def first(items: Iterable[Any]) -> Any:
    for item in items:
        return item
    return None


def iter_unique(items: Iterable[Any]) -> Iterator[Any]:
    seen: set[Any] = set()
    for item in items:
        if item not in seen:
            seen.add(item)
            yield item
