# FrameFix workbench, GUI part. InitGui.py is exec'd inside a function by FreeCAD: names
# defined here are not visible later, so everything is imported inside the methods.
class FrameFixWorkbench(Workbench):
    MenuText = "FrameFix"
    ToolTip = "Hex-meshability analysis: frame field singularities and 3-5 curves"

    def __init__(self):
        from framefix_wb import paths
        self.__class__.Icon = paths.icon("FrameFix_Workbench")

    def Initialize(self):
        from framefix_wb.commands import register_commands
        names = register_commands()
        self.appendToolbar("FrameFix", names)
        self.appendMenu("FrameFix", names)

    def GetClassName(self):
        return "Gui::PythonWorkbench"


Gui.addWorkbench(FrameFixWorkbench())
