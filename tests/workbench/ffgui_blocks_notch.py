"""GUI with the real backend: select the notch, FrameFix_Blocks, Apply, wait; the Blocks object
holds every tet of the run, coloured by block, as many blocks as the report; the corrected
curves and snapped paths are shown with it; the Hex mesh object holds the report's hexes, each
coloured by quality. Screenshots of the whole window in output/gui_blocks/, copied to
docs/screenshot_blocks.png and docs/screenshot_hexmesh.png when FRAMEFIX_UPDATE_DOCS is set."""
import os
import shutil

import FreeCAD
import FreeCADGui
from PySide2 import QtWidgets

import ffgui_harness
from ffworkbench_testing import notch_document

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(ffgui_harness.__file__))))
DOCS_SHOT = os.path.join(REPO, "docs", "screenshot_blocks.png")
DOCS_HEX_SHOT = os.path.join(REPO, "docs", "screenshot_hexmesh.png")


def scenario(h):
    from framefix_wb import make
    from framefix_wb.objects.hex_mesh import HexMesh
    from framefix_wb.objects.properties import report_of
    from framefix_wb.objects.snapped_paths import SnappedPaths
    from framefix_wb.taskpanels.analyze_panel import AnalyzePanel
    FreeCADGui.activateWorkbench("FrameFixWorkbench")
    doc, part = notch_document()
    h.show_all()
    h.clear_report_view()
    yield 0.5
    FreeCADGui.Selection.addSelection(part)
    FreeCADGui.runCommand("FrameFix_Blocks")
    yield 0.5
    panel = AnalyzePanel.active
    h.check(panel is not None and panel.blocks and panel.form.windowTitle() == "FrameFix Blocks",
            "the Blocks panel is open")
    h.button(QtWidgets.QDialogButtonBox.Apply).click()
    yield 1.0
    h.check(panel.runner.is_running(), "the backend runs while the GUI stays responsive")
    yield h.until(lambda: not panel.runner.is_running(), 600, "the backend to finish")
    # The objects come after the run: building the block surfaces takes a second or two.
    yield h.until(lambda: "blocks" in panel.form.summary.text(), 120, "the results in the panel")
    yield 0.5
    curves = panel.analysis
    blocks = make.blocks_of(curves) if curves is not None else None
    texts = [w.text() for w in panel.form.findChildren(QtWidgets.QLabel) if w.text()] + [
        w.toPlainText() for w in panel.form.findChildren(QtWidgets.QTextEdit)]
    h.check(blocks is not None and blocks.isValid(), "Blocks object exists: %s | %s"
            % (panel.form.summary.text(), " | ".join(texts)[:600]))
    if blocks is None:
        return
    report = report_of(curves)
    count, cut = report["blocks"]["count"], report["blocks"]["cut"]
    h.check(cut == 7 and blocks.Count == count == 9,
            "the notch cuts into 7 blocks after snapping, 9 once its flat block is refined: %d shown "
            "(the report: %d, %d as cut)" % (blocks.Count, count, cut))
    tets = blocks.FemMesh.VolumeCount
    h.check(tets > 0 and len(blocks.BlockIds) == tets == int(report["mesh"]["tets"]),
            "one block id per tet: %d ids, %d volumes, %s tets in the report"
            % (len(blocks.BlockIds), tets, report["mesh"]["tets"]))
    coloured = blocks.ViewObject.Proxy.coloured
    h.check(coloured == tets, "every tet coloured: %d colours" % coloured)
    h.check(blocks.Summary in panel.form.summary.text(), "summary in the panel: " + blocks.Summary)
    h.check(curves.Curves35 == 0, "the corrected curves have no 3-5 curve")
    paths = [o for o in curves.InList if isinstance(getattr(o, "Proxy", None), SnappedPaths)]
    h.check(len(paths) == 1 and len(paths[0].Shape.Edges) > 0, "snapped paths shown")
    hexes = [o for o in curves.InList if isinstance(getattr(o, "Proxy", None), HexMesh)]
    h.check(len(hexes) == 1, "one Hex mesh object")
    if hexes:
        n = report["hexmesh"]["hexes"]
        h.check(hexes[0].FemMesh.HexaCount == n > 0, "the Hex mesh holds the report's %d hexes: %d"
                % (n, hexes[0].FemMesh.HexaCount))
        h.check(hexes[0].ViewObject.Proxy.coloured == n, "every hex coloured by quality")
        h.check("Hex mesh:" in panel.form.summary.text(), "the panel shows the hex mesh")
    h.button(QtWidgets.QDialogButtonBox.Ok).click()
    yield h.until(lambda: AnalyzePanel.active is None, 10, "OK to close the panel")
    FreeCADGui.Selection.clearSelection()
    part.ViewObject.Visibility = False  # the blocks cover the part: its faces would z-fight
    h.expand_tree()
    h.show_all()
    view = FreeCADGui.ActiveDocument.ActiveView  # isometric from the pocket's side
    view.setCameraOrientation(FreeCAD.Rotation(FreeCAD.Vector(0, 0, 1), -90).multiply(
        view.getCameraOrientation()))
    FreeCADGui.SendMsgToActiveView("ViewFit")
    yield 1.0
    shot = h.screenshot("blocks_notch")
    h.check(os.path.getsize(shot) > 10000, "screenshot " + shot)
    if os.environ.get("FRAMEFIX_UPDATE_DOCS"):  # tests never write the sources unless asked
        shutil.copyfile(shot, DOCS_SHOT)
    if hexes:  # the hex mesh alone, with its edges, beside the tree
        shown = [o for o in doc.Objects if o.ViewObject.Visibility]
        for o in shown:
            o.ViewObject.Visibility = False
        hexes[0].ViewObject.Visibility = True
        view.setCameraOrientation(FreeCAD.Rotation(FreeCAD.Vector(0, 0, 1), 180).multiply(
            view.getCameraOrientation()))  # the pocket faces the camera
        FreeCADGui.SendMsgToActiveView("ViewFit")
        yield 1.0
        shot = h.screenshot("hexmesh_notch")
        h.check(os.path.getsize(shot) > 10000, "screenshot " + shot)
        if os.environ.get("FRAMEFIX_UPDATE_DOCS"):
            shutil.copyfile(shot, DOCS_HEX_SHOT)
        for o in shown:
            o.ViewObject.Visibility = True

    # The same part again from the existing analysis: the command takes its part.
    FreeCADGui.Selection.addSelection(curves)
    FreeCADGui.runCommand("FrameFix_Blocks")
    yield 0.5
    panel = AnalyzePanel.active
    h.check(panel is not None and panel.source is part, "Blocks on an analysis uses its part")
    FreeCADGui.Control.closeDialog()
    yield 0.3


ffgui_harness.run(scenario, watchdog_s=800)
