"""FrameFix_Correct: the Analyze panel with a correction method (auto by default: the
methods in turn, the best kept). The backend analyses, corrects the 3-5 curves and analyses again; the document
gets the curves after the correction, next to (never instead of) the part."""
from .. import paths
from .analyze import AnalyzeCommand


class CorrectCommand(AnalyzeCommand):
    METHOD = "auto"

    def GetResources(self):
        return {"Pixmap": paths.icon("FrameFix_Correct"),
                "MenuText": "Correct 3-5 curves",
                "ToolTip": "Correct the frame field of the selected solid (auto by default: the "
                           "methods in turn, the best kept) and show the singular curves after the correction"}
