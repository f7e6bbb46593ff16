"""AnalyzePanel: target size (with the tet estimate), Apply/OK/Cancel, progress, log, summary.

Apply runs the backend in a QProcess (ProcessRunner) and only then, in one transaction, adds
or updates the analysis objects: a failed, cancelled or hung run leaves the document as it
was. Apply is refused while a run is going; Cancel kills it.
"""
import collections
import html
import time

import FreeCAD
import FreeCADGui
from PySide2 import QtCore, QtGui, QtWidgets

from .. import analysis, paths, shapes, sizing, style
from ..errors import FrameFixError
from ..job import AnalysisJob
from ..report import curve_breakdown, summary_text
from .process_runner import ProcessRunner


def _alive(obj):
    """False for None and for a document object deleted since."""
    try:
        return obj is not None and obj.Document is not None
    except (ReferenceError, RuntimeError):
        return False


def _error_html(text):
    return '<span style="color:#c00000"><b>Error:</b> %s</span>' % html.escape(text)


class AnalyzePanel:
    """Task panel of FrameFix_Analyze; `analysis_obj` is a SingularCurves object to update."""

    active = None  # the open panel, for macros and GUI tests

    def __init__(self, source=None, analysis_obj=None, message=""):
        AnalyzePanel.active = self
        self.source = source
        self.fixed_source = source is not None
        self.analysis = analysis_obj
        self.runner = ProcessRunner()
        self.runner.progress.connect(self._on_progress)
        self.runner.lines.connect(self._queue_output)
        self.pending = collections.deque(maxlen=300)  # backend output not yet in the log
        self.runner.succeeded.connect(self._on_succeeded)
        self.runner.failed.connect(self._on_failed)
        self.job = self.digest = self.size_run = None
        self.last = None  # (source name, size) of the run the document shows
        self.close_on_success = False
        self.closed = False  # the form is gone: slots must not touch widgets
        self.started = 0.0
        self._build()
        self._set_source(source)
        if analysis_obj is not None:
            self.auto.setChecked(analysis_obj.Size.Value == 0)
            if analysis_obj.Size.Value > 0:
                self.size.setValue(analysis_obj.Size.Value)
            self.last = (analysis_obj.Source.Name, self.chosen_size())
        if message:
            self._show_error(message)
        self.ticker = QtCore.QTimer(self.form)  # dies with the form, however it is closed
        self.ticker.timeout.connect(self._tick)
        self.ticker.start(250)
        self.form.destroyed.connect(lambda *_: self._on_form_destroyed())

    # -- widgets ---------------------------------------------------------------------------
    def _build(self):
        self.form = w = QtWidgets.QWidget()
        w.setWindowTitle("FrameFix Analyze")
        w.setWindowIcon(QtGui.QIcon(paths.icon("FrameFix_Analyze")))
        layout = QtWidgets.QVBoxLayout(w)
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
        self.size.valueChanged.connect(self._update_estimate)
        grid.addWidget(self.size, 0, 1)
        self.auto = QtWidgets.QCheckBox("Automatic")
        self.auto.setToolTip("Let the backend choose the size: about %d tets" % sizing.TARGET_TETS)
        self.auto.setChecked(True)
        self.auto.toggled.connect(self._reset_size)
        grid.addWidget(self.auto, 0, 2)
        self.estimate = QtWidgets.QLabel()
        grid.addWidget(self.estimate, 1, 1, 1, 2)
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

    def getStandardButtons(self):
        return int(QtWidgets.QDialogButtonBox.Ok | QtWidgets.QDialogButtonBox.Apply
                   | QtWidgets.QDialogButtonBox.Cancel)

    def clicked(self, button):
        if button == QtWidgets.QDialogButtonBox.Apply:
            self.apply()

    # -- source and size -------------------------------------------------------------------
    def _set_source(self, source):
        self.source = source
        if source is None:
            self.part_label.setText("Part: <i>select one solid (%s)</i>" % shapes.ACCEPTED)
            self.volume = 0.0
            self._update_estimate()
            return
        solid = shapes.solid_of(source)
        self.volume, diagonal = shapes.volume_and_diagonal(solid)
        self.part_label.setText("Part: <b>%s</b> &mdash; volume %.4g, bounding box diagonal %.4g"
                                % (shapes.label_of(source), self.volume, diagonal))
        self._reset_size()

    def _reset_size(self, *_):
        """Automatic: show the size the backend will about choose, and lock it."""
        self.size.setEnabled(not self.auto.isChecked())
        if self.volume > 0 and self.auto.isChecked():
            self.size.setValue(sizing.default_size(self.volume))
        self._update_estimate()

    def chosen_size(self):
        """The size to run with; None: the backend's default."""
        return None if self.auto.isChecked() else self.size.value()

    def _update_estimate(self, *_):
        if self.volume <= 0:
            self.estimate.setText("")
            return
        tets = sizing.estimate_tets(self.volume, self.size.value())
        warn = " <b>(large: may take minutes)</b>" if tets > 2e6 else ""
        self.estimate.setText("\u2248 {:,.0f} tets (estimate){}".format(
            float("%.2g" % tets), warn))

    def _follow_selection(self):
        if self.fixed_source or self.runner.is_running():
            return
        try:
            source = shapes.source_from_selection(FreeCADGui.Selection.getSelection())
        except FrameFixError:
            return
        if source is not self.source:
            self._set_source(source)
            self.summary.setText("")

    # -- running ---------------------------------------------------------------------------
    def apply(self):
        """Start a run (refused while one is going). Returns False if it could not start."""
        if self.runner.is_running():
            self._log("FrameFix: a run is in progress; wait for it or press Cancel")
            return False
        try:
            if self.source is None:
                self._set_source(shapes.source_from_selection(FreeCADGui.Selection.getSelection()))
            solid = shapes.solid_of(self.source)
            self.size_run = self.chosen_size()
            self.digest = analysis.input_digest(solid, self.size_run)
            self.job = AnalysisJob(solid, self.size_run)
        except (FrameFixError, ReferenceError, RuntimeError, OSError) as e:
            self._show_error(str(e))
            return False
        self.fixed_source = True
        self.summary.setText("")
        self._log("$ " + " ".join(self.job.argv))
        self.bar.setValue(0)
        self.stage.setText("Starting")
        self.started = time.monotonic()
        self.runner.start(self.job)
        return True

    def _on_progress(self, stage, fraction):
        if self.closed:
            return
        self.bar.setValue(max(self.bar.value(), int(1000 * fraction)))  # never backwards
        self.stage.setText("Stage: %s" % stage)

    def _on_succeeded(self, report):
        self._finish_job()
        try:
            if _alive(self.analysis):
                analysis.update_analysis(self.analysis, self.size_run, report, self.digest)
            else:
                self.analysis = analysis.make_analysis(self.source, self.size_run, report,
                                                       self.digest)
        except Exception as e:  # the adapter boundary: whatever went wrong goes to the panel
            self._show_error("could not add the results: %s" % e)
            return
        self.last = (self.source.Name, self.size_run)
        self.bar.setValue(1000)
        self.stage.setText("Done")
        text = summary_text(report["summary"], report["mesh"])
        FreeCAD.Console.PrintMessage("FrameFix: %s: %s\n" % (self.source.Label, text))
        self._log(text)
        self._show_summary(report)
        self.estimate.setText("{:,} tets, size {:.4g} (this run)".format(
            int(report["mesh"].get("tets", 0)), float(report["mesh"].get("size", 0))))
        FreeCADGui.Selection.clearSelection()  # the part's highlight would hide the curves
        if self.close_on_success:
            self._close()
            # not from inside the backend's finished() signal: closing deletes this panel
            QtCore.QTimer.singleShot(0, self._close_dialog_if_still_shown)

    def _on_failed(self, message):
        self._finish_job()
        if self.closed:
            return
        self.stage.setText("Failed")
        self.close_on_success = False
        self._show_error(message)

    def _finish_job(self):
        if self.job is not None:
            if not self.closed:
                self.elapsed.setText("Elapsed %.1f s" % (time.monotonic() - self.started))
            self.job.cleanup()
            self.job = None

    def _show_error(self, message):
        FreeCAD.Console.PrintError("FrameFix: %s\n" % message)
        self._log("Error: " + message)
        self.summary.setText(_error_html(message))

    def _show_summary(self, report):
        s = report["summary"]
        verdict = ('<b style="color:#008000">hex-meshable</b>' if s["meshable"] else
                   '<b style="color:#c00000">not hex-meshable</b>')
        kinds = {style.CURVE_KIND_CODES.get(c["kind"], style.OTHER_KIND)
                 for c in report["curves"]} | {3, 5, 35}
        self.summary.setText(
            "%s: <b>%d 3-5 curves</b>, %d singular curves in all (%s), %d nodes (%d invalid)"
            "<br>%s<br>%s" % (
                verdict, s["curves_3_5"], s["curves"], curve_breakdown(s), s["nodes"],
                s["invalid_nodes"], style.legend_html(style.CURVE_COLORS, kinds),
                style.legend_html(style.NODE_COLORS)))

    def _queue_output(self, text):
        """Backend output goes to the log from the ticker: a flood costs one layout a tick."""
        self.pending.extend(text.split("\n"))

    def _flush_output(self):
        if self.pending and not self.closed:
            self.log.appendPlainText("\n".join(self.pending))
            self.pending.clear()

    def _log(self, text):
        self._flush_output()
        self.log.appendPlainText(text)

    def _tick(self):
        self._flush_output()
        if self.runner.is_running():
            self.elapsed.setText("Elapsed %.1f s" % (time.monotonic() - self.started))
        else:
            self._follow_selection()

    # -- task dialog protocol ----------------------------------------------------------------
    def accept(self):
        """OK: close if the document shows a run with this size, else run and close after."""
        if self.runner.is_running():
            self.close_on_success = True
            return False
        if self.source is not None and self.last == (self.source.Name, self.chosen_size()):
            self._close()
            return True
        self.close_on_success = self.apply()
        return False

    def reject(self):
        """Cancel: kill a running backend and close; applied results stay (undo removes them)."""
        self.runner.cancel()
        self._close()
        return True

    def _close_dialog_if_still_shown(self):
        try:
            shown = not self.closed and self.form.isVisible()
        except RuntimeError:  # the form is gone already
            shown = False
        if shown:
            FreeCADGui.Control.closeDialog()

    def _on_form_destroyed(self):
        """Closed by closeDialog() or FreeCAD, not by OK/Cancel: stop a run, touch no widget."""
        self.closed = True
        self.runner.cancel()
        if AnalyzePanel.active is self:
            AnalyzePanel.active = None

    def _close(self):
        if not self.closed:
            self.ticker.stop()
        self.close_on_success = False
        if AnalyzePanel.active is self:
            AnalyzePanel.active = None
