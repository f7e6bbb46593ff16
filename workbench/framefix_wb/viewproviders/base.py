"""Behaviour shared by the view providers: icon, state, double click opens the panel."""
import FreeCAD

from .. import paths
from ..objects.properties import ProxyBase


class ViewProviderBase(ProxyBase):
    ICON = "FrameFix_Analyze"

    def __init__(self, vobj):
        vobj.Proxy = self
        self.set_style(vobj)

    def set_style(self, vobj):
        pass

    def attach(self, vobj):
        self.Object = vobj.Object

    def getIcon(self):
        return paths.icon(self.ICON)

    def analysis(self):
        return getattr(self.Object, "Analysis", None) or self.Object

    def doubleClicked(self, vobj):
        """Open the Analyze panel on this analysis, to rerun it with another size."""
        if not FreeCAD.GuiUp:
            return False
        import FreeCADGui
        from ..taskpanels.analyze_panel import AnalyzePanel
        if FreeCADGui.Control.activeDialog():
            FreeCADGui.Control.closeDialog()
        analysis = self.analysis()
        FreeCADGui.Control.showDialog(AnalyzePanel(analysis.Source, analysis))
        return True
