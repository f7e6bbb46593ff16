"""AnalyzePanel: target size (with the tet estimate), Apply/OK/Cancel, progress, log, summary.

Apply runs the backend in a QProcess (ProcessRunner) and only then, in one transaction, adds
or updates the analysis objects: a failed, cancelled or hung run leaves the document as it
was. Apply is refused while a run is going; Cancel kills it.
"""
import time

import FreeCAD
import FreeCADGui
from PySide2 import QtCore, QtWidgets

from .. import make, runs, shapes, sizing
from ..errors import BackendError, FrameFixError
from ..job import AnalysisJob
from ..report import run_text
from .analyze_form import AnalyzeForm
from .process_runner import ProcessRunner

RIM_METHODS = ("fillet", "auto")  # the methods that fillet, so the rims switch applies


def _alive(obj):
    """False for None and for a document object deleted since."""
    try:
        return obj is not None and obj.Document is not None
    except (ReferenceError, RuntimeError):
        return False


class AnalyzePanel:
    """Task panel of FrameFix_Analyze; `analysis_obj` is a SingularCurves object to update."""

    active = None  # the open panel, for macros and GUI tests

    def __init__(self, source=None, analysis_obj=None, message="", method=None, blocks=False):
        AnalyzePanel.active = self
        self.source = source
        self.fixed_source = source is not None
        self.analysis = analysis_obj
        self.runner = ProcessRunner()
        self.runner.progress.connect(self._on_progress)
        self.runner.succeeded.connect(self._on_succeeded)
        self.runner.failed.connect(self._on_failed)
        self.job = self.digest = self.size_run = self.method_run = None
        self.rims_run = False
        self.last = None  # (source name, size, method, rims) of the run the document shows
        self.close_on_success = False
        self.closed = False  # the form is gone: slots must not touch widgets
        self.started = 0.0
        if analysis_obj is not None and analysis_obj.Method:
            method = analysis_obj.Method
        if analysis_obj is not None:
            blocks = bool(getattr(analysis_obj, "Blocks", False))
        self.blocks = blocks  # the Blocks panel: `framefix blocks`, method auto by default
        method = method or ("auto" if blocks else None)
        self.info, info_error = self._backend_info()
        self.form = f = AnalyzeForm(self._methods(method), method, blocks)
        if self.info is not None:
            f.show_target(self.info["default_target_tets"])
        f.size.valueChanged.connect(self._update_estimate)
        f.auto.toggled.connect(self._reset_size)
        self.runner.lines.connect(f.queue_output)
        if f.method is not None:
            f.method.currentIndexChanged.connect(self._enable_rims)
            self._enable_rims()
        self._set_source(source)
        if analysis_obj is not None:
            f.auto.setChecked(analysis_obj.Size.Value == 0)
            if analysis_obj.Size.Value > 0:
                f.size.setValue(analysis_obj.Size.Value)
            if f.rims is not None:
                f.rims.setChecked(bool(getattr(analysis_obj, "FilletRims", False)))
            self.last = (analysis_obj.Source.Name,) + self.chosen_run()
        if message or info_error:
            self._show_error("; ".join(m for m in (message, info_error) if m))
        self.ticker = QtCore.QTimer(self.form)  # dies with the form, however it is closed
        self.ticker.timeout.connect(self._tick)
        self.ticker.start(250)
        self.form.destroyed.connect(lambda *_: self._on_form_destroyed())

    def getStandardButtons(self):
        return int(QtWidgets.QDialogButtonBox.Ok | QtWidgets.QDialogButtonBox.Apply
                   | QtWidgets.QDialogButtonBox.Cancel)

    def clicked(self, button):
        if button == QtWidgets.QDialogButtonBox.Apply:
            self.apply()

    @staticmethod
    def _backend_info():
        """(`framefix info`, None) or (None, why there is none): the panel still runs then,
        without a size estimate, the backend checking the method itself."""
        try:
            return runs.backend_info(), None
        except BackendError as e:
            return None, str(e)

    def _methods(self, method):
        """[(name, available, description)] for the method box; [] for Analyze."""
        if not method:
            return []
        if self.info is None:
            return [(method, True, "the backend did not list its methods")]
        described = {m["name"]: m for m in self.info["correction_methods"]}
        if self.blocks:
            return [(name, True, described.get(name, {}).get("description", ""))
                    for name in self.info["block_methods"]]
        return [(m["name"], m["available"], m["description"])
                for m in self.info["correction_methods"]]

    # -- source and size -------------------------------------------------------------------
    def _set_source(self, source):
        self.source = source
        if source is None:
            self.form.show_no_part(shapes.ACCEPTED)
            self.volume = 0.0
            self._update_estimate()
            return
        solid = shapes.solid_of(source)
        self.volume, diagonal = shapes.volume_and_diagonal(solid)
        self.form.show_part(shapes.label_of(source), self.volume, diagonal)
        self._reset_size()

    def _reset_size(self, *_):
        """Automatic: show the size the backend will about choose, and lock it."""
        f = self.form
        f.size.setEnabled(not f.auto.isChecked())
        if self.volume > 0 and f.auto.isChecked() and self.info is not None:
            f.size.setValue(sizing.default_size(self.volume, self.info))
        self._update_estimate()

    def chosen_size(self):
        """The size to run with; None: the backend's default."""
        return None if self.form.auto.isChecked() else self.form.size.value()

    def chosen_method(self):
        """The correction method; "" for an analysis."""
        return self.form.method.currentData() if self.form.method is not None else ""

    def chosen_rims(self):
        """Whether the fillet correction fillets the rims too (only methods that fillet)."""
        return bool(self.form.rims is not None and self.form.rims.isChecked()
                    and self.chosen_method() in RIM_METHODS)

    def chosen_run(self):
        """(size, method, rims): what a run from the panel depends on besides the part."""
        return self.chosen_size(), self.chosen_method(), self.chosen_rims()

    def _enable_rims(self, *_):
        self.form.rims.setEnabled(self.chosen_method() in RIM_METHODS)

    def _update_estimate(self, *_):
        self.form.show_estimate(self.volume, self.info)

    def _follow_selection(self):
        if self.fixed_source or self.runner.is_running():
            return
        try:
            source = shapes.source_from_selection(FreeCADGui.Selection.getSelection())
        except FrameFixError:
            return
        if source is not self.source:
            self._set_source(source)
            self.form.summary.setText("")

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
            self.size_run, self.method_run, self.rims_run = self.chosen_run()
            runs.check_method(self.method_run, self.blocks)
            order = getattr(self.analysis, "HexOrder", 1) if _alive(self.analysis) else 1
            self.digest = runs.input_digest(solid, self.size_run, self.method_run, self.blocks,
                                            self.rims_run, order)
            self.job = AnalysisJob(solid, self.size_run, method=self.method_run or None,
                                   blocks=self.blocks, fillet_rims=self.rims_run, hex_order=order)
        except (FrameFixError, ReferenceError, RuntimeError, OSError) as e:
            self._show_error(str(e))
            return False
        self.fixed_source = True
        self.form.summary.setText("")
        self._log("$ " + " ".join(self.job.argv))
        self.form.bar.setValue(0)
        self.form.stage.setText("Starting")
        self.started = time.monotonic()
        self.runner.start(self.job)
        return True

    def _on_progress(self, stage, fraction):
        if not self.closed:
            self.form.show_progress(stage, fraction)

    def _on_succeeded(self, report):
        self._finish_job()
        try:
            if _alive(self.analysis):
                make.update_analysis(self.analysis, self.size_run, report, self.digest,
                                     self.method_run, self.rims_run)
            else:
                self.analysis = make.make_analysis(self.source, self.size_run, report,
                                                   self.digest, method=self.method_run,
                                                   blocks=self.blocks, fillet_rims=self.rims_run)
        except Exception as e:  # the adapter boundary: whatever went wrong goes to the panel
            self._show_error("could not add the results: %s" % e)
            return
        self.last = (self.source.Name, self.size_run, self.method_run, self.rims_run)
        text = run_text(report)
        FreeCAD.Console.PrintMessage("FrameFix: %s: %s\n" % (self.source.Label, text))
        self._log(text)
        self.form.show_report(report)
        FreeCADGui.Selection.clearSelection()  # the part's highlight would hide the curves
        if self.close_on_success:
            self._close()
            # not from inside the backend's finished() signal: closing deletes this panel
            QtCore.QTimer.singleShot(0, self._close_dialog_if_still_shown)

    def _on_failed(self, message):
        self._finish_job()
        if self.closed:
            return
        self.form.stage.setText("Failed")
        self.close_on_success = False
        self._show_error(message)

    def _finish_job(self):
        if self.job is not None:
            if not self.closed:
                self.form.elapsed.setText("Elapsed %.1f s" % (time.monotonic() - self.started))
            self.job.cleanup()
            self.job = None

    def _show_error(self, message):
        FreeCAD.Console.PrintError("FrameFix: %s\n" % message)
        if not self.closed:
            self.form.show_error(message)

    def _log(self, text):
        if not self.closed:
            self.form.log_line(text)

    def _tick(self):
        self.form.flush_output()
        if self.runner.is_running():
            self.form.elapsed.setText("Elapsed %.1f s" % (time.monotonic() - self.started))
        else:
            self._follow_selection()

    # -- task dialog protocol ----------------------------------------------------------------
    def accept(self):
        """OK: close if the document shows a run with this size, else run and close after."""
        if self.runner.is_running():
            self.close_on_success = True
            return False
        if self.source is not None and self.last == (self.source.Name,) + self.chosen_run():
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
