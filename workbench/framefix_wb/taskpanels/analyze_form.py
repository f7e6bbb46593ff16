"""AnalyzeForm: the widgets of the Analyze panel and how results and errors look in them.
No control logic: AnalyzePanel decides, this shows."""
import collections
import html

from PySide2 import QtCore, QtGui, QtWidgets

from .. import paths, sizing, style
from ..report import (blocks_text, curve_breakdown, extrusion_lines, fillet_lines, hexmesh_text,
                      tries_lines)


class AnalyzeForm(QtWidgets.QWidget):
    """`methods` given, [(name, available, description)]: a method choice, `method` chosen
    (the Correct and Blocks panels); unavailable ones are listed greyed out."""

    def __init__(self, methods=(), method=None, blocks=False):
        super().__init__()
        name = "Blocks" if blocks else "Correct" if method else "Analyze"
        self.setWindowTitle("FrameFix " + name)
        self.setWindowIcon(QtGui.QIcon(paths.icon("FrameFix_" + name)))
        layout = QtWidgets.QVBoxLayout(self)
        self.part_label = QtWidgets.QLabel()
        self.part_label.setWordWrap(True)
        layout.addWidget(self.part_label)
        grid = QtWidgets.QGridLayout()
        grid.addWidget(QtWidgets.QLabel("Target size"), 0, 0)
        self.size = QtWidgets.QDoubleSpinBox()
        self.size.setDecimals(4)
        self.size.setRange(1e-4, 1e5)
        self.size.setMinimumWidth(80)
        self.size.setToolTip("Target tet edge length, in model units")
        grid.addWidget(self.size, 0, 1)
        self.auto = QtWidgets.QCheckBox("Automatic")
        self.auto.setToolTip("Let the backend choose the size")
        self.auto.setChecked(True)
        grid.addWidget(self.auto, 0, 2)
        self.estimate = QtWidgets.QLabel()
        grid.addWidget(self.estimate, 1, 1, 1, 2)
        self.method = self.rims = None
        if methods:
            grid.addWidget(QtWidgets.QLabel("Method"), 2, 0)
            self.method = self._method_box(methods, method)
            grid.addWidget(self.method, 2, 1, 1, 2)
            self.rims = QtWidgets.QCheckBox("Fillet the rims too")
            self.rims.setToolTip("Method fillet (or auto's fillet try): also fillet the convex "
                                 "rim across a strip from each concave edge, as for a groove")
            grid.addWidget(self.rims, 3, 1, 1, 2)
        layout.addLayout(grid)
        self.bar = QtWidgets.QProgressBar()
        self.bar.setRange(0, 1000)
        self.bar.setValue(0)
        layout.addWidget(self.bar)
        row = QtWidgets.QHBoxLayout()
        self.stage = QtWidgets.QLabel("Idle")
        self.elapsed = QtWidgets.QLabel("")
        row.addWidget(self.stage)
        row.addStretch()
        row.addWidget(self.elapsed)
        layout.addLayout(row)
        self.summary = QtWidgets.QLabel()
        self.summary.setWordWrap(True)
        self.summary.setTextFormat(QtCore.Qt.RichText)
        layout.addWidget(self.summary)
        self.log = QtWidgets.QPlainTextEdit()
        self.log.setReadOnly(True)
        self.log.setMaximumBlockCount(2000)
        self.log.setMinimumHeight(120)
        layout.addWidget(self.log)
        self.pending = collections.deque(maxlen=300)  # backend output not yet in the log

    @staticmethod
    def _method_box(methods, chosen):
        box = QtWidgets.QComboBox()
        tips = []
        for i, (name, available, description) in enumerate(methods):
            box.addItem(name if available else name + " (not yet available)", name)
            box.setItemData(i, description, QtCore.Qt.ToolTipRole)
            box.model().item(i).setEnabled(available)
            tips.append("%s: %s%s" % (name, description or "-", "" if available else
                                      " (not yet available)"))
        box.setCurrentIndex(max(0, box.findData(chosen)))
        box.setToolTip("\n".join(tips))
        return box

    def show_target(self, target_tets):
        self.auto.setToolTip("Let the backend choose the size: about %d tets" % target_tets)

    def show_part(self, label, volume, diagonal):
        self.part_label.setText("Part: <b>%s</b> &mdash; volume %.4g, bounding box diagonal "
                                "%.4g" % (html.escape(label), volume, diagonal))

    def show_no_part(self, accepted):
        self.part_label.setText("Part: <i>select one solid (%s)</i>" % html.escape(accepted))

    def show_estimate(self, volume, info):
        """The tet estimate (`info`: the backend's `framefix info`; None: no estimate)."""
        if volume <= 0 or info is None:
            self.estimate.setText("")
            return
        tets = sizing.estimate_tets(volume, self.size.value(), info)
        warn = " <b>(large: may take minutes)</b>" if tets > 2e6 else ""
        self.estimate.setText("\u2248 {:,.0f} tets (estimate){}".format(
            float("%.2g" % tets), warn))

    def show_progress(self, stage, fraction):
        self.bar.setValue(max(self.bar.value(), int(1000 * fraction)))  # never backwards
        self.stage.setText("Stage: %s" % stage)

    def show_error(self, message):
        self.log_line("Error: " + message)
        self.summary.setText('<span style="color:#c00000"><b>Error:</b> %s</span>'
                             % html.escape(message))

    def show_report(self, report):
        """Summary with the colour legend; the mesh actually made instead of the estimate."""
        s, mesh = report["summary"], report["mesh"]
        verdict = ('<b style="color:#008000">hex-meshable</b>' if s["meshable"] else
                   '<b style="color:#c00000">not hex-meshable</b>')
        kinds = {style.CURVE_KIND_CODES.get(c["kind"], style.OTHER_KIND)
                 for c in report["curves"]} | {3, 5, 35}
        correction = report["correction"]
        before = ("after %s (%d before): " % (correction["method"],
                                             correction["before"]["curves_3_5"])
                  if correction else "")
        blocks = report.get("blocks")
        head = ""
        if blocks is not None:
            good = blocks["valid"] == blocks["count"] and (
                blocks["conforming_pairs"] == blocks["pairs"])
            head = '<b style="color:%s">%s</b><br>%s<br>' % (
                "#008000" if good else "#c00000", html.escape(blocks_text(blocks)),
                style.blocks_legend_html(blocks["blocks"]))
        hexmesh = report.get("hexmesh")
        if hexmesh is not None:
            head += '<b>Hex mesh:</b> %s<br>' % html.escape(hexmesh_text(hexmesh))
        self.summary.setText(head +
            "%s: %s<b>%d 3-5 curves</b>, %d singular curves in all (%s), %d nodes (%d invalid)"
            "<br>%s<br>%s" % (
                verdict, before, s["curves_3_5"], s["curves"], curve_breakdown(s), s["nodes"],
                s["invalid_nodes"], style.legend_html(style.CURVE_COLORS, kinds),
                style.legend_html(dict(style.NODE_COLORS, **_correction_legend(correction)))))
        for title, lines in (("Tries (auto)", tries_lines(correction)),
                             ("Fillets", fillet_lines(correction)),
                             ("Extrusion", extrusion_lines(correction))):
            if lines:
                self.summary.setText(self.summary.text() + "<br><b>%s:</b><br>" % title +
                                     "<br>".join(html.escape(line) for line in lines))
        self.estimate.setText("{:,} tets, size {:.4g} (this run)".format(
            int(mesh.get("tets", 0)), float(mesh.get("size", 0))))
        self.bar.setValue(1000)
        self.stage.setText("Done")

    def queue_output(self, text):
        """Backend output reaches the log on flush_output (a timer): a flood costs one layout
        per tick, not one per read."""
        self.pending.extend(text.split("\n"))

    def flush_output(self):
        if self.pending:
            self.log.appendPlainText("\n".join(self.pending))
            self.pending.clear()

    def log_line(self, text):
        self.flush_output()
        self.log.appendPlainText(text)


def _correction_legend(correction):
    """What a correction adds to the node legend: snapped paths, or an extrusion's streamlines."""
    if not correction:
        return {}
    if correction.get("method", "").startswith("extrude"):
        return {"streamlines": (style.STREAMLINE_COLOR, "streamline")}
    return {"paths": (style.SNAPPED_PATH_COLOR, "snapped path")}
