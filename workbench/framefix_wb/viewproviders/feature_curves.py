"""ViewProviderFeatureCurves: the part's feature curves by valence, hidden by default."""
from .. import style
from .base import ViewProviderBase


class ViewProviderFeatureCurves(ViewProviderBase):
    ICON = "FrameFix_Features"

    def set_style(self, vobj):
        vobj.LineWidth = style.FEATURE_LINE_WIDTH
        vobj.PointSize = 1.0
        vobj.Visibility = False

    def updateData(self, obj, prop):
        if prop in ("EdgeValences", "Shape") and len(obj.EdgeValences) == len(obj.Shape.Edges):
            if obj.EdgeValences:
                obj.ViewObject.LineColorArray = style.color_list(
                    obj.EdgeValences, style.FEATURE_COLORS)
