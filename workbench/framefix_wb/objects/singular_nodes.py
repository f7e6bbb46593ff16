"""SingularNodes: the singular nodes of an analysis as a compound of vertices."""
from .. import geometry
from .properties import HIDDEN, READ_ONLY, ProxyBase, add, report_of


class SingularNodes(ProxyBase):
    def __init__(self, obj):
        obj.Proxy = self
        self.setup(obj)

    def setup(self, obj):
        add(obj, "App::PropertyLink", "Analysis", "FrameFix", "The singular curves object")
        add(obj, "App::PropertyIntegerList", "NodeValid", "FrameFix",
            "per vertex: 1 valid, 0 invalid", HIDDEN)
        add(obj, "App::PropertyInteger", "InvalidNodes", "Summary", "Invalid nodes", READ_ONLY)

    def onDocumentRestored(self, obj):
        self.setup(obj)

    def execute(self, obj):
        nodes = report_of(obj.Analysis)["nodes"]
        obj.Shape = geometry.points([n["position"] for n in nodes])
        obj.NodeValid = [int(n["valid"]) for n in nodes]
        obj.InvalidNodes = sum(1 for n in nodes if not n["valid"])
