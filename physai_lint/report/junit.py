"""``--format junit`` / ``--xunit-file``: JUnit XML for ``colcon test`` and CI dashboards.

One ``testsuite`` "physai-lint", one ``testcase`` per checked file; each finding at or above
``fail_on`` is a ``failure`` (``type`` = code), the others are listed in ``system-out``.
"""
from __future__ import annotations

import re
import xml.etree.ElementTree as ET
from typing import Any, Mapping

from physai_lint.model.findings import SEVERITY_RANK, Finding
from physai_lint.report import ReportLike, one_line, ordered, rel


_NOT_XML = re.compile("[^\t\n\r\x20-\ud7ff\ue000-\ufffd\U00010000-\U0010ffff]")


def _xml_text(text: str) -> str:
    """Characters XML 1.0 cannot carry, even escaped, become U+FFFD."""
    return _NOT_XML.sub("\ufffd", text)


def _line(f: Finding, cwd: str) -> str:
    return _xml_text(one_line(f, cwd))


def render(report: ReportLike, catalog: Mapping[str, Any], *, fail_on: str = "error", **_: Any) -> str:
    cwd = report.cwd
    by_file: dict[str, list[Finding]] = {rel(p, cwd): [] for p in report.files}
    for f in ordered(report):
        by_file.setdefault(rel(f.span.file, cwd), []).append(f)
    floor = SEVERITY_RANK[fail_on]
    files = sorted(by_file)
    failing = sum(1 for p in files if any(SEVERITY_RANK[f.severity] >= floor for f in by_file[p]))
    time = f"{report.duration_s:.3f}"
    root = ET.Element("testsuites", name="physai-lint", tests=str(len(files)), failures=str(failing), errors="0", time=time)
    suite = ET.SubElement(
        root, "testsuite", name="physai-lint", tests=str(len(files)), failures=str(failing), errors="0", skipped="0", time=time
    )
    for path in files:
        case = ET.SubElement(suite, "testcase", classname="physai-lint", name=path, file=path)
        other = []
        for f in by_file[path]:
            if SEVERITY_RANK[f.severity] >= floor:
                failure = ET.SubElement(case, "failure", type=f.code, message=_line(f, cwd))
                failure.text = f"{f.severity}: {_line(f, cwd)}" + (f"\nhelp: {_xml_text(f.help)}" if f.help else "")
            else:
                other.append(f"{f.severity}: {_line(f, cwd)}")
        if other:
            ET.SubElement(case, "system-out").text = "\n".join(other)
    ET.indent(root)
    return '<?xml version="1.0" encoding="utf-8"?>\n' + ET.tostring(root, encoding="unicode") + "\n"
