"""ViewProviderMappedCurves: the mapped curves, thin and coloured by kind."""
from .. import style
from .base import ViewProviderBase
from .singular_curves import colour_by_kind


class ViewProviderMappedCurves(ViewProviderBase):
    ICON = "FrameFix_Correct"

    def set_style(self, vobj):
        vobj.LineWidth = style.STREAMLINE_LINE_WIDTH
        vobj.PointSize = 1.0

    def updateData(self, obj, prop):
        colour_by_kind(obj, prop)
