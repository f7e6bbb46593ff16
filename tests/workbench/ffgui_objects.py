"""GUI plumbing of the analysis objects with the canned backend (its curves are made up):
OK without Apply runs and closes, double click reopens the panel on the analysis and Apply
updates it in place, editing the part reruns on recompute, a saved document reopens with its
view providers, deleting the curves gives the part its transparency back."""
import os
import tempfile

import FreeCAD
import FreeCADGui
from PySide2 import QtCore, QtWidgets

import ffgui_harness

FAKES = os.path.join(os.path.dirname(os.path.abspath(ffgui_harness.__file__)), "fake_backends")
Apply, Ok = QtWidgets.QDialogButtonBox.Apply, QtWidgets.QDialogButtonBox.Ok


def runs(log):
    with open(log) as f:
        return len(f.readlines())


def scenario(h):
    from framefix_wb.taskpanels.analyze_panel import AnalyzePanel
    log = tempfile.NamedTemporaryFile(suffix=".log", delete=False).name
    os.environ.update(FRAMEFIX_BACKEND=os.path.join(FAKES, "canned.py"), FAKE_BACKEND_LOG=log)
    FreeCADGui.activateWorkbench("FrameFixWorkbench")
    doc = FreeCAD.newDocument("Objects")
    part = doc.addObject("Part::Box", "Box")
    doc.recompute()
    transparency = part.ViewObject.Transparency
    FreeCADGui.Selection.addSelection(part)
    FreeCADGui.runCommand("FrameFix_Analyze")
    yield 0.3
    h.button(Ok).click()
    yield h.until(lambda: not FreeCADGui.Control.activeDialog(), 30, "OK to run and close")
    curves = doc.getObject("SingularCurves")
    h.check(curves is not None and runs(log) == 1, "OK without Apply ran once and closed")
    h.check(curves.Size.Value == 0, "automatic size stored as 0: %s" % curves.Size)

    curves.ViewObject.Proxy.doubleClicked(curves.ViewObject)
    yield 0.3
    panel = AnalyzePanel.active
    h.check(panel is not None and panel.form.auto.isChecked(), "double click opens the panel")
    panel.form.auto.setChecked(False)
    panel.form.size.setValue(0.25)
    h.button(Apply).click()
    yield h.until(lambda: not panel.runner.is_running(), 30, "the rerun")
    h.check(curves.Size.Value == 0.25 and curves.MeshSize == 0.25, "Apply updated the size")
    h.check(len(doc.findObjects("Part::FeaturePython")) == 3, "updated in place, not added")
    h.button(Ok).click()
    yield h.until(lambda: not FreeCADGui.Control.activeDialog(), 10, "OK to close")

    part.Length = 12
    doc.recompute()
    h.check(runs(log) == 3 and curves.isValid(), "editing the part reruns on recompute")

    path = os.path.join(tempfile.mkdtemp(), "objects.FCStd")
    doc.saveAs(path)
    FreeCAD.closeDocument(doc.Name)
    yield 0.3
    doc = FreeCAD.openDocument(path)
    yield 0.5
    curves, part = doc.getObject("SingularCurves"), doc.getObject("Box")
    vp = curves.ViewObject.Proxy
    h.check(type(vp).__name__ == "ViewProviderSingularCurves", "view provider restored: %r" % vp)
    h.check(len(curves.ViewObject.LineColorArray) == len(curves.Shape.Edges),
            "edge colours restored")
    h.check(doc.getObject("FeatureCurves").ViewObject.Visibility is False,
            "feature curves hidden by default")
    doc.removeObject("SingularNodes")
    doc.removeObject("FeatureCurves")
    FreeCADGui.Selection.clearSelection()
    FreeCADGui.Selection.addSelection(curves)
    FreeCADGui.runCommand("Std_Delete")
    yield 0.5
    h.check(doc.getObject("SingularCurves") is None, "curves deleted")
    h.check(part.ViewObject.Transparency == transparency,
            "deleting the curves restores the part's transparency")
    os.unlink(log)

    # The Correct panel lists the backend's methods (canned `info`), unavailable ones greyed.
    doc = FreeCAD.newDocument("Methods")
    part = doc.addObject("Part::Box", "Box")
    doc.recompute()
    FreeCADGui.Selection.addSelection(part)
    FreeCADGui.runCommand("FrameFix_Correct")
    yield 0.3
    box = AnalyzePanel.active.form.method
    items = [(box.itemData(i), box.model().item(i).isEnabled(),
              box.itemData(i, QtCore.Qt.ToolTipRole)) for i in range(box.count())]
    h.check([(n, e) for n, e, _ in items] == [("auto", True), ("snap", True), ("fillet", False),
                                              ("extrude-curves", False), ("extrude-nodes", False)],
            "Correct lists the backend's methods, unavailable ones disabled: %s" % items)
    h.check(all(tip for _, _, tip in items), "each method shows its description")
    h.check(box.currentData() == "auto", "auto chosen")
    FreeCADGui.Control.closeDialog()
    yield 0.3
    # A backend without `info` (an older one): the panel says so, and still opens.
    os.environ["FRAMEFIX_BACKEND"] = os.path.join(FAKES, "reject.sh")
    FreeCADGui.runCommand("FrameFix_Correct")
    yield 0.3
    panel = AnalyzePanel.active
    text = panel.form.summary.text() if panel is not None else ""
    h.check("does not answer `framefix info`" in text, "no info: the panel says so: %s" % text)
    h.check(panel is not None and panel.form.estimate.text() == "", "no info: no estimate")
    FreeCADGui.Control.closeDialog()
    yield 0.3


ffgui_harness.run(scenario)
