"""Running the backend for the workbench: the layer every other one calls.

    report = run(solid, size, method="snap", blocks=True)  # checked report; raises BackendError
    refresh(curves)                 # rerun a SingularCurves object if its input changed
    info = backend_info()           # `framefix info` of the found backend, asked once a session

Below it: backend.py (which backend, lookup order), job.py (one run's command line and
outcome), runner.py (the child process), info.py (`framefix info`). Above it: objects/ (the
proxies), make.py, taskpanels/, commands/. The tet meshes of block runs are kept here
(report.json does not hold them) until the Blocks object's recompute takes them.
"""
import json

import FreeCAD

from . import shapes
from .backend import find_backend
from .errors import BackendError, FrameFixError
from .info import INFO_TIMEOUT_S, InfoJob
from .job import AnalysisJob, timeout_from_env
from .report import run_text
from .runner import run_sync

_BLOCK_MESHES = {}  # input digest -> tet mesh of that block run, newest last
_KEPT_BLOCK_MESHES = 3
_INFO = {}  # backend key -> checked info, or the BackendError it gave


def input_digest(solid, size, method="", blocks=False, fillet_rims=False, hex_order=1):
    """What a run depends on: the solid's geometry, the size (None: the backend's default),
    the correction method ("" for an analysis), whether it cuts blocks and fillets rims, and
    the order of the hex mesh of the blocks."""
    digest = "%s size=%r" % (shapes.shape_digest(solid), float(size or 0.0))
    return (digest + (" method=%s" % method if method else "") + (" blocks" if blocks else "") +
            (" rims" if fillet_rims else "") + (" order=%d" % hex_order if blocks and hex_order != 1 else ""))


def remember_block_mesh(digest, report):
    mesh = report.get("block_mesh")
    if mesh is not None:
        _BLOCK_MESHES.pop(digest, None)
        _BLOCK_MESHES[digest] = mesh
        while len(_BLOCK_MESHES) > _KEPT_BLOCK_MESHES:
            del _BLOCK_MESHES[next(iter(_BLOCK_MESHES))]


def block_mesh(digest):
    """The tet mesh of the block run with input `digest`, or None if this session has none."""
    return _BLOCK_MESHES.get(digest)


def forget_block_meshes():
    _BLOCK_MESHES.clear()


def gui_idle():
    """Keep the window painted while FreeCAD waits for the backend (input is blocked)."""
    if FreeCAD.GuiUp:
        from PySide2 import QtCore, QtWidgets
        QtWidgets.QApplication.processEvents(QtCore.QEventLoop.ExcludeUserInputEvents)


def _key(backend):
    return tuple(backend.argv), tuple(sorted(backend.env.items()))


def backend_info(backend=None):
    """The checked `framefix info` of `backend` (default: the one found), asked once per
    session and backend; raises the BackendError it gave (cached too) if it has none."""
    backend = backend or find_backend()
    key = _key(backend)
    if key not in _INFO:
        try:
            _INFO[key] = run_sync(InfoJob(backend, min(INFO_TIMEOUT_S, timeout_from_env())),
                                  on_idle=gui_idle)
        except BackendError as e:
            _INFO[key] = e
    if isinstance(_INFO[key], BackendError):
        raise _INFO[key]
    return _INFO[key]


def method_names(info, blocks=False):
    return list(info["block_methods"]) if blocks else [
        m["name"] for m in info["correction_methods"]]


def check_method(method, blocks=False, backend=None):
    """Refuse a method the backend does not offer before running it. A backend without
    `info` (an older one) is left to refuse it itself."""
    if not method:
        return
    try:
        info = backend_info(backend)
    except BackendError:
        return
    names = method_names(info, blocks)
    if method not in names:
        raise FrameFixError("unknown %s method %r: use one of %s" % (
            "block" if blocks else "correction", method, ", ".join(names)))
    for m in info["correction_methods"] if not blocks else []:
        if m["name"] == method and not m["available"]:
            raise FrameFixError("correction method %r is not available yet in this backend "
                                "(%s)" % (method, m["description"]))


def run(solid, size, method=None, blocks=False, backend=None, timeout=None, out_dir=None,
        on_progress=None, fillet_rims=False, hex_order=1):
    """The checked report of the backend on `solid`: an analysis, with `method` a correction,
    with `blocks` a block decomposition and its hex mesh of order `hex_order` (their meshes kept
    for the Blocks and HexMesh objects). `size` None lets the backend choose. Raises
    FrameFixError (BackendError when the run failed)."""
    check_method(method, blocks, backend)
    job = AnalysisJob(solid, size, backend, timeout, method, blocks, out_dir, fillet_rims, hex_order)
    try:
        report = run_sync(job, on_progress=on_progress, on_idle=gui_idle)
    finally:
        job.cleanup()
    if blocks:
        remember_block_mesh(input_digest(solid, size, method or "", True, fillet_rims, hex_order), report)
    return report


def store(curves, report, digest):
    """A run's report (and the fillet's solid) on its SingularCurves object."""
    curves.Report = json.dumps(report["raw"])
    curves.InputDigest = digest
    curves.FilletedBrep = report.get("filleted_brep") or ""


def refresh(curves):
    """Bring a SingularCurves object's Report up to date: rerun if its solid, Size, Method, FilletRims or
    Blocks changed since (InputDigest): results applied from the panel are not run twice."""
    solid = shapes.solid_of(curves.Source)
    size = curves.Size.Value or None  # 0: the backend's default
    rims, order = curves.FilletRims, curves.HexOrder
    digest = input_digest(solid, size, curves.Method, curves.Blocks, rims, order)
    if digest != curves.InputDigest or not curves.Report:
        report = run(solid, size, method=curves.Method or None, blocks=curves.Blocks,
                     fillet_rims=rims, hex_order=order)
        store(curves, report, digest)
        FreeCAD.Console.PrintMessage("FrameFix: %s: %s\n" % (curves.Source.Label,
                                                            run_text(report)))
