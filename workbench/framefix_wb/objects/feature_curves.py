"""FeatureCurves: the part's feature curves coloured by the hex valence their dihedral angle
asks for. From the report's feature_curves; an entry without points uses the solid's edge."""
from .. import geometry, shapes
from .properties import HIDDEN, ProxyBase, add, report_of


class FeatureCurves(ProxyBase):
    def __init__(self, obj):
        obj.Proxy = self
        self.setup(obj)

    def setup(self, obj):
        add(obj, "App::PropertyLink", "Analysis", "FrameFix", "The singular curves object")
        add(obj, "App::PropertyIntegerList", "EdgeValences", "FrameFix",
            "per edge: hex valence 1..4", HIDDEN)

    def onDocumentRestored(self, obj):
        self.setup(obj)

    def execute(self, obj):
        features = report_of(obj.Analysis)["feature_curves"]
        with_points = [f for f in features if len(f["points"]) >= 2]
        compound, codes, _ = geometry.polylines(with_points, lambda f: f["valence"])
        pieces = [compound] if codes else []
        missing = [f for f in features if len(f["points"]) < 2 and f["edge"] > 0]
        if missing:
            edges = shapes.solid_of(obj.Analysis.Source).Edges
            for f in missing:
                if f["edge"] <= len(edges):
                    pieces.append(edges[f["edge"] - 1].copy())
                    codes.append(f["valence"])
        obj.Shape = geometry.compound_of(pieces)
        obj.EdgeValences = codes
