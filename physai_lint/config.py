"""Configuration: ``[tool.physai-lint]`` in ``pyproject.toml`` or a ``physai-lint.toml``.

Found by walking up from the working directory (``physai-lint.toml`` wins over ``pyproject.toml``
in the same folder; a ``pyproject.toml`` without the table is skipped). Validated by
``schemas/config.schema.json``. Relative paths in it are relative to the file's folder.
"""
from __future__ import annotations

import json
import os
import sys
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Mapping

from physai_lint.errors import ConfigError

STANDALONE = "physai-lint.toml"
PYPROJECT = "pyproject.toml"
TABLE = "physai-lint"


@dataclass
class Config:
    path: str | None = None  # the file it came from; None: defaults
    root: str = "."  # its folder: relative paths are resolved against it
    select: list[str] | None = None
    ignore: list[str] = field(default_factory=list)
    extend_select: list[str] = field(default_factory=list)
    per_file_ignores: dict[str, list[str]] = field(default_factory=dict)
    fail_on: str | None = None
    distro: str | None = None
    workspace: str | None = None
    interfaces: list[str] = field(default_factory=list)
    exclude: list[str] = field(default_factory=list)
    respect_gitignore: bool | None = None
    severity: dict[str, str] = field(default_factory=dict)
    rules: dict[str, dict[str, Any]] = field(default_factory=dict)
    baseline: str | None = None


def _toml_load(path: Path) -> dict[str, Any]:
    if sys.version_info >= (3, 11):
        import tomllib
    else:  # pragma: no cover - exercised on 3.10 only
        import tomli as tomllib
    try:
        with path.open("rb") as fh:
            return tomllib.load(fh)
    except tomllib.TOMLDecodeError as exc:
        raise ConfigError(f"{path}: invalid TOML: {exc}") from None
    except OSError as exc:
        raise ConfigError(f"{path}: cannot be read: {exc.strerror}") from None


def _table(path: Path, doc: dict[str, Any]) -> dict[str, Any] | None:
    if path.name == PYPROJECT:
        tool = doc.get("tool")
        table = tool.get(TABLE) if isinstance(tool, dict) else None
        if table is not None and not isinstance(table, dict):
            raise ConfigError(f'{path}: "tool.{TABLE}" must be a table')
        return table
    return doc


def find_config(cwd: str) -> Path | None:
    """The nearest ``physai-lint.toml`` or ``pyproject.toml`` with a ``[tool.physai-lint]`` table."""
    here = Path(cwd).resolve()
    for folder in (here, *here.parents):
        standalone = folder / STANDALONE
        if standalone.is_file():
            return standalone
        pyproject = folder / PYPROJECT
        if pyproject.is_file() and _table(pyproject, _toml_load(pyproject)) is not None:
            return pyproject
    return None


def load_config(cwd: str, explicit: str | None) -> Config:
    """The configuration in effect: ``explicit`` (``--config``) or the one found from ``cwd``."""
    if explicit is not None:
        path = Path(cwd, explicit)
        if not path.is_file():
            raise ConfigError(f'config file "{explicit}" does not exist')
    else:
        found = find_config(cwd)
        if found is None:
            return Config(root=str(Path(cwd).resolve()))
        path = found
    table = _table(path, _toml_load(path)) or {}
    where = f"tool.{TABLE}." if path.name == PYPROJECT else ""
    shown = _display(path, cwd)
    _validate(table, shown, where)
    return _build(path.resolve(), table)


def _display(path: Path, cwd: str) -> str:
    try:
        return os.path.relpath(path, cwd).replace(os.sep, "/")
    except ValueError:
        return str(path)


def _build(path: Path, t: Mapping[str, Any]) -> Config:
    root = path.parent

    def rel(p: str | None) -> str | None:
        return None if p is None else str((root / os.path.expanduser(p)).resolve())

    return Config(
        path=str(path),
        root=str(root),
        select=list(t["select"]) if "select" in t else None,
        ignore=list(t.get("ignore", [])),
        extend_select=list(t.get("extend-select", [])),
        per_file_ignores={k: list(v) for k, v in t.get("per-file-ignores", {}).items()},
        fail_on=t.get("fail-on"),
        distro=t.get("distro"),
        workspace=rel(t.get("workspace")),
        interfaces=[rel(p) or p for p in t.get("interfaces", [])],
        exclude=list(t.get("exclude", [])),
        respect_gitignore=t.get("respect-gitignore"),
        severity=dict(t.get("severity", {})),
        rules={k: dict(v) for k, v in t.get("rules", {}).items()},
        baseline=rel(t.get("baseline")),
    )


def schema_path(name: str) -> Path:
    """A bundled schema: installed package data, else the source checkout's ``schemas/``."""
    from physai_lint.resources import data_dir

    return data_dir("_schemas") / name


def _validate(table: Mapping[str, Any], shown: str, where: str) -> None:
    import jsonschema

    schema = json.loads(schema_path("config.schema.json").read_text(encoding="utf-8"))
    validator = jsonschema.Draft202012Validator(schema)
    errors = sorted(validator.iter_errors(table), key=lambda e: (list(map(str, e.absolute_path)), e.message))
    if not errors:
        return
    err = errors[0]
    key = where + ".".join(str(p) for p in err.absolute_path)
    if err.validator == "additionalProperties" and not err.absolute_path:
        from physai_lint.catalog import suggest

        unknown = sorted(set(table) - set(schema["properties"]))
        hint = suggest(unknown[0], schema["properties"]) if unknown else None
        extra = f' (did you mean "{where}{hint}"?)' if hint else ""
        raise ConfigError(f'{shown}: unknown key "{where}{unknown[0]}"{extra}')
    if err.validator == "propertyNames":
        raise ConfigError(f'{shown}: "{key}": {err.instance!r} is not a rule code or name')
    raise ConfigError(f'{shown}: "{key}": {_short(err)}')


def _short(err: Any) -> str:
    if err.validator == "enum":
        return f"{err.instance!r} is not one of " + ", ".join(map(repr, err.validator_value))
    if err.validator == "type":
        return f"expected {err.validator_value}, got {type(err.instance).__name__} {err.instance!r}"
    return str(err.message)


def normalise_rule_keys(config: Config, catalog: Mapping[str, Any]) -> tuple[dict[str, str], dict[str, dict[str, Any]]]:
    """``severity`` and ``rules`` keyed by code (names resolved); rule options validated against
    the rule's ``options`` schema from the catalog."""
    from physai_lint.catalog import lookup, suggest

    shown = _display(Path(config.path), ".") if config.path else "configuration"

    def code_of(key: str, table: str) -> str:
        doc = lookup(key, dict(catalog))
        if doc is not None:
            return str(doc.code)
        if not catalog and key[:1].isupper():
            return key
        hint = suggest(key, [*catalog, *(getattr(d, "name", "") for d in catalog.values())])
        extra = f' (did you mean "{hint}"?)' if hint else ""
        raise ConfigError(f'{shown}: "{table}.{key}": unknown rule{extra}')

    severity = {code_of(k, "severity"): v for k, v in config.severity.items()}
    options: dict[str, dict[str, Any]] = {}
    for key, opts in config.rules.items():
        code = code_of(key, "rules")
        schema = getattr(catalog.get(code), "options", None)
        if schema:
            import jsonschema

            errs = sorted(jsonschema.Draft202012Validator(schema).iter_errors(opts), key=lambda e: e.message)
            if errs:
                path = ".".join(str(p) for p in errs[0].absolute_path)
                raise ConfigError(f'{shown}: "rules.{key}{"." + path if path else ""}": {_short(errs[0])}')
        options[code] = opts
    return severity, options
