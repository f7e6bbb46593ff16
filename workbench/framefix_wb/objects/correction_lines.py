"""Polylines a correction reports (report.correction[KEY]), one Part object per kind: the
snapped paths of boundary snapping, the streamlines of the extrusions."""
from .. import geometry
from .properties import ProxyBase, add, report_of


class CorrectionLines(ProxyBase):
    KEY = ""              # the correction's list of {"points": ...} items

    @staticmethod
    def code_of(item):    # the edge code of an item's edges (the view provider may colour by it)
        return 0

    def __init__(self, obj):
        obj.Proxy = self
        self.setup(obj)

    def setup(self, obj):
        add(obj, "App::PropertyLink", "Analysis", "FrameFix", "The corrected curves object")

    def onDocumentRestored(self, obj):
        self.setup(obj)

    def execute(self, obj):
        correction = report_of(obj.Analysis)["correction"]
        items = correction[self.KEY] if correction else []
        obj.Shape = geometry.polylines(items, self.code_of)[0]
