"""GUI with the real backend: the paper's half-sphere box (samples/half_sphere_box.step),
FrameFix_Blocks, Apply, wait. Snapping moves its four 3-5 curves onto the dome; the dome is one
block and the box an O-grid of 9 blocks around and below it (docs/algorithms.md#curtain-corners):
10 valid blocks meeting face to face, neighbours in distinct colours, and a hex mesh. A
screenshot of the whole window in output/gui_blocks_dome/, copied to
docs/screenshot_blocks_dome.png when FRAMEFIX_UPDATE_DOCS is set."""
import os
import shutil

import FreeCAD
import FreeCADGui
from PySide2 import QtWidgets

import ffgui_harness
from ffworkbench_testing import sample_document

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(ffgui_harness.__file__))))
DOCS_SHOT = os.path.join(REPO, "docs", "screenshot_blocks_dome.png")


def scenario(h):
    from framefix_wb import make
    from framefix_wb.objects.hex_mesh import HexMesh
    from framefix_wb.objects.properties import report_of
    from framefix_wb.taskpanels.analyze_panel import AnalyzePanel
    FreeCADGui.activateWorkbench("FrameFixWorkbench")
    doc, part = sample_document("half_sphere_box", "Dome", "HalfSphereBox")
    h.show_all()
    yield 0.5
    FreeCADGui.Selection.addSelection(part)
    FreeCADGui.runCommand("FrameFix_Blocks")
    yield 0.5
    panel = AnalyzePanel.active
    h.check(panel is not None and panel.blocks, "the Blocks panel is open")
    h.button(QtWidgets.QDialogButtonBox.Apply).click()
    yield 1.0
    yield h.until(lambda: not panel.runner.is_running(), 600, "the backend to finish")
    yield h.until(lambda: "blocks" in panel.form.summary.text(), 120, "the results in the panel")
    yield 0.5
    curves = panel.analysis
    blocks = make.blocks_of(curves) if curves is not None else None
    h.check(blocks is not None and blocks.isValid(), "Blocks object exists: " + panel.form.summary.text())
    if blocks is None:
        return
    report = report_of(curves)["blocks"]
    cut = report["cut"]  # the blocks as the sheets cut them, before the flat refinement
    h.check(cut == 10 and blocks.Count == report["count"] >= cut,
            "10 blocks as cut, all shown: %d as cut, %d shown (the report: %d)" % (cut, blocks.Count, report["count"]))
    h.check(list(blocks.BlockValid) == [1] * blocks.Count and report["valid"] == report["count"],
            "every block a valid hexahedron: %s" % list(blocks.BlockValid))
    h.check(report["conforming_pairs"] == report["pairs"] > 0,
            "every neighbour pair conforms: %d of %d" % (report["conforming_pairs"], report["pairs"]))
    colours = [tuple(round(c, 3) for c in col[:3]) for col in blocks.BlockColors]
    clashes = [(b["id"], n) for b in report["blocks"] for n in b["neighbours"] if colours[b["id"]] == colours[n]]
    h.check(not clashes, "neighbours in distinct colours (same colour: %s)" % clashes)
    hexes = [o for o in curves.InList if isinstance(getattr(o, "Proxy", None), HexMesh)]
    h.check(len(hexes) == 1 and hexes[0].FemMesh.HexaCount == report_of(curves)["hexmesh"]["hexes"] > 0,
            "the Hex mesh holds the report's hexes")
    h.button(QtWidgets.QDialogButtonBox.Ok).click()
    yield h.until(lambda: AnalyzePanel.active is None, 10, "OK to close the panel")
    FreeCADGui.Selection.clearSelection()
    for o in doc.Objects:  # the blocks alone: the part and the hex mesh would hide them
        o.ViewObject.Visibility = False
    for o in doc.Objects:
        if o.Name.startswith(("BlockSurfaces", "BlockEdges", "SnappedPaths")):
            o.ViewObject.Visibility = True
    h.expand_tree()
    FreeCADGui.ActiveDocument.ActiveView.viewIsometric()
    FreeCADGui.SendMsgToActiveView("ViewFit")
    yield 1.0
    shot = h.screenshot("blocks_dome")
    h.check(os.path.getsize(shot) > 10000, "screenshot " + shot)
    if os.environ.get("FRAMEFIX_UPDATE_DOCS"):  # tests never write the sources unless asked
        shutil.copyfile(shot, DOCS_SHOT)


ffgui_harness.run(scenario, watchdog_s=800)
