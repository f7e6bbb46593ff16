"""ViewProviderBlockSurfaces: each block's smoothed boundary in its block's colour (BlockColors,
invalid blocks red), shaded without the triangles' edges; ViewProviderBlockEdges: the block
edges as dark lines over them."""
from .. import style
from .base import ViewProviderBase


class ViewProviderBlockSurfaces(ViewProviderBase):
    ICON = "FrameFix_Blocks"

    def set_style(self, vobj):
        if "Shaded" in vobj.getEnumerationsOfProperty("DisplayMode"):
            vobj.DisplayMode = "Shaded"  # "Flat Lines" draws every triangle's edges: noise
        vobj.Transparency = style.BLOCKS_TRANSPARENCY

    def attach(self, vobj):
        super().attach(vobj)
        self.colour(vobj.Object)  # a restored document: the shape is there already

    def updateData(self, obj, prop):
        if prop in ("BlockOfFace", "BlockColors"):
            self.colour(obj)

    def colour(self, obj):
        colours = [tuple(c)[:3] for c in obj.BlockColors]
        owner = list(obj.BlockOfFace)
        if not owner or len(owner) != len(obj.Shape.Faces) or max(owner) >= len(colours):
            return  # the shape and its labels do not agree yet
        alpha = style.BLOCKS_TRANSPARENCY / 100.0  # per-face colours carry the transparency
        obj.ViewObject.DiffuseColor = [colours[b] + (alpha,) for b in owner]


class ViewProviderBlockEdges(ViewProviderBase):
    ICON = "FrameFix_Blocks"

    def set_style(self, vobj):
        vobj.LineWidth = style.BLOCK_EDGE_WIDTH
        vobj.LineColor = style.BLOCK_EDGE_COLOR
        vobj.PointSize = 1.0
