"""The catalog's examples are tests: each rule's ``Example`` must report its code, ``Use instead`` must not.

Conventions (rules/README.md, "Examples are tests"): every fenced block with ``title="path"`` is a
file of the workspace; ``src/<pkg>/`` folders without a ``package.xml`` get an ament_cmake one with
an ``<exec_depend>`` on each package the launch files reference, and a ``CMakeLists.txt`` that
installs launch/config/urdf/rviz unless build files are given; ``interfaces.yaml`` is passed as
``--interfaces``; ``<!-- args: ... -->`` / ``<!-- distro: ... -->`` directives apply;
``<!-- example: not-run -->`` sections are rendered but not run. The entry is the first block whose
title ends in launch.py/launch.xml/launch.yaml, else the first block.

Known failures are listed in ``tests/doc_examples_xfail.txt`` (``CODE reason`` per line): they xfail.
``python tests/test_doc_examples.py`` prints a table of every example and why it fails.
"""
from __future__ import annotations

import os
import re
import sys
import tempfile
from dataclasses import dataclass
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from physai_lint.catalog import RuleDoc, load_catalog  # noqa: E402
from physai_lint.engine import CheckOptions, run_check  # noqa: E402

XFAIL_FILE = ROOT / "tests" / "doc_examples_xfail.txt"
NOT_RUN = "<!-- example: not-run -->"
_BLOCK = re.compile(r'^(?P<fence>`{3,}|~{3,})[ \t]*(?P<lang>[\w+-]*)[^\n]*?title="(?P<title>[^"]+)"[^\n]*\n'
                    r"(?P<body>.*?)^(?P=fence)[ \t]*$", re.MULTILINE | re.DOTALL)
_ARGS = re.compile(r"<!--\s*args:\s*(.*?)\s*-->", re.DOTALL)
_DISTRO = re.compile(r"<!--\s*distro:\s*(\S+)\s*-->")
_LAUNCH_SUFFIXES = ("launch.py", "launch.xml", "launch.yaml")
# Package references in launch files, per format.
_PKG_REFS = (
    re.compile(r"FindPackageShare\(\s*['\"]([A-Za-z0-9_]+)['\"]"),
    re.compile(r"get_package_share_directory\(\s*['\"]([A-Za-z0-9_]+)['\"]"),
    re.compile(r"\bpackage\s*=\s*['\"]([A-Za-z0-9_]+)['\"]"),
    re.compile(r"\bpkg\s*=\s*['\"]([A-Za-z0-9_]+)['\"]"),
    re.compile(r"\$\(find-pkg-(?:share|prefix)\s+([A-Za-z0-9_]+)\)"),
    re.compile(r"^\s*(?:-\s*)?(?:pkg|package):\s*['\"]?([A-Za-z0-9_]+)", re.MULTILINE),
)
_INSTALLED_DIRS = ("launch", "config", "urdf", "rviz")


@dataclass(frozen=True)
class Example:
    code: str
    section: str  # "Example" (bad) or "Use instead" (good)
    files: dict[str, str]
    args: dict[str, str]
    distro: str

    @property
    def bad(self) -> bool:
        return self.section == "Example"


def parse_example(doc: RuleDoc, section: str) -> Example | None:
    text = doc.sections.get(section, "")
    if NOT_RUN in text:
        return None
    files = {m.group("title").strip(): m.group("body") for m in _BLOCK.finditer(text)}
    if not files:
        return None
    args: dict[str, str] = {}
    for directive in _ARGS.findall(text):
        for item in directive.split():
            name, sep, value = item.partition(":=")
            if sep:
                args[name] = value
    distro = _DISTRO.search(text)
    return Example(doc.code, section, files, args, distro.group(1) if distro else "humble")


def _package_xml(name: str, deps: list[str]) -> str:
    dep_lines = "".join(f"  <exec_depend>{d}</exec_depend>\n" for d in deps)
    return (f'<?xml version="1.0"?>\n<package format="3">\n  <name>{name}</name>\n  <version>0.0.0</version>\n'
            f"  <description>{name}</description>\n  <maintainer email=\"dev@example.com\">dev</maintainer>\n"
            f"  <license>Apache-2.0</license>\n  <buildtool_depend>ament_cmake</buildtool_depend>\n{dep_lines}"
            "  <export>\n    <build_type>ament_cmake</build_type>\n  </export>\n</package>\n")


def _cmakelists(name: str, dirs: list[str]) -> str:
    install = f"install(DIRECTORY {' '.join(dirs)} DESTINATION share/${{PROJECT_NAME}})\n" if dirs else ""
    return (f"cmake_minimum_required(VERSION 3.8)\nproject({name})\nfind_package(ament_cmake REQUIRED)\n"
            f"{install}ament_package()\n")


def materialise(example: Example, root: Path) -> tuple[str, list[str]]:
    """Write the workspace; return (entry path, interfaces files), both relative to ``root``."""
    files = dict(example.files)
    launch_texts = "\n".join(t for p, t in files.items() if p.endswith(_LAUNCH_SUFFIXES))
    referenced = sorted({m for rx in _PKG_REFS for m in rx.findall(launch_texts)})
    packages = sorted({p.split("/")[1] for p in files if p.startswith("src/") and p.count("/") >= 2})
    # an author declares what exists (a workspace or released package), not a misspelt name: a
    # declared run dependency is taken as installed from elsewhere (U101 stays silent on it)
    from physai_lint.workspace.distro import released_in

    existing = [r for r in referenced if r in packages or released_in(r)]
    for pkg in packages:
        prefix = f"src/{pkg}/"
        if prefix + "package.xml" not in files:
            files[prefix + "package.xml"] = _package_xml(pkg, [r for r in existing if r != pkg])
        if not any(prefix + b in files for b in ("CMakeLists.txt", "setup.py")):
            dirs = sorted({p[len(prefix):].split("/")[0] for p in files if p.startswith(prefix)} & set(_INSTALLED_DIRS))
            files[prefix + "CMakeLists.txt"] = _cmakelists(pkg, dirs)
    for rel, text in files.items():
        path = root / rel
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text, encoding="utf-8")
    titles = list(example.files)
    entry = next((t for t in titles if t.endswith(_LAUNCH_SUFFIXES)), titles[0])
    interfaces = [t for t in titles if t == "interfaces.yaml"]
    return entry, interfaces


def run_example(example: Example) -> list[tuple[str, str, int, str]]:
    """(code, file, line, message) of every finding in the example's workspace."""
    with tempfile.TemporaryDirectory(prefix=f"physai-doc-{example.code}-") as tmp:
        entry, interfaces = materialise(example, Path(tmp))
        opts = CheckOptions(paths=[entry], launch_args=dict(example.args), workspace=".",
                            distro=example.distro, interfaces=interfaces, cache=False)
        report = run_check(opts, cwd=tmp)
        return [(f.code, os.path.relpath(f.span.file, tmp), f.span.line, f.message) for f in report.findings]


def problem(example: Example) -> str | None:
    """Why the example does not behave as documented, or None."""
    try:
        found = run_example(example)
    except Exception as exc:  # a usage error (bad args, missing file) is a doc problem worth showing
        return f"run failed: {type(exc).__name__}: {exc}"
    crashes = [f for f in found if f[0] == "X003"]
    if crashes:
        return f"internal error: {crashes[0][3][:160]}"
    codes = sorted({f[0] for f in found})
    from physai_lint.checks.base import load_all

    producer = load_catalog(ROOT / "rules")[example.code].producer
    if example.bad and producer == "check" and example.code not in load_all():
        return f"rule not implemented: no @rule({example.code!r}) is registered"
    mine = [f for f in found if f[0] == example.code]
    if example.bad and not mine:
        return f"{example.code} not reported (got {', '.join(codes) or 'nothing'})"
    if not example.bad and mine:
        return f"{example.code} reported on the good example: {mine[0][1]}:{mine[0][2]} {mine[0][3][:120]}"
    return None


def known_failures() -> dict[str, str]:
    if not XFAIL_FILE.is_file():
        return {}
    out = {}
    for line in XFAIL_FILE.read_text(encoding="utf-8").splitlines():
        if line.strip() and not line.startswith("#"):
            code, _, reason = line.strip().partition(" ")
            out[code] = reason.strip()
    return out


def _examples() -> list[Example]:
    out = []
    for doc in load_catalog(ROOT / "rules").values():
        for section in ("Example", "Use instead"):
            ex = parse_example(doc, section)
            if ex is not None:
                out.append(ex)
    return out


EXAMPLES = _examples()


@pytest.fixture(autouse=True)
def _no_ament(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv("AMENT_PREFIX_PATH", raising=False)


@pytest.mark.parametrize("example", EXAMPLES,
                         ids=[f"{e.code}-{'bad' if e.bad else 'good'}" for e in EXAMPLES])
def test_doc_example(example: Example) -> None:
    why = problem(example)
    reason = known_failures().get(example.code)
    if why is not None and reason is not None:
        pytest.xfail(f"{reason} [{why}]")
    assert why is None, f"rules/{example.code[0]}/{example.code}-*.md [{example.section}]: {why}"


def test_xfail_list_names_catalog_rules() -> None:
    catalog = load_catalog(ROOT / "rules")
    unknown = sorted(set(known_failures()) - set(catalog))
    assert not unknown, f"{XFAIL_FILE.name} lists codes that are not in the catalog: {unknown}"


def main() -> int:
    """Print a table of every failing doc example (code, section, cause, listed in the xfail file?)."""
    os.environ.pop("AMENT_PREFIX_PATH", None)
    known = known_failures()
    rows = [(e.code, e.section, why) for e in EXAMPLES if (why := problem(e)) is not None]
    print(f"{len(rows)} failing of {len(EXAMPLES)} examples\n")
    print("| code | section | listed | cause |\n| --- | --- | --- | --- |")
    for code, section, why in rows:
        print(f"| {code} | {section} | {'yes' if code in known else 'NO'} | {why} |")
    return 1 if any(code not in known for code, _, _ in rows) else 0


if __name__ == "__main__":
    raise SystemExit(main())
