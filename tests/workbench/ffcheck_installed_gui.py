# Run by check_install.py as `freecad ffcheck_installed_gui.py` (GUI, under Xvfb) in a HOME
# holding only the installed workbench: it is listed, activates, and has its command.
import os
import sys
import traceback

code = 1
try:
    import FreeCADGui
    assert "FrameFixWorkbench" in FreeCADGui.listWorkbenches(), FreeCADGui.listWorkbenches().keys()
    FreeCADGui.activateWorkbench("FrameFixWorkbench")
    assert "FrameFix_Analyze" in FreeCADGui.listCommands()
    print("check: gui workbench ok")
    code = 0
except BaseException:
    traceback.print_exc(file=sys.stdout)
sys.stdout.flush()
os._exit(code)
