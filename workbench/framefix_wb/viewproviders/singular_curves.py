"""ViewProviderSingularCurves: thick lines, one colour per curve kind (style.CURVE_COLORS)."""
from .. import style
from .base import ViewProviderBase


def colour_by_kind(obj, prop):
    """One colour per edge from obj.EdgeKinds, once Shape and EdgeKinds agree."""
    if prop in ("EdgeKinds", "Shape") and len(obj.EdgeKinds) == len(obj.Shape.Edges):
        if obj.EdgeKinds:
            obj.ViewObject.LineColorArray = style.color_list(obj.EdgeKinds, style.CURVE_COLORS)


class ViewProviderSingularCurves(ViewProviderBase):
    ICON = "FrameFix_Analyze"

    def set_style(self, vobj):
        vobj.LineWidth = style.CURVE_LINE_WIDTH
        vobj.PointSize = 1.0

    def updateData(self, obj, prop):
        colour_by_kind(obj, prop)

    def onDelete(self, vobj, subelements):
        """Give the analysed part back the transparency it had."""
        obj = vobj.Object
        source = getattr(obj, "Source", None)
        svo = getattr(source, "ViewObject", None)
        if svo is not None and hasattr(svo, "Transparency") and obj.SourceTransparency >= 0:
            svo.Transparency = obj.SourceTransparency
        return True
