"""ProcessRunner: an AnalysisJob in a QProcess, so FreeCAD's GUI thread never waits for it.

The child is started through setsid(1), which makes it the leader of its own process group
(it execs in place: same pid), so cancel and timeout kill it and everything it started
without touching FreeCAD's own group. A crash, a non-zero exit or a bad report ends in
`failed(message)`; only a checked report reaches `succeeded(report)`.

Finished QProcess objects stay children of the runner until it goes (one per run). Whoever
handles `succeeded`/`failed` must not delete the runner from inside the slot (they are
emitted from the QProcess' finished()): FreeCAD segfaults; defer it with a timer.
"""
import os
import signal

from PySide2 import QtCore

from ..errors import BackendError
from ..job import MAX_LINE

SETSID = "/usr/bin/setsid"


class ProcessRunner(QtCore.QObject):
    progress = QtCore.Signal(str, float)  # stage, overall fraction 0..1
    lines = QtCore.Signal(str)  # the backend's new output lines, one batch per read
    succeeded = QtCore.Signal(object)  # the checked report (dict)
    failed = QtCore.Signal(str)  # a message for the user

    def __init__(self, parent=None):
        super().__init__(parent)
        self.job = None
        self.process = None
        self._buffer = b""
        self._timer = QtCore.QTimer(self)
        self._timer.setSingleShot(True)
        self._timer.timeout.connect(self._on_timeout)

    def is_running(self):
        return self.process is not None

    def start(self, job):
        assert self.process is None, "one run at a time"
        self.job, self._buffer = job, b""
        self.process = p = QtCore.QProcess(self)
        p.setProcessChannelMode(QtCore.QProcess.MergedChannels)
        env = QtCore.QProcessEnvironment()
        for key, value in job.env.items():
            env.insert(key, value)
        p.setProcessEnvironment(env)
        # Each slot checks it is still about this process: a stopped one is ignored.
        p.readyReadStandardOutput.connect(lambda: self._on_output(p))
        p.finished.connect(lambda code, status: self._on_finished(p, code, status))
        p.errorOccurred.connect(lambda error: self._on_error(p, error))
        if os.access(SETSID, os.X_OK):
            p.start(SETSID, job.argv)
        else:
            p.start(job.argv[0], job.argv[1:])
        self._timer.start(int(job.timeout * 1000))

    def cancel(self):
        """Kill a running backend; emits failed('cancelled ...')."""
        if self.process is not None:
            self._stop(BackendError("cancelled; your document is unchanged", "cancel"))

    # -- internals ---------------------------------------------------------------------------
    @staticmethod
    def _kill(p):
        pid = int(p.processId()) if p.state() != QtCore.QProcess.NotRunning else 0
        if pid > 0 and os.getpgid(pid) == pid and pid != os.getpgrp():
            try:
                os.killpg(pid, signal.SIGKILL)
            except ProcessLookupError:
                pass
        p.kill()
        p.waitForFinished(2000)

    def _stop(self, error):
        """End the run with `error`, whatever the process still does."""
        p = self.process
        self._drain()
        self.process = None  # from here on, the process' own signals are ignored
        self._timer.stop()
        self._kill(p)
        self.failed.emit(str(error))

    def _drain(self):
        if self.process is None:
            return
        self._buffer += bytes(self.process.readAllStandardOutput())
        *lines, self._buffer = self._buffer.split(b"\n")
        if len(self._buffer) > MAX_LINE:  # no newline in sight: cut it into a line
            lines.append(self._buffer[:MAX_LINE])
            self._buffer = b""
        if not lines:
            return
        texts = [raw.decode("utf-8", "replace") for raw in lines]
        last = None  # a flood of progress lines moves the bar once per read
        for text in texts:
            last = self.job.add_line(text) or last
        # a flood shows its end, long lines their start: the log must stay cheap to lay out
        self.lines.emit("\n".join(t[:300] for t in texts[-200:]))
        fraction = self.job.overall_fraction(*last) if last else None
        if fraction is not None:
            self.progress.emit(last[0], fraction)

    def _on_output(self, p):
        if p is self.process:
            self._drain()

    def _on_timeout(self):
        if self.process is not None:
            self._stop(self.job.timeout_error())

    def _on_error(self, p, error):
        if p is self.process and error == QtCore.QProcess.FailedToStart:
            self._stop(BackendError("could not start the backend %s: %s"
                                    % (self.job.argv[0], self.process.errorString()), "start"))

    def _on_finished(self, p, exit_code, exit_status):
        if p is not self.process:
            return
        self._drain()
        if self._buffer:
            self._buffer += b"\n"
            self._drain()
        self.process = None
        self._timer.stop()
        crashed = exit_status == QtCore.QProcess.CrashExit
        try:
            report = self.job.finish(exit_code, crashed=crashed,
                                     signal_number=exit_code if crashed else None)
        except BackendError as e:
            self.failed.emit(str(e))
            return
        except Exception as e:  # a slot must not raise: Qt would drop it and the panel would wait
            self.failed.emit("could not read the backend's results: %s: %s" % (type(e).__name__, e))
            return
        self.succeeded.emit(report)
