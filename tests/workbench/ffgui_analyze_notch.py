"""GUI with the real backend: select the notch, FrameFix_Analyze, Apply, wait; the analysis
objects exist with one 3-5 curve; then FrameFix_Correct (snap) removes it. Screenshots of the
whole window in output/gui_analyze/."""
import FreeCADGui
from PySide2 import QtWidgets

import ffgui_harness
from ffworkbench_testing import notch_document


def scenario(h):
    from framefix_wb.objects.snapped_paths import SnappedPaths
    from framefix_wb.taskpanels.analyze_panel import AnalyzePanel
    FreeCADGui.activateWorkbench("FrameFixWorkbench")
    doc, part = notch_document()
    h.show_all()
    h.clear_report_view()
    yield 0.5
    FreeCADGui.Selection.addSelection(part)
    FreeCADGui.runCommand("FrameFix_Analyze")
    yield 0.5
    panel = AnalyzePanel.active
    h.button(QtWidgets.QDialogButtonBox.Apply).click()
    yield 1.0
    h.screenshot("analyze_notch_running")
    yield h.until(lambda: not panel.runner.is_running(), 600, "the backend to finish")
    yield 0.5
    curves = doc.getObject("SingularCurves")
    h.check(curves is not None and curves.isValid(), "analysis objects exist: %s"
            % panel.form.summary.text())
    if curves is None:
        return
    for name in ("SingularNodes", "FeatureCurves"):
        h.check(doc.getObject(name) is not None and doc.getObject(name).isValid(), name + " ok")
    h.check(curves.Curves35 == 1, "the notch has exactly one 3-5 curve: %d" % curves.Curves35)
    h.show_all()
    yield 1.0
    h.screenshot("analyze_notch")
    h.button(QtWidgets.QDialogButtonBox.Ok).click()
    yield h.until(lambda: AnalyzePanel.active is None, 10, "OK to close the panel")
    FreeCADGui.Selection.clearSelection()
    h.expand_tree()
    yield 0.5
    h.screenshot("analyze_notch_closed")

    FreeCADGui.Selection.addSelection(part)
    FreeCADGui.runCommand("FrameFix_Correct")
    yield 0.5
    panel = AnalyzePanel.active
    f, chosen = panel.form, panel.form.method.currentIndex()
    f.rims.setChecked(True)
    for method, applies in (("snap", False), ("fillet", True), ("auto", True)):
        f.method.setCurrentIndex(f.method.findData(method))
        h.check(f.rims.isEnabled() == applies and panel.chosen_rims() == applies,
                "the rims switch applies to %s: %s" % (method, applies))
    f.rims.setChecked(False)
    f.method.setCurrentIndex(chosen)
    h.button(QtWidgets.QDialogButtonBox.Apply).click()
    yield 1.0
    yield h.until(lambda: not panel.runner.is_running(), 600, "the correction to finish")
    yield 0.5
    corrected = panel.analysis
    h.check(corrected is not None and corrected.isValid() and corrected is not curves,
            "correction objects exist: %s" % panel.form.summary.text())
    if corrected is None:
        return
    h.check(corrected.Before35 == 1 and corrected.Curves35 == 0,
            "snapping removes the notch's 3-5 curve: %d before, %d after"
            % (corrected.Before35, corrected.Curves35))
    paths = [o for o in corrected.InList if isinstance(getattr(o, "Proxy", None), SnappedPaths)]
    h.check(len(paths) == 1 and len(paths[0].Shape.Edges) > 0,
            "the snapped path is shown on the boundary")
    curves.getParentGroup().ViewObject.Visibility = False
    h.expand_tree()
    yield 0.5
    h.screenshot("correct_notch")


ffgui_harness.run(scenario, watchdog_s=800)
