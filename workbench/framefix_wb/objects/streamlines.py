"""Streamlines: what an extrusion correction traced (report.correction.streamlines), as
polylines inside the part; the ones that constrain the field are kept apart from the failed
ones by their edge code (1 used, 0 not used)."""
from .. import geometry
from .properties import ProxyBase, add, report_of


class Streamlines(ProxyBase):
    def __init__(self, obj):
        obj.Proxy = self
        self.setup(obj)

    def setup(self, obj):
        add(obj, "App::PropertyLink", "Analysis", "FrameFix", "The corrected curves object")

    def onDocumentRestored(self, obj):
        self.setup(obj)

    def execute(self, obj):
        correction = report_of(obj.Analysis)["correction"]
        lines = correction["streamlines"] if correction else []
        obj.Shape = geometry.polylines(lines, lambda s: int(s["used"]))[0]
