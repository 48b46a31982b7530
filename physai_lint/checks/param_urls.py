"""P114 invalid-camera-info-url: a ``camera_info_url`` that camera_info_manager does not read.

Camera drivers (usb_cam, v4l2_camera, gscam, image_publisher, most vendor drivers) hand their
``camera_info_url`` parameter to ``camera_info_manager::CameraInfoManager``, whose
``loadCalibration`` expands ``${NAME}``/``${ROS_HOME}`` (``resolveURL``) and then accepts only
what ``parseURL`` recognises: "" (the default ``file://${ROS_HOME}/camera_info/${NAME}.yaml``),
``file:///<absolute path>``, ``package://<package>/<path>`` (scheme in any case) and
``flash:///`` (not implemented). Anything else logs "Invalid camera calibration URL" and loads
nothing: the camera publishes a CameraInfo with K all zero, and rectification and every
consumer of the intrinsics silently get nothing useful.

Where a URL is valid, U101 checks the package of a ``package://`` URL and U104 the file it names."""
from __future__ import annotations

from collections.abc import Iterator

from physai_lint.checks._urls import package_url, parameter_strings
from physai_lint.checks.base import CheckContext, rule
from physai_lint.model.findings import Diagnostic

_NAMES = frozenset({"camera_info_url"})
# Released drivers whose camera_info_url goes to camera_info_manager as it is (a workspace package
# counts when its package.xml depends on camera_info_manager). Other nodes may read a parameter of
# that name as a plain path; they are not judged.
CAMERA_INFO_MANAGER_USERS = frozenset({"usb_cam", "v4l2_camera", "gscam", "image_publisher", "camera_ros"})


@rule("P114", "invalid-camera-info-url")
def invalid_camera_info_url(ctx: CheckContext) -> Iterator[Diagnostic]:
    for ps in parameter_strings(ctx):
        if ps.item or ps.base not in _NAMES or not any(_uses_camera_info_manager(ctx, p) for p in sorted(ps.packages)):
            continue
        problem = _url_problem(ps.value)
        if problem is None:
            continue
        why, fix = problem
        yield Diagnostic(
            "P114", ps.span,
            f'parameter "{ps.name}" {ps.whose} is "{ps.value}", {why}: camera_info_manager accepts only '
            '"file:///<absolute path>", "package://<package>/<path>" or "" (the default), logs "Invalid '
            'camera calibration URL" for anything else and loads no calibration, so the camera publishes '
            "a CameraInfo with K all zero",
            help=fix, key=ps.value)


def _uses_camera_info_manager(ctx: CheckContext, package: str) -> bool:
    if ctx.packages.workspace_package(package) is not None:
        return "camera_info_manager" in ctx.packages.exec_depends(package)
    return package in CAMERA_INFO_MANAGER_USERS


def _url_problem(value: str) -> tuple[str, str] | None:
    """(what is wrong, the remedy) when camera_info_manager's ``parseURL`` rejects ``value``
    (after ``resolveURL``, which a "$" makes unknown here), else None."""
    if value == "" or "$" in value:
        return None
    low = value.lower()
    if low.startswith("file:///"):
        return None
    if low.startswith("flash:///"):
        return ('a flash URL, which camera_info_manager recognises but does not read ("reading from '
                'flash not implemented yet")', 'use "file:///<absolute path>" or "package://<package>/<path>"')
    if low.startswith("package://"):
        if package_url(value) is not None:
            return None
        return ('a package URL with no package name or no file after it',
                'write "package://<package>/<path inside its share directory>"')
    if low.startswith("file://"):
        return ('a file URL whose path is not absolute ("file://" must be followed by "/")',
                'write "file://" and then the absolute path, which starts with "/" ("file:///home/...")')
    if value.startswith("/"):
        return ("a path, not a URL",
                'put "file://" before the path (in a launch file: '
                "['file://', PathJoinSubstitution([...])]), or use \"package://<package>/<path>\"")
    if "://" in value:
        return (f'a URL with the scheme "{value.split("://", 1)[0]}"',
                'use "file:///<absolute path>" or "package://<package>/<path>"')
    return ("neither a URL nor an absolute path",
            'use "package://<package>/<path inside its share directory>" or "file:///<absolute path>"')

