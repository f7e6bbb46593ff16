"""Blocks: the part cut into blocks (`framefix blocks`), as the run's tet mesh with the block
of each tet. A Fem::FemMeshObjectPython: FemMesh holds the tets (element i + 1 is tet i),
BlockIds their blocks, BlockValid the blocks' validity, BlockColors their colours (chosen on
the App side, so that a macro's blocks are coloured as the command's); the view provider colours
the elements by block. Hidden by default: BlockSurfaces shows the blocks smoothed. The run (and its report) belongs to the curves object in Analysis; the
tet mesh of a new run comes from runs.block_mesh() in the recompute after it, and is
saved with the document (MeshDigest: the run it belongs to).
"""
from .. import runs, style
from ..errors import FrameFixError
from ..report import blocks_text
from .properties import HIDDEN, READ_ONLY, ProxyBase, add, report_of

SUMMARY_PROPERTIES = (
    ("Count", "count", "Blocks"), ("Valid", "valid", "Valid blocks"),
    ("Pairs", "pairs", "Neighbouring block pairs"),
    ("ConformingPairs", "conforming_pairs", "Neighbouring pairs meeting face to face"),
    ("FlatEdges", "flat_edges", "Block edges with a flat (180 deg) angle"),
    ("FlatCorners", "flat_corners", "Block corners with a flat angle"))


def build_fem_mesh(mesh):
    """A Fem.FemMesh of the tets of `mesh` (vtk.read_tets): node i + 1 is point i, volume
    i + 1 is tet i. SMESH orders a tet's nodes the other way round from VTK."""
    import Fem
    fem = Fem.FemMesh()
    for i, (x, y, z) in enumerate(mesh["points"].tolist()):
        fem.addNode(x, y, z, i + 1)
    for i, (a, b, c, d) in enumerate(mesh["tets"].tolist()):
        fem.addVolume([a + 1, c + 1, b + 1, d + 1], i + 1)
    return fem


class Blocks(ProxyBase):
    def __init__(self, obj):
        obj.Proxy = self
        self.setup(obj)

    def setup(self, obj):
        add(obj, "App::PropertyLink", "Analysis", "FrameFix",
            "The curves object of the block run (Source, Size, Method)")
        add(obj, "App::PropertyIntegerList", "BlockIds", "FrameFix",
            "per tet (FemMesh element i + 1): its block, -1 none", HIDDEN)
        add(obj, "App::PropertyIntegerList", "BlockValid", "FrameFix",
            "per block: 1 valid hexahedron, 0 not", HIDDEN)
        add(obj, "App::PropertyColorList", "BlockColors", "FrameFix",
            "per block: its colour (neighbours differ, invalid blocks red)", HIDDEN)
        add(obj, "App::PropertyString", "MeshDigest", "FrameFix",
            "InputDigest of the run FemMesh comes from", HIDDEN)
        for name, _, doc in SUMMARY_PROPERTIES:
            add(obj, "App::PropertyInteger", name, "Summary", doc, READ_ONLY)
        add(obj, "App::PropertyString", "Summary", "Summary", "The blocks in one line", READ_ONLY)

    def onDocumentRestored(self, obj):
        self.setup(obj)

    def execute(self, obj):
        curves = obj.Analysis
        blocks = report_of(curves)["blocks"]
        if blocks is None:
            raise FrameFixError("%s holds no block run" % curves.Label)
        if obj.MeshDigest != curves.InputDigest:
            mesh = runs.block_mesh(curves.InputDigest)
            if mesh is None:
                raise FrameFixError("the tets of this block run are not in memory: change the "
                                    "Size of %s or rerun FrameFix Blocks" % curves.Label)
            obj.FemMesh = build_fem_mesh(mesh)
            obj.MeshDigest = curves.InputDigest
            ids = mesh["block"].tolist()
        else:
            ids = list(obj.BlockIds)
        obj.BlockValid = [int(b["valid"]) for b in blocks["blocks"]]
        obj.BlockColors = style.block_colors(blocks["blocks"])
        for name, key, _ in SUMMARY_PROPERTIES:
            setattr(obj, name, blocks[key])
        obj.Summary = blocks_text(blocks)
        obj.BlockIds = ids  # last: the view provider colours the elements on this change
