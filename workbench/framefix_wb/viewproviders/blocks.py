"""ViewProviderBlocks: the tets coloured by block (one colour per block, invalid blocks in
style.INVALID_BLOCK_COLOR), only the faces, semi-transparent so the curves inside show."""
from .. import style
from .base import ViewProviderBase


class ViewProviderBlocks(ViewProviderBase):
    ICON = "FrameFix_Blocks"
    coloured = 0  # elements given a colour by the last colour()

    def set_style(self, vobj):
        if "Faces" in vobj.getEnumerationsOfProperty("DisplayMode"):
            vobj.DisplayMode = "Faces"  # "Faces & Wireframe" draws every tet edge: noise
        vobj.Transparency = style.BLOCKS_TRANSPARENCY
        vobj.ShapeColor = style.block_color(0, True)
        vobj.Visibility = False  # BlockSurfaces shows the blocks without the staircase

    def updateData(self, obj, prop):
        if prop == "BlockIds":
            self.colour(obj)

    def colour(self, obj):
        ids = list(obj.BlockIds)
        colours = [tuple(c)[:3] for c in obj.BlockColors]
        none = style.block_color(-1, False)
        element_colors = {
            i + 1: colours[b] if 0 <= b < len(colours) else none for i, b in enumerate(ids)}
        obj.ViewObject.ElementColor = element_colors
        self.coloured = len(element_colors)  # FreeCAD 0.20 cannot read ElementColor back
