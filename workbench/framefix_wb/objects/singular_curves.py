"""SingularCurves: the analysis object. It owns the backend run and its report; the nodes and
feature curves objects read the report from it. With a Method it is a correction: the
backend runs `correct --method M` and the curves are those after the correction.

Recompute reruns the backend only when the analysed solid, size or method changed
(runs.refresh), so results applied from the task panel are not computed twice.
"""
from .. import geometry, runs, style
from .properties import HIDDEN, READ_ONLY, ProxyBase, add, report_of

SUMMARY_PROPERTIES = (
    ("Curves", "curves", "singular curves"), ("Valence3", "valence3", "valence 3 curves"),
    ("Valence5", "valence5", "valence 5 curves"), ("Curves35", "curves_3_5", "3-5 curves"),
    ("Nodes", "nodes", "singular nodes"), ("InvalidNodes", "invalid_nodes", "invalid nodes"))


class SingularCurves(ProxyBase):
    def __init__(self, obj):
        obj.Proxy = self
        self.setup(obj)

    def setup(self, obj):
        add(obj, "App::PropertyLink", "Source", "FrameFix",
            "The analysed solid; editing it marks this analysis for recompute")
        add(obj, "App::PropertyLength", "Size", "FrameFix",
            "Target tet edge length (model units); 0: the backend's default size")
        add(obj, "App::PropertyString", "Method", "FrameFix",
            "Correction method (the backend lists them: framefix info); empty: an analysis")
        add(obj, "App::PropertyBool", "Blocks", "FrameFix",
            "The run also cuts the part into blocks (framefix blocks); Method: the correction "
            "before the cut", READ_ONLY)
        add(obj, "App::PropertyBool", "FilletRims", "FrameFix",
            "Method fillet (or auto's fillet try): also fillet the convex rim across a strip "
            "from each concave edge filleted, as the paper does for a groove")
        add(obj, "App::PropertyInteger", "HexOrder", "FrameFix",
            "Block runs: the hex mesh's elements, 1 hexa8 (C3D8) or 2 hexa20 (C3D20)", 0, 1)
        add(obj, "App::PropertyInteger", "Before35", "Summary",
            "3-5 curves before the correction", READ_ONLY)
        self.show_method(obj)
        add(obj, "App::PropertyString", "Report", "FrameFix", "report.json of the last run", HIDDEN)
        add(obj, "App::PropertyString", "InputDigest", "FrameFix", "solid, size, method, rims of that run",
            HIDDEN)
        add(obj, "App::PropertyString", "FilletedBrep", "FrameFix",
            "method fillet: the filleted solid of that run (BREP text), read by FilletedPart", HIDDEN)
        add(obj, "App::PropertyIntegerList", "EdgeKinds", "FrameFix",
            "per edge: 3 valence 3, 5 valence 5, 35 3-5 curve, 0 other", HIDDEN)
        add(obj, "App::PropertyIntegerList", "EdgeCurves", "FrameFix", "per edge: curve id", HIDDEN)
        add(obj, "App::PropertyInteger", "SourceTransparency", "FrameFix",
            "source's transparency before the analysis (-1: untouched)", HIDDEN, -1)
        for name, _, doc in SUMMARY_PROPERTIES:
            add(obj, "App::PropertyInteger", name, "Summary", "Number of " + doc, READ_ONLY)
        add(obj, "App::PropertyBool", "Meshable", "Summary",
            "No 3-5 curve and no invalid node", READ_ONLY)
        add(obj, "App::PropertyInteger", "Tets", "Summary", "Tets of the analysed mesh", READ_ONLY)
        add(obj, "App::PropertyFloat", "MeshSize", "Summary", "Size the mesh was made with",
            READ_ONLY)

    def onDocumentRestored(self, obj):
        self.setup(obj)

    def show_method(self, obj):
        """Method and Before35 only on corrections: an analysis has no use for them."""
        for name in ("Method", "Before35", "FilletRims"):
            obj.setEditorMode(name, (READ_ONLY if name == "Before35" else 0) if obj.Method
                              else HIDDEN)
        obj.setEditorMode("Blocks", READ_ONLY if obj.Blocks else HIDDEN)
        obj.setEditorMode("HexOrder", 0 if obj.Blocks else HIDDEN)

    def onChanged(self, obj, prop):
        if prop in ("Method", "Blocks") and "Before35" in obj.PropertiesList:
            self.show_method(obj)

    def execute(self, obj):
        runs.refresh(obj)
        report = report_of(obj)
        shape, codes, owners = geometry.polylines(
            report["curves"], lambda c: style.CURVE_KIND_CODES.get(c["kind"], style.OTHER_KIND))
        obj.Shape = shape
        obj.EdgeCurves = [report["curves"][i]["id"] for i in owners]
        obj.EdgeKinds = codes  # after Shape: the view provider colours edges on this change
        for name, key, _ in SUMMARY_PROPERTIES:
            setattr(obj, name, report["summary"][key])
        obj.Meshable = report["summary"]["meshable"]
        obj.Tets = int(report["mesh"].get("tets", 0))
        obj.MeshSize = float(report["mesh"].get("size", 0.0))
        correction = report["correction"]
        obj.Before35 = correction["before"]["curves_3_5"] if correction else 0
