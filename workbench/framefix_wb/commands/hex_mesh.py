"""FrameFix_HexMesh: the Blocks panel (a block run meshes its blocks too); the document gets
the blocks and, when they can be meshed, the hex mesh as a Fem::FemMeshObject for FreeCAD's
FEM workbench, coloured by quality."""
from .. import paths
from .blocks import BlocksCommand


class HexMeshCommand(BlocksCommand):
    def GetResources(self):
        return {"Pixmap": paths.icon("FrameFix_HexMesh"),
                "MenuText": "Hex mesh",
                "ToolTip": "Correct the frame field of the selected solid, cut it into blocks "
                           "and mesh the blocks with hexahedra: a FEM mesh object (hexa8) "
                           "coloured by scaled Jacobian, for a CalculiX analysis"}
