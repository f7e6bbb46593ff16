"""ViewProviderStreamlines: the extrusions' streamlines in green, as in the paper's figures."""
from .. import style
from .base import ViewProviderBase


class ViewProviderStreamlines(ViewProviderBase):
    ICON = "FrameFix_Correct"

    def set_style(self, vobj):
        vobj.LineWidth = style.STREAMLINE_LINE_WIDTH
        vobj.LineColor = style.STREAMLINE_COLOR
        vobj.PointSize = 1.0
