"""BlockSurfaces and BlockEdges: the blocks of a block run as the backend smoothed them for
display (block_surfaces.vtk, block_edges.vtk), not as tet-face staircases. BlockSurfaces is a
compound of one shell of triangles per block; BlockOfFace names the block of each face (Face1 is
element 0) and BlockColors gives one colour per block, chosen here on the App side so that a
macro's blocks are coloured as the command's are. BlockEdges is a compound of each block's
edges as polylines. Both come from the run's block mesh (runs.block_mesh) and are saved with
the document like any Part shape.
"""
import FreeCAD

from .. import runs, style
from ..errors import FrameFixError
from .properties import HIDDEN, ProxyBase, add, report_of


def _run_cells(curves, key):
    mesh = runs.block_mesh(curves.InputDigest)
    if mesh is None or key not in mesh:
        raise FrameFixError("the blocks of this run are not in memory: change the Size of %s "
                            "or rerun FrameFix Blocks" % curves.Label)
    return mesh[key]


def shells_of(surfaces):
    """(compound, block of each face) of block_surfaces: one shell per block, in block order."""
    import Part
    points = [FreeCAD.Vector(*p) for p in surfaces["points"].tolist()]
    extent = surfaces["points"].max(axis=0) - surfaces["points"].min(axis=0) if len(points) else [1.0]
    tolerance = 1e-9 * max(1.0, float(max(extent)))  # joins only coincident points
    by_block = {}
    for tri, b in zip(surfaces["cells"], surfaces["block"].tolist()):
        by_block.setdefault(b, []).append(tuple(int(i) for i in tri))
    shells, owner = [], []
    for b in sorted(by_block):
        shell = Part.Shape()
        shell.makeShapeFromMesh((points, by_block[b]), tolerance)
        shells.append(shell)
        owner += [b] * len(shell.Faces)
    return (Part.Compound(shells) if shells else Part.Shape()), owner


class _RunShape(ProxyBase):
    """A Part shape made from one kind of the run's block cells (CELLS)."""
    CELLS = ""

    def __init__(self, obj):
        obj.Proxy = self
        self.setup(obj)

    def setup(self, obj):
        add(obj, "App::PropertyLink", "Analysis", "FrameFix", "The curves object of the block run")
        add(obj, "App::PropertyString", "MeshDigest", "FrameFix",
            "InputDigest of the run the shape comes from", HIDDEN)

    def onDocumentRestored(self, obj):
        self.setup(obj)

    def blocks(self, obj):
        blocks = report_of(obj.Analysis)["blocks"]
        if blocks is None:
            raise FrameFixError("%s holds no block run" % obj.Analysis.Label)
        return blocks

    def execute(self, obj):
        self.update(obj, self.blocks(obj))
        if obj.MeshDigest != obj.Analysis.InputDigest:
            self.build(obj, _run_cells(obj.Analysis, self.CELLS))
            obj.MeshDigest = obj.Analysis.InputDigest

    def update(self, obj, blocks):
        pass


class BlockSurfaces(_RunShape):
    CELLS = "surfaces"

    def setup(self, obj):
        super().setup(obj)
        add(obj, "App::PropertyIntegerList", "BlockOfFace", "FrameFix",
            "per face (Face1 first): its block", HIDDEN)
        add(obj, "App::PropertyColorList", "BlockColors", "FrameFix",
            "per block: its colour (neighbours differ, invalid blocks red)", HIDDEN)

    def update(self, obj, blocks):
        obj.BlockColors = style.block_colors(blocks["blocks"])

    def build(self, obj, cells):
        obj.Shape, owner = shells_of(cells)
        obj.BlockOfFace = owner  # last: the view provider colours the faces on this change


class BlockEdges(_RunShape):
    CELLS = "edges"

    def build(self, obj, cells):
        from .. import geometry
        items = [{"points": cells["points"][c].tolist()} for c in cells["cells"]]
        obj.Shape = geometry.polylines(items, lambda item: 0)[0]
