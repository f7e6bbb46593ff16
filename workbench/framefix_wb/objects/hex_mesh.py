"""HexMesh: the hex mesh of a block run (`framefix hexmesh`) as a Fem::FemMeshObjectPython:
hexa8 volumes (hexa20 when the run's HexOrder is 2), which a FEM analysis with CalculiX takes as
it is. ScaledJacobians holds each hex's smallest scaled Jacobian;
the view provider colours the hexes by it. Like Blocks, the mesh of a new run comes from
runs.block_mesh() in the recompute after it and is saved with the document (MeshDigest). A run
whose blocks could not be meshed leaves the mesh empty and says why in Summary.
"""
from .. import runs
from ..errors import FrameFixError
from ..report import hexmesh_text
from .properties import HIDDEN, READ_ONLY, ProxyBase, add, report_of

# FreeCAD's node order from C3D8's / C3D20's (= VTK's), as FreeCAD's own .inp reader maps them.
FREECAD_HEXA8 = (5, 6, 7, 4, 1, 2, 3, 0)
FREECAD_HEXA20 = FREECAD_HEXA8 + (13, 14, 15, 12, 9, 10, 11, 8, 17, 18, 19, 16)


def build_fem_mesh(hexes):
    """A Fem.FemMesh of `hexes` (job.AnalysisJob._hexes): node i + 1 is point i, volume h + 1
    is hex h."""
    import Fem
    fem = Fem.FemMesh()
    for i, (x, y, z) in enumerate(hexes["points"].tolist()):
        fem.addNode(x, y, z, i + 1)
    order = FREECAD_HEXA20 if hexes["cells"].shape[1] == 20 else FREECAD_HEXA8
    for h, cell in enumerate(hexes["cells"].tolist()):
        fem.addVolume([cell[k] + 1 for k in order], h + 1)
    return fem


class HexMesh(ProxyBase):
    def __init__(self, obj):
        obj.Proxy = self
        self.setup(obj)

    def setup(self, obj):
        add(obj, "App::PropertyLink", "Analysis", "FrameFix",
            "The curves object of the block run (Source, Size, Method, HexOrder)")
        add(obj, "App::PropertyFloatList", "ScaledJacobians", "FrameFix",
            "per hex (FemMesh volume h + 1): its smallest scaled Jacobian", HIDDEN)
        add(obj, "App::PropertyString", "MeshDigest", "FrameFix",
            "InputDigest of the run FemMesh comes from", HIDDEN)
        add(obj, "App::PropertyInteger", "Hexes", "Summary", "Hexahedra", READ_ONLY)
        add(obj, "App::PropertyInteger", "Inverted", "Summary", "Hexes with a corner of scaled Jacobian <= 0", READ_ONLY)
        add(obj, "App::PropertyFloat", "MinScaledJacobian", "Summary", "Smallest scaled Jacobian", READ_ONLY)
        add(obj, "App::PropertyString", "Summary", "Summary", "The hex mesh in one line", READ_ONLY)

    def onDocumentRestored(self, obj):
        self.setup(obj)

    def execute(self, obj):
        curves = obj.Analysis
        hexmesh = report_of(curves)["hexmesh"]
        if hexmesh is None:
            raise FrameFixError("%s holds no hex mesh run" % curves.Label)
        obj.Summary = hexmesh_text(hexmesh)
        if obj.MeshDigest != curves.InputDigest:
            mesh = runs.block_mesh(curves.InputDigest)
            if mesh is None:
                raise FrameFixError("the hexes of this run are not in memory: change the Size of "
                                    "%s or rerun FrameFix Blocks" % curves.Label)
            hexes = mesh.get("hexes")
            if hexes is None:
                import Fem
                obj.FemMesh, sj = Fem.FemMesh(), []
            else:
                obj.FemMesh, sj = build_fem_mesh(hexes), hexes["scaled_jacobian"].tolist()
            obj.MeshDigest = curves.InputDigest
        else:
            sj = list(obj.ScaledJacobians)
        obj.Hexes = hexmesh.get("hexes", 0)
        obj.Inverted = hexmesh.get("inverted", 0)
        obj.MinScaledJacobian = hexmesh.get("min_scaled_jacobian", 0.0)
        obj.ScaledJacobians = sj  # last: the view provider colours the hexes on this change
