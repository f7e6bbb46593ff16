"""FrameFix on FreeCAD objects, for macros (GUI or freecadcmd)::

    import framefix.freecad as ff
    r = ff.analyze(App.ActiveDocument.Body, size=2.0)
    r.summary["curves_3_5"], r.summary["meshable"], r.curves[0].kind, r.curves[0].points

The backend runs as a child process (the `framefix` CLI) on a BREP export of the solid, in a
temporary folder: a crash of the mesher cannot take FreeCAD down, and the user's shape is
never modified. Failures raise framefix.Error with the backend's message.

Finding and running the backend is the workbench's (framefix_wb.runs, lookup order in
framefix_wb/backend.py), shared with it rather than copied: one lookup order, one runner.
It lives in the workbench, not here, because this package imports its compiled extension
(_core) on import, while the workbench must run any backend, even a plain executable
(FRAMEFIX_BACKEND) with no Python package beside it. framefix_wb needs no extension and is
on FreeCAD's path whenever the workbench is installed, the only place this module runs.
"""
import os
import sys

import numpy as np

from . import Error

_PACKAGE_DIR = os.path.dirname(os.path.abspath(__file__))
DEFAULT_TIMEOUT_S = 1800.0


class Curve:
    """A singular curve: kind "valence3" | "valence5" | "3-5"; points: (n, 3) float array."""

    def __init__(self, d):
        self.id, self.kind = int(d["id"]), d["kind"]
        self.length, self.ends = float(d.get("length", 0.0)), list(d.get("ends", []))
        self.points = np.asarray(d["points"], dtype=float).reshape(-1, 3)

    def __repr__(self):
        return "Curve(id=%d, kind=%r, %d points)" % (self.id, self.kind, len(self.points))


class Node:
    """A singular node: position (3,) array; valid False when no hex mesh can realise it."""

    def __init__(self, d):
        self.id, self.position = int(d["id"]), np.asarray(d["position"], dtype=float)
        self.boundary, self.valid = bool(d.get("boundary")), bool(d.get("valid", True))
        self.n3, self.n5 = int(d.get("n3", 0)), int(d.get("n5", 0))

    def __repr__(self):
        return "Node(id=%d, valid=%s)" % (self.id, self.valid)


class Result:
    """One analysis: `report` is report.json as a dict (version 1, docs/design.md)."""

    def __init__(self, report, out_dir=None):
        self.report = report
        sing = report["singularities"]
        self.summary = dict(sing["summary"])
        self.curves = [Curve(c) for c in sing.get("curves", [])]
        self.nodes = [Node(n) for n in sing.get("nodes", [])]
        self.feature_curves = report.get("feature_curves", [])
        self.mesh = report.get("mesh", {})
        self.out_dir = out_dir  # the VTK files and report.json, when analyze(out=...) kept them

    @property
    def meshable(self):
        return bool(self.summary.get("meshable"))

    def __repr__(self):
        return "Result(%d curves, %d 3-5 curves, meshable=%s)" % (
            self.summary.get("curves", 0), self.summary.get("curves_3_5", 0), self.meshable)


def solid_of(obj_or_shape):
    """The single solid of a Part.Shape or a document object (Part feature, Body, Link)."""
    import Part
    shape = obj_or_shape if isinstance(obj_or_shape, Part.Shape) else Part.getShape(obj_or_shape)
    solids = [] if shape.isNull() else shape.Solids
    if len(solids) != 1:
        raise Error("freecad: %s has %d solids; pass exactly one solid"
                    % (getattr(obj_or_shape, "Label", "the shape"), len(solids)))
    return solids[0].copy()  # a copy without the display mesh, so the BREP is the geometry only


def _workbench_runs():
    """framefix_wb.runs: FreeCAD puts the installed workbench on sys.path; otherwise look
    beside this package (installed: <Mod/FrameFix>/python/framefix -> <Mod/FrameFix>; build
    or source tree: <repo>/build/python/framefix or <repo>/backend/python/framefix ->
    <repo>/workbench)."""
    try:
        from framefix_wb import runs
        return runs
    except ImportError:
        pass
    up2 = os.path.dirname(os.path.dirname(_PACKAGE_DIR))
    for path in (up2, os.path.join(os.path.dirname(up2), "workbench")):
        if os.path.isdir(os.path.join(path, "framefix_wb")) and path not in sys.path:
            sys.path.append(path)
            try:
                from framefix_wb import runs
                return runs
            except ImportError:
                sys.path.remove(path)
    raise Error("freecad: the FrameFix workbench (framefix_wb) is not installed: it runs the "
                "backend (cmake --install build)")


def analyze(obj_or_shape, size=None, out=None, timeout=DEFAULT_TIMEOUT_S, progress=None):
    """Analyse one solid; returns a Result. `size`: target tet edge length (model units),
    None for about 50k tets. `out`: a folder to keep the report and VTK files in.
    `progress(stage, fraction)` is called for each progress line of the backend."""
    solid = solid_of(obj_or_shape)
    runs = _workbench_runs()
    from framefix_wb.errors import FrameFixError
    try:
        report = runs.run(solid, size, timeout=timeout, on_progress=progress,
                          out_dir=os.path.abspath(out) if out else None)
    except FrameFixError as e:
        raise Error("freecad: %s" % e) from None
    return Result(report["raw"], os.path.abspath(out) if out else None)
