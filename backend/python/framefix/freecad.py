"""FrameFix on FreeCAD objects, for macros (GUI or freecadcmd)::

    import framefix.freecad as ff
    r = ff.analyze(App.ActiveDocument.Body, size=2.0)
    r.summary["curves_3_5"], r.summary["meshable"], r.curves[0].kind, r.curves[0].points

The backend runs as a child process (the `framefix` CLI) on a BREP export of the solid, in a
temporary folder: a crash of the mesher cannot take FreeCAD down, and the user's shape is
never modified. The CLI is FRAMEFIX_BACKEND if set, else bin/framefix beside this package
(build tree and installed workbench alike), else `/usr/bin/python3 -m framefix`.
Failures raise framefix.Error with the backend's message.
"""
import json
import os
import shutil
import signal
import subprocess
import tempfile

import numpy as np

from . import Error

_PACKAGE_DIR = os.path.dirname(os.path.abspath(__file__))
DEFAULT_TIMEOUT_S = 1800.0


class Curve:
    """A singular curve: kind "valence3" | "valence5" | "3-5"; points: (n, 3) float array."""

    def __init__(self, d):
        self.id, self.kind = int(d["id"]), d["kind"]
        self.length, self.ends = float(d.get("length", 0.0)), list(d.get("ends", []))
        self.points = np.asarray(d["points"], dtype=float).reshape(-1, 3)

    def __repr__(self):
        return "Curve(id=%d, kind=%r, %d points)" % (self.id, self.kind, len(self.points))


class Node:
    """A singular node: position (3,) array; valid False when no hex mesh can realise it."""

    def __init__(self, d):
        self.id, self.position = int(d["id"]), np.asarray(d["position"], dtype=float)
        self.boundary, self.valid = bool(d.get("boundary")), bool(d.get("valid", True))
        self.n3, self.n5 = int(d.get("n3", 0)), int(d.get("n5", 0))

    def __repr__(self):
        return "Node(id=%d, valid=%s)" % (self.id, self.valid)


class Result:
    """One analysis: `report` is report.json as a dict (DESIGN.md, version 1)."""

    def __init__(self, report, out_dir=None):
        self.report = report
        sing = report["singularities"]
        self.summary = dict(sing["summary"])
        self.curves = [Curve(c) for c in sing.get("curves", [])]
        self.nodes = [Node(n) for n in sing.get("nodes", [])]
        self.feature_curves = report.get("feature_curves", [])
        self.mesh = report.get("mesh", {})
        self.out_dir = out_dir  # the VTK files and report.json, when analyze(out=...) kept them

    @property
    def meshable(self):
        return bool(self.summary.get("meshable"))

    def __repr__(self):
        return "Result(%d curves, %d 3-5 curves, meshable=%s)" % (
            self.summary.get("curves", 0), self.summary.get("curves_3_5", 0), self.meshable)


def solid_of(obj_or_shape):
    """The single solid of a Part.Shape or a document object (Part feature, Body, Link)."""
    import Part
    shape = obj_or_shape if isinstance(obj_or_shape, Part.Shape) else Part.getShape(obj_or_shape)
    solids = [] if shape.isNull() else shape.Solids
    if len(solids) != 1:
        raise Error("freecad: %s has %d solids; pass exactly one solid"
                    % (getattr(obj_or_shape, "Label", "the shape"), len(solids)))
    return solids[0].copy()  # a copy without the display mesh, so the BREP is the geometry only


def backend_command():
    """The argv prefix of the CLI to run and the environment it needs."""
    env = dict(os.environ)
    exe = os.environ.get("FRAMEFIX_BACKEND") or os.path.join(
        os.path.dirname(os.path.dirname(_PACKAGE_DIR)), "bin", "framefix")
    if os.path.isfile(exe) and os.access(exe, os.X_OK):
        return [exe], env
    env["PYTHONPATH"] = os.pathsep.join(
        p for p in (os.path.dirname(_PACKAGE_DIR), env.get("PYTHONPATH")) if p)
    return ["/usr/bin/python3", "-m", "framefix"], env


def _run(argv, env, timeout, progress):
    proc = subprocess.Popen(argv, env=env, stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                            stderr=subprocess.PIPE, start_new_session=True)
    try:
        lines = _read_stderr(proc, timeout, progress)
    finally:
        try:
            os.killpg(proc.pid, signal.SIGKILL)  # what the backend may have left running
        except (ProcessLookupError, PermissionError):
            pass
        proc.wait()
    return proc.returncode, lines


def _read_stderr(proc, timeout, progress):
    import threading
    lines = []

    def read():
        for raw in proc.stderr:
            line = raw.decode("utf-8", "replace").rstrip()
            lines.append(line)
            parts = line.split()
            if progress and len(parts) == 3 and parts[0] == "progress":
                try:
                    progress(parts[1], float(parts[2]))
                except ValueError:
                    pass

    reader = threading.Thread(target=read, daemon=True)
    reader.start()
    try:
        proc.wait(timeout=timeout)
    except subprocess.TimeoutExpired:
        raise Error("freecad: the backend did not finish within %.0f s" % timeout) from None
    reader.join(5.0)
    return lines


def analyze(obj_or_shape, size=None, out=None, timeout=DEFAULT_TIMEOUT_S, progress=None):
    """Analyse one solid; returns a Result. `size`: target tet edge length (model units),
    None for about 50k tets. `out`: a folder to keep the report and VTK files in.
    `progress(stage, fraction)` is called for each progress line of the backend."""
    solid = solid_of(obj_or_shape)
    workdir = tempfile.mkdtemp(prefix="framefix_")
    try:
        brep = os.path.join(workdir, "shape.brep")
        solid.exportBrep(brep)
        out_dir = os.path.abspath(out) if out else os.path.join(workdir, "out")
        os.makedirs(out_dir, exist_ok=True)
        prefix, env = backend_command()
        argv = prefix + ["analyze", brep, "--out", out_dir]
        if size:
            argv += ["--size", repr(float(size))]
        code, lines = _run(argv, env, timeout, progress)
        if code != 0:
            errors = [l for l in lines if l.startswith("framefix:")] or lines[-3:]
            what = ("crashed (%s)" % signal.Signals(-code).name if code < 0
                    else "failed (exit code %d)" % code)
            raise Error("freecad: the backend %s: %s" % (what, " | ".join(errors) or "no message"))
        try:
            with open(os.path.join(out_dir, "report.json"), encoding="utf-8") as f:
                report = json.load(f)
            return Result(report, out_dir if out else None)
        except (OSError, ValueError, KeyError, TypeError) as e:
            raise Error("freecad: the backend's report.json is unusable: %s" % e) from None
    finally:
        shutil.rmtree(workdir, ignore_errors=True)
