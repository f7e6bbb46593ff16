"""FrameFix_Analyze: open the Analyze task panel on the selected solid."""
import FreeCAD
import FreeCADGui

from .. import paths
from ..errors import SelectionError
from ..shapes import source_from_selection


class AnalyzeCommand:
    METHOD = None  # a correction method: the Correct command
    BLOCKS = False  # `framefix blocks`: the Blocks command

    def GetResources(self):
        return {"Pixmap": paths.icon("FrameFix_Analyze"),
                "MenuText": "Analyze hex-meshability",
                "ToolTip": "Compute the frame field of the selected solid and show its singular "
                           "curves; 3-5 curves and invalid nodes make it not hex-meshable"}

    def IsActive(self):
        return FreeCAD.ActiveDocument is not None and FreeCADGui.Control.activeDialog() is False

    def Activated(self):
        from ..taskpanels.analyze_panel import AnalyzePanel
        source, message = None, ""
        try:
            source = source_from_selection(FreeCADGui.Selection.getSelection())
        except SelectionError as e:
            message = str(e)
            FreeCAD.Console.PrintWarning("FrameFix: %s\n" % message)
        FreeCADGui.Control.showDialog(AnalyzePanel(source, message=message, method=self.METHOD,
                                                   blocks=self.BLOCKS))
