"""Making and updating an analysis in a document, with or without the GUI.

    curves = make_analysis(part)                  # runs the backend, then adds the objects
    curves = make_analysis(part, size, report=r)  # objects from a report the panel already has

The backend runs before anything is added, so a failed run leaves the document unchanged.
Each change is one undoable transaction.
"""
import json

import FreeCAD

from . import shapes, style
from .errors import FrameFixError
from .job import AnalysisJob
from .runner import run_sync

GROUP_LABEL = "FrameFix analysis of %s"
CORRECTION_GROUP_LABEL = "FrameFix correction (%s) of %s"
BLOCKS_GROUP_LABEL = "FrameFix blocks (%s) of %s"

# The tet meshes of the last block runs, by input digest: report.json does not hold them
# (blocks.vtk does), the Blocks object takes its run's mesh from here in the recompute that
# follows the run. Saved documents keep the mesh in the Blocks object itself.
_BLOCK_MESHES = {}
_KEPT_BLOCK_MESHES = 3


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


def input_digest(solid, size, method="", blocks=False):
    """What a run depends on: the solid's geometry, the size (None: the backend's default),
    the correction method ("" for an analysis) and whether it cuts blocks."""
    digest = "%s size=%r" % (shapes.shape_digest(solid), float(size or 0.0))
    return digest + (" method=%s" % method if method else "") + (" blocks" if blocks else "")


def _gui_idle():
    """Keep the window painted while a recompute waits for the backend (input is blocked)."""
    if FreeCAD.GuiUp:
        from PySide2 import QtCore, QtWidgets
        QtWidgets.QApplication.processEvents(QtCore.QEventLoop.ExcludeUserInputEvents)


def run_analysis(solid, size, backend=None, timeout=None, method=None, blocks=False):
    """The checked report of the backend on `solid`; size None lets the backend choose
    (about sizing.TARGET_TETS tets); with `method`, of a correction; with `blocks`, of a
    block decomposition (its tet mesh remembered for the Blocks object). Raises BackendError."""
    job = AnalysisJob(solid, size, backend, timeout, method, blocks)
    try:
        report = run_sync(job, on_idle=_gui_idle)
    finally:
        job.cleanup()
    if blocks:
        remember_block_mesh(input_digest(solid, size, method or "", True), report)
    return report


def _add(doc, type_name, name, label, proxy_class, vp_module, vp_class):
    obj = doc.addObject(type_name, name)
    proxy_class(obj)
    obj.Label = label
    if FreeCAD.GuiUp:
        import importlib
        getattr(importlib.import_module("framefix_wb.viewproviders." + vp_module), vp_class)(
            obj.ViewObject)
    return obj


def _fade_source(curves, source):
    vo = getattr(source, "ViewObject", None) if FreeCAD.GuiUp else None
    if vo is not None and hasattr(vo, "Transparency"):
        if curves.SourceTransparency < 0:
            curves.SourceTransparency = vo.Transparency
        vo.Transparency = max(vo.Transparency, style.SOURCE_TRANSPARENCY)


def _recompute(doc, objects):
    """Recompute `objects` (not the user's other touched features); raise if one failed."""
    doc.recompute(objects)
    failed = [o for o in objects if not o.isValid()]
    if failed:
        raise FrameFixError("could not build %s: %s" % (
            failed[0].Label, " ".join(failed[0].getStatusString().split())))


class _Transaction:
    def __init__(self, doc, name):
        self.doc, self.name = doc, name

    def __enter__(self):
        self.doc.openTransaction(self.name)

    def __exit__(self, kind, value, tb):
        if kind is None:
            self.doc.commitTransaction()
        else:
            self.doc.abortTransaction()


def _kind(method, blocks):
    return "FrameFix blocks" if blocks else "FrameFix correction" if method else "FrameFix analysis"


def make_analysis(source, size=None, report=None, digest=None, backend=None, method="",
                  blocks=False):
    """Add the analysis group of `source` (a part, Body or Link); returns SingularCurves.

    `size` None (stored as Size 0) lets the backend pick it. Without `report` the backend
    runs first (synchronously). With it, `digest` must be input_digest() of the solid, size,
    method and blocks that report was computed from. With `method` ("snap", ...), a
    correction: the curves are those after correcting, Before35 counts the 3-5 curves before.
    With `blocks` (method "snap", the default, or "none"), the part cut into blocks too: a
    Blocks object (the tets coloured by block) beside the curves.
    """
    from .objects.feature_curves import FeatureCurves
    from .objects.singular_curves import SingularCurves
    from .objects.singular_nodes import SingularNodes
    solid = shapes.solid_of(source)
    size = float(size or 0.0)
    if blocks:
        method = method or "snap"
    if report is None:
        report = run_analysis(solid, size or None, backend, method=method or None, blocks=blocks)
        digest = input_digest(solid, size, method, blocks)
    elif blocks:
        remember_block_mesh(digest, report)
    corrected = method and method != "none"
    doc = source.Document
    label = shapes.label_of(source)
    with _Transaction(doc, _kind(method, blocks)):
        group = doc.addObject("App::DocumentObjectGroup", "FrameFixBlocks" if blocks else
                              "FrameFixCorrection" if method else "FrameFixAnalysis")
        group.Label = (BLOCKS_GROUP_LABEL % (method, label) if blocks else
                       CORRECTION_GROUP_LABEL % (method, label) if method else GROUP_LABEL % label)
        curves = _add(doc, "Part::FeaturePython", "SingularCurves",
                      "Corrected singular curves" if corrected else "Singular curves",
                      SingularCurves, "singular_curves", "ViewProviderSingularCurves")
        curves.Source, curves.Size, curves.Blocks, curves.Method = source, size, blocks, method
        curves.Report, curves.InputDigest = json.dumps(report["raw"]), digest
        nodes = _add(doc, "Part::FeaturePython", "SingularNodes", "Singular nodes",
                     SingularNodes, "singular_nodes", "ViewProviderSingularNodes")
        features = _add(doc, "Part::FeaturePython", "FeatureCurves", "Feature curves",
                        FeatureCurves, "feature_curves", "ViewProviderFeatureCurves")
        nodes.Analysis = features.Analysis = curves
        parts = [curves, nodes, features]
        if corrected:
            from .objects.snapped_paths import SnappedPaths
            paths = _add(doc, "Part::FeaturePython", "SnappedPaths", "Snapped paths",
                         SnappedPaths, "snapped_paths", "ViewProviderSnappedPaths")
            paths.Analysis = curves
            parts.append(paths)
        if blocks:
            from .objects.blocks import Blocks
            cut = _add(doc, "Fem::FemMeshObjectPython", "Blocks", "Blocks", Blocks, "blocks",
                       "ViewProviderBlocks")
            cut.Analysis = curves
            parts.append(cut)
        group.addObjects(parts)
        _fade_source(curves, source)
        _recompute(doc, parts)
    return curves


def update_analysis(curves, size, report, digest, method=""):
    """Store a new run (from the task panel) on an existing analysis and recompute it."""
    doc = curves.Document
    if curves.Blocks:
        remember_block_mesh(digest, report)
    with _Transaction(doc, _kind(method, curves.Blocks)):
        curves.Size, curves.Method = float(size or 0.0), method
        curves.Report, curves.InputDigest = json.dumps(report["raw"]), digest
        _fade_source(curves, curves.Source)
        _recompute(doc, [curves] + [o for o in curves.InList if hasattr(o, "Analysis")])
    return curves


def make_blocks(source, size=None, method="snap", report=None, digest=None, backend=None):
    """make_analysis with blocks: correct (`method` snap, or none), cut into blocks; returns
    the Blocks object (its Analysis is the curves object owning the run)."""
    curves = make_analysis(source, size, report, digest, backend, method, blocks=True)
    return blocks_of(curves)


def blocks_of(curves):
    """The Blocks object of a block run's curves object, or None."""
    found = [o for o in curves.InList if type(getattr(o, "Proxy", None)).__name__ == "Blocks"]
    return found[0] if found else None


def analyses_of(source):
    """The SingularCurves objects analysing `source`."""
    return [o for o in source.InList
            if type(getattr(o, "Proxy", None)).__name__ == "SingularCurves"]
