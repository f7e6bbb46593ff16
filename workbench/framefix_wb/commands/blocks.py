"""FrameFix_Blocks: the Analyze panel running `framefix blocks`: analyse, correct (method
auto by default, or none), cut the part into blocks. The document gets the blocks (the
tets coloured by block) with the corrected curves and what the correction added, beside the part."""
from .. import paths
from .analyze import AnalyzeCommand


class BlocksCommand(AnalyzeCommand):
    METHOD = "auto"
    BLOCKS = True

    def GetResources(self):
        return {"Pixmap": paths.icon("FrameFix_Blocks"),
                "MenuText": "Cut into blocks",
                "ToolTip": "Correct the frame field of the selected solid (or of an analysis) and "
                           "cut it into blocks along the separatrix sheets; shows the blocks "
                           "(invalid ones red), the corrected curves and the snapped paths"}
