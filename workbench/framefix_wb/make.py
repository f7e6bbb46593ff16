"""Making and updating FrameFix results in a document, with or without the GUI.

    curves = make_analysis(part)                  # runs the backend, then adds the objects
    curves = make_analysis(part, size, report=r)  # objects from a report the panel already has
    blocks = make_blocks(part, method="snap")
    hexes = make_hex_mesh(part, order=2)          # the blocks' hex mesh, a Fem::FemMeshObject

The backend runs before anything is added, so a failed run leaves the document unchanged.
Each change is one undoable transaction. The make layer: above the proxies (objects/) and
runs.py, below taskpanels/ and commands/.
"""

import FreeCAD

from . import runs, shapes, style
from .errors import FrameFixError
from .objects.block_surfaces import BlockEdges, BlockSurfaces
from .objects.blocks import Blocks
from .objects.feature_curves import FeatureCurves
from .objects.filleted_part import FilletedPart
from .objects.hex_mesh import HexMesh
from .objects.mapped_curves import MappedCurves
from .objects.properties import report_of
from .objects.singular_curves import SingularCurves
from .objects.singular_nodes import SingularNodes
from .objects.snapped_paths import SnappedPaths
from .objects.streamlines import Streamlines

if FreeCAD.GuiUp:
    from .viewproviders.block_surfaces import ViewProviderBlockEdges, ViewProviderBlockSurfaces
    from .viewproviders.blocks import ViewProviderBlocks
    from .viewproviders.feature_curves import ViewProviderFeatureCurves
    from .viewproviders.hex_mesh import ViewProviderHexMesh
    from .viewproviders.mapped_curves import ViewProviderMappedCurves
    from .viewproviders.singular_curves import ViewProviderSingularCurves
    from .viewproviders.singular_nodes import ViewProviderSingularNodes
    from .viewproviders.snapped_paths import ViewProviderSnappedPaths
    from .viewproviders.streamlines import ViewProviderStreamlines
    VIEW_PROVIDERS = {SingularCurves: ViewProviderSingularCurves,
                      SingularNodes: ViewProviderSingularNodes,
                      FeatureCurves: ViewProviderFeatureCurves,
                      SnappedPaths: ViewProviderSnappedPaths, Streamlines: ViewProviderStreamlines,
                      MappedCurves: ViewProviderMappedCurves, Blocks: ViewProviderBlocks,
                      BlockSurfaces: ViewProviderBlockSurfaces, BlockEdges: ViewProviderBlockEdges,
                      HexMesh: ViewProviderHexMesh}
else:
    VIEW_PROVIDERS = {}

GROUP_LABEL = "FrameFix analysis of %s"
CORRECTION_GROUP_LABEL = "FrameFix correction (%s) of %s"
BLOCKS_GROUP_LABEL = "FrameFix blocks (%s) of %s"
MAPPED_LABEL = "Curves mapped onto the part"


def _add(doc, type_name, name, label, proxy_class):
    obj = doc.addObject(type_name, name)
    proxy_class(obj)
    obj.Label = label
    if proxy_class in VIEW_PROVIDERS:
        VIEW_PROVIDERS[proxy_class](obj.ViewObject)
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
                  blocks=False, fillet_rims=False, hex_order=1):
    """Add the analysis group of `source` (a part, Body or Link); returns SingularCurves.

    `size` None (stored as Size 0) lets the backend pick it. Without `report` the backend
    runs first (synchronously). With it, `digest` must be runs.input_digest() of the solid,
    size, method and blocks that report was computed from. With `method` ("auto", "snap", ...), a
    correction: the curves are those after correcting, Before35 counts the 3-5 curves before.
    With `blocks` (method "auto", the default, another method, or "none"), the part cut into blocks too: a
    Blocks object (the tets coloured by block) beside the curves, and when the blocks could be
    meshed a HexMesh object (hexa8, or hexa20 with `hex_order` 2). `fillet_rims`: method fillet
    (or auto's fillet try) also fillets the convex rims across a strip from each concave edge.
    """
    solid = shapes.solid_of(source)
    size = float(size or 0.0)
    if blocks:
        method = method or "auto"
    if report is None:
        report = runs.run(solid, size or None, method or None, blocks, backend,
                          fillet_rims=fillet_rims, hex_order=hex_order)
        digest = runs.input_digest(solid, size, method, blocks, fillet_rims, hex_order)
    elif blocks:
        runs.remember_block_mesh(digest, report)
    doc = source.Document
    with _Transaction(doc, _kind(method, blocks)):
        group = doc.addObject("App::DocumentObjectGroup", "FrameFixBlocks" if blocks else
                              "FrameFixCorrection" if method else "FrameFixAnalysis")
        group.Label = _group_label(source, _method_label(method, report), blocks)
        curves, parts = _add_parts(doc, method, blocks, report)
        curves.Source, curves.Size, curves.Blocks, curves.Method = source, size, blocks, method
        curves.FilletRims = bool(fillet_rims)
        curves.HexOrder = int(hex_order)
        runs.store(curves, report, digest)
        if curves.FilletedBrep:
            parts.append(_add_filleted(doc, source, curves))
        if _has_hexes(report):
            parts.append(_add_hex_mesh(doc, curves))
        group.addObjects(parts)
        _fade_source(curves, source)
        _recompute(doc, parts)
    return curves


def _has_hexes(report):
    return bool((report.get("hexmesh") or {}).get("done"))


def _add_hex_mesh(doc, curves):
    obj = _add(doc, "Fem::FemMeshObjectPython", "HexMesh", "Hex mesh", HexMesh)
    obj.Analysis = curves
    return obj


def _add_filleted(doc, source, curves):
    """The fillet correction's solid as a new feature reading curves.FilletedBrep (the user's
    part is not touched)."""
    obj = _add(doc, "Part::FeaturePython", "FilletedPart", "Filleted %s" % shapes.label_of(source),
               FilletedPart)
    obj.Analysis = curves
    return obj


def _method_label(method, report):
    """"auto: fillet+snap" for auto (what it kept), else the method."""
    return "%s: %s" % (method, _chosen(report)) if method == "auto" and _chosen(report) else method


def _group_label(source, method, blocks):
    label = shapes.label_of(source)
    return (BLOCKS_GROUP_LABEL % (method, label) if blocks else
            CORRECTION_GROUP_LABEL % (method, label) if method else GROUP_LABEL % label)


def _chosen(report):
    """What method auto kept ("fillet+snap"), "" when nothing or another method ran."""
    return ((report or {}).get("correction") or {}).get("chosen") or ""


def _methods_run(method, report):
    """The methods whose results a run holds: auto's chosen one(s) ("fillet+snap"), or `method`."""
    if method == "auto":
        return [m for m in _chosen(report).split("+") if m]
    return [method] if method and method != "none" else []


# What each method adds to the document beside the curves: (name, label, proxy).
_METHOD_OBJECTS = {"snap": ("SnappedPaths", "Snapped paths", SnappedPaths),
                   "fillet": ("MappedCurves", MAPPED_LABEL, MappedCurves),
                   "extrude-nodes": ("Streamlines", "Streamlines", Streamlines),
                   "extrude-curves": ("Streamlines", "Streamlines", Streamlines)}


def _method_objects(methods):
    found = []
    for m in methods:
        if m in _METHOD_OBJECTS and _METHOD_OBJECTS[m] not in found:
            found.append(_METHOD_OBJECTS[m])
    return found


def _add_parts(doc, method, blocks, report):
    """The curves object and the objects reading its report; returns (curves, all of them)."""
    corrected = method and method != "none"
    curves = _add(doc, "Part::FeaturePython", "SingularCurves",
                  "Corrected singular curves" if corrected else "Singular curves", SingularCurves)
    parts = [curves, _add(doc, "Part::FeaturePython", "SingularNodes", "Singular nodes",
                          SingularNodes),
             _add(doc, "Part::FeaturePython", "FeatureCurves", "Feature curves", FeatureCurves)]
    for name, label, proxy in _method_objects(_methods_run(method, report)):
        parts.append(_add(doc, "Part::FeaturePython", name, label, proxy))
    if blocks:
        parts.append(_add(doc, "Fem::FemMeshObjectPython", "Blocks", "Blocks (tets)", Blocks))
        parts.append(_add(doc, "Part::FeaturePython", "BlockSurfaces", "Block surfaces", BlockSurfaces))
        parts.append(_add(doc, "Part::FeaturePython", "BlockEdges", "Block edges", BlockEdges))
    for part in parts[1:]:
        part.Analysis = curves
    return curves, parts


def update_analysis(curves, size, report, digest, method="", fillet_rims=False):
    """Store a new run (from the task panel) on an existing analysis and recompute it."""
    doc = curves.Document
    if curves.Blocks:
        runs.remember_block_mesh(digest, report)
    with _Transaction(doc, _kind(method, curves.Blocks)):
        curves.Size, curves.Method = float(size or 0.0), method
        curves.FilletRims = bool(fillet_rims)
        runs.store(curves, report, digest)
        if curves.FilletedBrep and not _with_proxy(curves.InList, FilletedPart):
            _add_to_group(curves, _add_filleted(doc, curves.Source, curves))
        if _has_hexes(report) and not _with_proxy(curves.InList, HexMesh):
            _add_to_group(curves, _add_hex_mesh(doc, curves))
        for name, label, proxy in _method_objects(_methods_run(method, report)):
            if not _with_proxy(curves.InList, proxy):
                obj = _add(doc, "Part::FeaturePython", name, label, proxy)
                obj.Analysis = curves
                _add_to_group(curves, obj)
        _fade_source(curves, curves.Source)
        _recompute(doc, [curves] + [o for o in curves.InList if hasattr(o, "Analysis")])
    return curves


def _add_to_group(curves, obj):
    """Put a new object of an analysis (a panel run switched its method) into its group."""
    for group in [o for o in curves.InList if o.isDerivedFrom("App::DocumentObjectGroup")]:
        group.addObject(obj)


def make_blocks(source, size=None, method="auto", report=None, digest=None, backend=None,
                fillet_rims=False, hex_order=1):
    """make_analysis with blocks: correct (`method`, auto by default, or none), cut into blocks; returns
    the Blocks object (its Analysis is the curves object owning the run)."""
    curves = make_analysis(source, size, report, digest, backend, method, blocks=True,
                           fillet_rims=fillet_rims, hex_order=hex_order)
    return blocks_of(curves)


def make_hex_mesh(source, size=None, method="auto", order=1, backend=None, fillet_rims=False):
    """make_blocks, and the blocks' hex mesh: returns the HexMesh object (a Fem::FemMeshObject
    of hexa8, or hexa20 with `order` 2). Raises FrameFixError with the reason when the blocks
    cannot be meshed (an invalid block, a pair not face to face); the blocks stay in the document."""
    blocks = make_blocks(source, size, method, backend=backend, fillet_rims=fillet_rims, hex_order=order)
    found = _with_proxy(blocks.Analysis.InList, HexMesh)
    if not found:
        hexmesh = report_of(blocks.Analysis)["hexmesh"] or {"reason": "the backend made none"}
        raise FrameFixError("the blocks of %s could not be meshed: %s" % (shapes.label_of(source),
                                                                         hexmesh["reason"]))
    return found[0]


def _with_proxy(objects, proxy_class):
    return [o for o in objects if isinstance(getattr(o, "Proxy", None), proxy_class)]


def blocks_of(curves):
    """The Blocks object of a block run's curves object, or None."""
    found = _with_proxy(curves.InList, Blocks)
    return found[0] if found else None


def analyses_of(source):
    """The SingularCurves objects analysing `source`."""
    return _with_proxy(source.InList, SingularCurves)
