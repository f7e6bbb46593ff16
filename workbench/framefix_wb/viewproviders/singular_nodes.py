"""ViewProviderSingularNodes: big points, invalid nodes in their own colour."""
from .. import style
from .base import ViewProviderBase


class ViewProviderSingularNodes(ViewProviderBase):
    ICON = "FrameFix_Nodes"

    def set_style(self, vobj):
        vobj.PointSize = style.NODE_POINT_SIZE

    def updateData(self, obj, prop):
        if prop in ("NodeValid", "Shape") and len(obj.NodeValid) == len(obj.Shape.Vertexes):
            if obj.NodeValid and hasattr(obj.ViewObject, "PointColorArray"):
                obj.ViewObject.PointColorArray = [
                    style.NODE_COLORS[bool(v)][0] for v in obj.NodeValid]
