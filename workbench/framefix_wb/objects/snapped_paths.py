"""SnappedPaths: where boundary snapping moved each 3-5 curve (a correction's
report.correction.snapped_paths), as polylines on the part's boundary."""
from .. import geometry
from .properties import ProxyBase, add, report_of


class SnappedPaths(ProxyBase):
    def __init__(self, obj):
        obj.Proxy = self
        self.setup(obj)

    def setup(self, obj):
        add(obj, "App::PropertyLink", "Analysis", "FrameFix", "The corrected curves object")

    def onDocumentRestored(self, obj):
        self.setup(obj)

    def execute(self, obj):
        correction = report_of(obj.Analysis)["correction"]
        paths = correction["snapped_paths"] if correction else []
        obj.Shape = geometry.polylines(paths, lambda p: 0)[0]
