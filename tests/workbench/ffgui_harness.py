"""Scripted FreeCAD GUI sessions: a test is a generator of steps run from Qt's event loop.

    def scenario(h):
        h.run_command("FrameFix_Analyze")
        yield h.until(lambda: ..., timeout=30)   # wait, with the GUI running
        h.check(cond, "what went wrong")
    run(scenario)  # ends FreeCAD with os._exit(0) or os._exit(1)

A step yields a number (seconds to wait) or h.until(...). A failed check, an exception or
the watchdog ends the session with exit code 1 and the reason on stderr.
"""
import os
import sys
import time
import traceback

import FreeCADGui
from PySide2 import QtCore, QtGui, QtWidgets

OUT = os.environ.get("FRAMEFIX_TEST_OUT", "/tmp")
LOG = sys.__stderr__  # the terminal, not FreeCAD's report view (it is in the screenshots)


class Failure(Exception):
    pass


class Until:
    def __init__(self, condition, timeout, what):
        self.condition, self.deadline, self.what = condition, time.monotonic() + timeout, what


class Harness:
    def __init__(self):
        self.failures = []
        self.start = time.monotonic()

    def check(self, condition, message):
        if not condition:
            self.failures.append(message)
            print("FAIL: " + message, file=LOG)
        else:
            print("ok (%.1f s): %s" % (time.monotonic() - self.start, message.split(":")[0]),
                  file=LOG)

    def until(self, condition, timeout=30.0, what="condition"):
        return Until(condition, timeout, what)

    def main_window(self):
        return FreeCADGui.getMainWindow()

    def button(self, which):
        """The task panel's standard button `which` (QDialogButtonBox.Ok, Apply, Cancel)."""
        for box in self.main_window().findChildren(QtWidgets.QDialogButtonBox):
            b = box.button(which)
            if b is not None and b.isVisible():
                return b
        raise Failure("no visible task panel button %s" % which)

    def show_all(self, width=430):
        """Isometric view fitted to the document, the combo view wide enough for the panel."""
        view = FreeCADGui.ActiveDocument.ActiveView
        view.viewIsometric()
        view.fitAll()
        mw = self.main_window()
        for dock in mw.findChildren(QtWidgets.QDockWidget):
            if dock.objectName() == "Combo View":
                mw.resizeDocks([dock], [width], QtCore.Qt.Horizontal)

    def clear_report_view(self):
        """Start the report view afresh (FreeCAD's start-up warnings are not ours)."""
        for dock in self.main_window().findChildren(QtWidgets.QDockWidget):
            if dock.objectName() == "Report view":
                for text in dock.findChildren(QtWidgets.QTextEdit):
                    text.clear()

    def expand_tree(self):
        for tree in self.main_window().findChildren(QtWidgets.QTreeWidget):
            tree.expandAll()

    def screenshot(self, name):
        """The whole main window (the 3D view included) as OUT/<name>.png; returns the path."""
        path = os.path.join(OUT, name + ".png")
        mw = self.main_window()
        QtWidgets.QApplication.processEvents()
        QtGui.QGuiApplication.primaryScreen().grabWindow(mw.winId()).save(path)
        print("screenshot: " + path, file=LOG)
        return path


def run(scenario, watchdog_s=300.0):
    """Run scenario(harness) (a generator) from the event loop, then exit FreeCAD."""
    h = Harness()
    steps = scenario(h)
    start = time.monotonic()

    def finish(code):
        LOG.flush()
        sys.stdout.flush()
        os._exit(code)

    def step(waiting=None):
        try:
            if time.monotonic() - start > watchdog_s:
                raise Failure("watchdog: scenario took over %.0f s" % watchdog_s)
            if waiting is not None:
                if not waiting.condition():
                    if time.monotonic() > waiting.deadline:
                        raise Failure("timed out waiting for " + waiting.what)
                    QtCore.QTimer.singleShot(100, lambda: step(waiting))
                    return
            nxt = next(steps)
        except StopIteration:
            for f in h.failures:
                print("FAILED: " + f, file=LOG)
            print("GUI scenario: %d failure(s)" % len(h.failures), file=LOG)
            finish(1 if h.failures else 0)
            return
        except Exception:
            traceback.print_exc(file=LOG)
            finish(1)
            return
        if isinstance(nxt, Until):
            QtCore.QTimer.singleShot(100, lambda: step(nxt))
        else:
            QtCore.QTimer.singleShot(int(1000 * (nxt or 0)), step)

    mw = FreeCADGui.getMainWindow()
    mw.showNormal()
    mw.setGeometry(0, 0, 1600, 1000)
    QtCore.QTimer.singleShot(500, step)
