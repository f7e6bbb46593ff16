"""ViewProviderHexMesh: the hexes with their edges, each coloured by its smallest scaled
Jacobian (style.HEX_QUALITY_COLORS)."""
from .. import style
from .base import ViewProviderBase


class ViewProviderHexMesh(ViewProviderBase):
    ICON = "FrameFix_HexMesh"
    coloured = 0  # elements given a colour by the last colour()

    def set_style(self, vobj):
        if "Faces & Wireframe" in vobj.getEnumerationsOfProperty("DisplayMode"):
            vobj.DisplayMode = "Faces & Wireframe"  # the hexes' edges are the point of it
        vobj.ShapeColor = style.HEX_QUALITY_COLORS[-1][1]

    def updateData(self, obj, prop):
        if prop == "ScaledJacobians":
            self.colour(obj)

    def colour(self, obj):
        colors = {h + 1: style.hex_quality_color(sj) for h, sj in enumerate(obj.ScaledJacobians)}
        obj.ViewObject.ElementColor = colors
        self.coloured = len(colors)  # FreeCAD 0.20 cannot read ElementColor back
