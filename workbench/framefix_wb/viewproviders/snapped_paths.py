"""ViewProviderSnappedPaths: thick orange lines on the boundary."""
from .. import style
from .base import ViewProviderBase


class ViewProviderSnappedPaths(ViewProviderBase):
    ICON = "FrameFix_Correct"

    def set_style(self, vobj):
        vobj.LineWidth = style.CURVE_LINE_WIDTH
        vobj.LineColor = style.SNAPPED_PATH_COLOR
        vobj.PointSize = 1.0
