"""FilletedPart: the fillet correction's solid (a new feature; the user's part is never
touched). It reads the solid from its analysis's FilletedBrep, so that recomputing the
analysis (a moved part, another size) brings a new filleted solid with it."""
import Part

from .properties import ProxyBase, add


class FilletedPart(ProxyBase):
    def __init__(self, obj):
        obj.Proxy = self
        self.setup(obj)

    def setup(self, obj):
        add(obj, "App::PropertyLink", "Analysis", "FrameFix", "The fillet correction's curves object")

    def onDocumentRestored(self, obj):
        self.setup(obj)

    def execute(self, obj):
        shape = Part.Shape()
        brep = getattr(obj.Analysis, "FilletedBrep", "") if obj.Analysis else ""
        if brep:
            shape.importBrepFromString(brep)
        obj.Shape = shape
