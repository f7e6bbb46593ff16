"""Running a job (job.AnalysisJob, info.InfoJob) synchronously in a child process: freecadcmd,
recomputes, framefix.freecad macros; the GUI panel uses taskpanels/process_runner.py instead.

The child gets its own session so a timeout or cancel kills it and anything it started.
`on_progress(stage, fraction)` and `on_idle()` are called from this thread only; the GUI
uses on_idle to keep the window painted while a recompute waits.
"""
import os
import queue
import signal
import subprocess
import threading
import time

from .errors import BackendError
from .job import MAX_LINE


def _kill_group(proc):
    try:
        os.killpg(proc.pid, signal.SIGKILL)
    except (ProcessLookupError, PermissionError):
        pass
    proc.wait()


def _read_lines(stream, lines):
    for raw in iter(lambda: stream.readline(MAX_LINE), b""):
        lines.put(raw.decode("utf-8", "replace"))
    lines.put(None)


def run_sync(job, on_progress=None, on_idle=None, should_cancel=None, poll_s=0.1):
    """The checked report of `job`; raises BackendError on crash, failure, timeout or cancel."""
    try:
        proc = subprocess.Popen(job.argv, env=job.env, stdin=subprocess.DEVNULL,
                                stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                start_new_session=True)
    except OSError as e:
        raise BackendError("could not start the backend %s: %s" % (job.argv[0], e), "start") from None
    lines = queue.Queue()
    reader = threading.Thread(target=_read_lines, args=(proc.stdout, lines), daemon=True)
    reader.start()
    deadline = time.monotonic() + job.timeout
    eof = False
    try:
        while not eof:
            try:
                line = lines.get(timeout=poll_s)
            except queue.Empty:
                line = ""
            if line is None or (line == "" and proc.poll() is not None):
                eof = True  # a grandchild holding the pipe open must not keep us waiting
            elif line:
                progress = job.add_line(line)
                if progress and on_progress:
                    on_progress(*progress)
            if on_idle:
                on_idle()
            if should_cancel and should_cancel():
                _kill_group(proc)
                raise BackendError("cancelled; your document is unchanged", "cancel")
            if time.monotonic() > deadline:
                _kill_group(proc)
                raise job.timeout_error()
        # Output closed or the child exited: reap it, and whatever it left in its session.
        remaining = max(deadline - time.monotonic(), 0.0)
        try:
            code = proc.wait(timeout=remaining)
        except subprocess.TimeoutExpired:
            _kill_group(proc)
            raise job.timeout_error() from None
    finally:
        _kill_group(proc)  # no-op when the whole session is gone
        proc.stdout.close()
    while not lines.empty():
        line = lines.get()
        if line:
            job.add_line(line)
    return job.finish(code)
