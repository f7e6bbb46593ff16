"""MappedCurves: the fillet correction's curves mapped back onto the original part
(report.correction.mapped), coloured by kind as the singular curves are. Points that lay on a
fillet sit on the concave edge it replaced. Valid says whether the mapped graph is hex-meshable;
FlatCornersValid whether the original part's field, solved again with flat corners under the
mapped valence-5 curves, comes out hex-meshable too."""
from .. import geometry, style
from .properties import HIDDEN, READ_ONLY, ProxyBase, add, report_of


class MappedCurves(ProxyBase):
    def __init__(self, obj):
        obj.Proxy = self
        self.setup(obj)

    def setup(self, obj):
        add(obj, "App::PropertyLink", "Analysis", "FrameFix", "The corrected curves object")
        add(obj, "App::PropertyIntegerList", "EdgeKinds", "FrameFix",
            "per edge: 3 valence 3, 5 valence 5, 35 3-5 curve, 0 other", HIDDEN)
        add(obj, "App::PropertyBool", "Valid", "Summary",
            "The mapped graph is hex-meshable", READ_ONLY)
        add(obj, "App::PropertyBool", "FlatCornersValid", "Summary",
            "The original part solved again with flat corners under the mapped curves is "
            "hex-meshable", READ_ONLY)

    def onDocumentRestored(self, obj):
        self.setup(obj)

    def execute(self, obj):
        correction = report_of(obj.Analysis)["correction"] or {}
        mapped = correction.get("mapped") or {}
        shape, codes, _ = geometry.polylines(
            mapped.get("curves", []), lambda c: style.CURVE_KIND_CODES.get(c["kind"], style.OTHER_KIND))
        obj.Shape = shape
        obj.EdgeKinds = codes  # after Shape: the view provider colours edges on this change
        obj.Valid = bool(mapped) and mapped["summary"]["meshable"]
        flat = mapped.get("flat_corners") or {}
        obj.FlatCornersValid = bool(flat.get("solved")) and flat["summary"]["meshable"]
