"""GUI: the Analyze panel with fake backends that crash, hang, print garbage or reject the
input: FreeCAD stays up, the document is unchanged, the panel says what happened. Then the
canned backend (GUI plumbing only, its curves are made up) creates the objects; undo removes
them. Run by ctest through run_freecad.py --gui."""
import os
import tempfile

import FreeCAD
import FreeCADGui
import Part
from PySide2 import QtWidgets

import ffgui_harness
from ffworkbench_testing import FAKES, alive

Apply, Ok = QtWidgets.QDialogButtonBox.Apply, QtWidgets.QDialogButtonBox.Ok
Cancel = QtWidgets.QDialogButtonBox.Cancel


def scenario(h):
    from framefix_wb.shapes import shape_digest
    from framefix_wb.taskpanels.analyze_panel import AnalyzePanel
    FreeCADGui.activateWorkbench("FrameFixWorkbench")
    os.environ["FRAMEFIX_BACKEND"] = os.path.join(FAKES, "canned.py")  # its `info` sizes the part
    doc = FreeCAD.newDocument("CrashSafety")
    doc.UndoMode = 1
    part = doc.addObject("Part::Feature", "Part")
    part.Shape = Part.makeBox(1, 1, 1).cut(Part.makeCylinder(0.5, 1, FreeCAD.Vector(1, 1, 0.5)))
    doc.recompute()
    FreeCADGui.SendMsgToActiveView("ViewFit")
    names, digest = sorted(o.Name for o in doc.Objects), shape_digest(part.Shape)
    transparency = part.ViewObject.Transparency
    yield 0.5

    FreeCADGui.Selection.clearSelection()
    FreeCADGui.runCommand("FrameFix_Analyze")
    yield 0.3
    panel = AnalyzePanel.active
    h.check(panel is not None and "select one solid" in panel.form.part_label.text(),
            "no selection: the panel asks for one solid")
    FreeCADGui.Control.closeDialog()
    yield 0.2

    FreeCADGui.Selection.addSelection(part)
    FreeCADGui.runCommand("FrameFix_Analyze")
    yield 0.3
    panel = AnalyzePanel.active
    h.check(panel.form.size.value() > 0 and "tets" in panel.form.estimate.text(),
            "default size and estimate shown: %s" % panel.form.estimate.text())
    for fake, expected, timeout in (("segv.sh", "crashed (killed by SIGSEGV)", 60),
                                    ("hang.sh", "did not finish within 3 s", 3),
                                    ("garbage.sh", "not valid JSON", 60),
                                    ("flood.sh", "wrote no report.json", 60),
                                    ("reject.sh", "2 solids; select one solid", 60)):
        os.environ["FRAMEFIX_BACKEND"] = os.path.join(FAKES, fake)
        os.environ["FRAMEFIX_TIMEOUT"] = str(timeout)
        h.button(Apply).click()
        yield h.until(lambda: not panel.runner.is_running(), 70, fake + " to end")
        yield 0.2
        text = panel.form.summary.text()
        h.check(expected in text, "%s: the panel shows %r: %s" % (fake, expected, text))
        h.check(sorted(o.Name for o in doc.Objects) == names, fake + ": document unchanged")
        h.check(shape_digest(part.Shape) == digest, fake + ": part unchanged")
    h.screenshot("crash_safety_error_panel")

    pidfile = tempfile.NamedTemporaryFile(suffix=".pids", delete=False).name
    os.environ.update(FRAMEFIX_BACKEND=os.path.join(FAKES, "hang.sh"), FRAMEFIX_TIMEOUT="60",
                      FAKE_BACKEND_PIDFILE=pidfile)
    h.button(Apply).click()
    yield h.until(lambda: os.path.getsize(pidfile) > 0, 10, "hang.sh to start")
    h.button(Cancel).click()
    yield h.until(lambda: AnalyzePanel.active is None, 10, "Cancel to close the panel")
    yield 0.5
    with open(pidfile) as f:
        pids = [int(p) for p in f.read().split()]
    h.check(pids and not any(alive(p) for p in pids), "Cancel killed the backend: %s" % pids)
    h.check(sorted(o.Name for o in doc.Objects) == names, "Cancel: document unchanged")
    FreeCADGui.Selection.addSelection(part)
    FreeCADGui.runCommand("FrameFix_Analyze")
    yield 0.3
    panel = AnalyzePanel.active

    os.environ["FRAMEFIX_BACKEND"] = os.path.join(FAKES, "canned.py")
    os.environ["FAKE_BACKEND_DELAY"] = "0.1"
    h.button(Apply).click()
    yield 0.3
    h.check(panel.runner.is_running(), "canned: running while the GUI stays responsive")
    h.button(Apply).click()  # refused while running
    yield h.until(lambda: not panel.runner.is_running(), 20, "canned run to end")
    yield 0.3
    h.show_all()
    yield 0.5
    curves = doc.getObject("SingularCurves")
    h.check(curves is not None and curves.isValid(), "canned: analysis objects created")
    h.check(len(doc.Objects) == len(names) + 4, "canned: exactly one analysis (Apply twice)")
    h.check("3-5 curves" in panel.form.summary.text(), "canned: summary in the panel")
    h.check(part.ViewObject.Transparency >= 50, "canned: part made semi-transparent")
    h.check(len(curves.ViewObject.LineColorArray) == len(curves.Shape.Edges),
            "canned: one colour per curve edge")
    h.screenshot("crash_safety_canned_plumbing")
    h.button(Ok).click()
    yield h.until(lambda: AnalyzePanel.active is None, 10, "OK to close the panel")
    doc.undo()
    yield 0.2
    h.check(sorted(o.Name for o in doc.Objects) == names, "undo removes the analysis")
    h.check(part.ViewObject.Transparency == transparency,
            "undo restores the part's transparency: %d" % part.ViewObject.Transparency)

    # The same through FrameFix_Blocks (framefix blocks): failures, cancel, canned blocks.
    FreeCADGui.Selection.addSelection(part)
    FreeCADGui.runCommand("FrameFix_Blocks")
    yield 0.3
    panel = AnalyzePanel.active
    h.check(panel is not None and panel.blocks, "blocks: the Blocks panel is open")
    for fake, expected, timeout in (("segv.sh", "crashed (killed by SIGSEGV)", 60),
                                    ("hang.sh", "did not finish within 3 s", 3),
                                    ("garbage.sh", "not valid JSON", 60),
                                    ("reject.sh", "2 solids; select one solid", 60)):
        os.environ["FRAMEFIX_BACKEND"] = os.path.join(FAKES, fake)
        os.environ["FRAMEFIX_TIMEOUT"] = str(timeout)
        h.button(Apply).click()
        yield h.until(lambda: not panel.runner.is_running(), 70, "blocks: " + fake + " to end")
        yield 0.2
        text = panel.form.summary.text()
        h.check(expected in text, "blocks: %s: the panel shows %r: %s" % (fake, expected, text))
        h.check(sorted(o.Name for o in doc.Objects) == names, "blocks: %s: document unchanged"
                % fake)
        h.check(shape_digest(part.Shape) == digest, "blocks: %s: part unchanged" % fake)
    pidfile = tempfile.NamedTemporaryFile(suffix=".pids", delete=False).name
    os.environ.update(FRAMEFIX_BACKEND=os.path.join(FAKES, "hang.sh"), FRAMEFIX_TIMEOUT="60",
                      FAKE_BACKEND_PIDFILE=pidfile)
    h.button(Apply).click()
    yield h.until(lambda: os.path.getsize(pidfile) > 0, 10, "blocks: hang.sh to start")
    h.button(Cancel).click()
    yield h.until(lambda: AnalyzePanel.active is None, 10, "blocks: Cancel to close the panel")
    yield 0.5
    with open(pidfile) as f:
        pids = [int(p) for p in f.read().split()]
    h.check(pids and not any(alive(p) for p in pids), "blocks: Cancel killed the backend")
    h.check(sorted(o.Name for o in doc.Objects) == names, "blocks: Cancel: document unchanged")
    FreeCADGui.Selection.addSelection(part)
    FreeCADGui.runCommand("FrameFix_Blocks")
    yield 0.3
    panel = AnalyzePanel.active
    os.environ["FRAMEFIX_BACKEND"] = os.path.join(FAKES, "canned.py")
    h.button(Apply).click()
    yield h.until(lambda: not panel.runner.is_running(), 20, "blocks: canned run to end")
    yield 0.3
    blocks = doc.getObject("Blocks")
    h.check(blocks is not None and blocks.isValid() and blocks.Count == 2,
            "blocks: canned: Blocks object created")
    h.check(blocks is not None and blocks.ViewObject.Proxy.coloured == 6,
            "blocks: canned: every tet coloured")
    h.check("2 blocks, 1 valid" in panel.form.summary.text(), "blocks: canned: summary in the panel")
    h.button(Ok).click()
    yield h.until(lambda: AnalyzePanel.active is None, 10, "blocks: OK to close the panel")
    doc.undo()
    yield 0.2
    h.check(sorted(o.Name for o in doc.Objects) == names, "blocks: undo removes the blocks")


ffgui_harness.run(scenario)
