"""One backend run: its temporary folder, command line, progress parsing and outcome.

Both runners (runner.run_sync headless, taskpanels.process_runner.ProcessRunner in the GUI) drive an
AnalysisJob the same way: start `job.argv` with `job.env`, feed every output line to
`job.add_line`, then call `job.finish(exit_code, crashed)` for the checked report.
The user's shape only ever leaves FreeCAD as a BREP file in the job's own temp folder.
"""
import collections
import os
import re
import shutil
import signal
import tempfile

import numpy

from .backend import find_backend
from .errors import BackendError
from .report import load_report
from .vtk import (VTK_HEXAHEDRON, VTK_POLY_LINE, VTK_QUADRATIC_HEXAHEDRON, VTK_TRIANGLE,
                  read_cells, read_tets)

DEFAULT_TIMEOUT_S = 1800.0
# Share of the whole run each backend stage takes, measured roughly on the samples, by
# command (correct and blocks solve the field a second time in their "correct" stage).
STAGE_WEIGHTS = (("load", 0.05), ("mesh", 0.25), ("field", 0.55), ("singularities", 0.15))
COMMAND_STAGE_WEIGHTS = {
    "analyze": STAGE_WEIGHTS,
    "correct": (("load", 0.03), ("mesh", 0.15), ("field", 0.35), ("singularities", 0.07),
                ("correct", 0.40)),
    "blocks": (("load", 0.03), ("mesh", 0.14), ("field", 0.32), ("singularities", 0.06),
               ("correct", 0.34), ("blocks", 0.09), ("hexmesh", 0.02)),
}
MAX_LINE = 4096  # longer output lines are cut: a backend printing binary garbage stays cheap
KEPT_LINES = 500  # the last output lines kept for error messages
_PROGRESS = re.compile(r"^progress\s+(\w+)\s+([0-9.eE+-]+)\s*$")
_ERROR = re.compile(r"^framefix: (?:error \[(\w*)\]|internal error): (.*)$")


def parse_progress(line):
    """(stage, fraction in 0..1) for a `progress <stage> <fraction>` line, else None."""
    m = _PROGRESS.match(line.strip())
    if not m:
        return None
    try:
        fraction = float(m.group(2))
    except ValueError:
        return None
    return m.group(1), min(max(fraction, 0.0), 1.0)


def overall_fraction(stage, fraction, weights=STAGE_WEIGHTS):
    """Fraction of the whole run done when `stage` is `fraction` done."""
    done = 0.0
    for name, weight in weights:
        if name == stage:
            return done + weight * fraction
        done += weight
    return None  # a stage this workbench does not know: keep the bar where it is


def timeout_from_env(default=DEFAULT_TIMEOUT_S):
    try:
        return float(os.environ.get("FRAMEFIX_TIMEOUT", default))
    except ValueError:
        return default


BLOCKS_VTK = "blocks.vtk"  # the tets labelled by block, beside report.json
BLOCK_SURFACES_VTK = "block_surfaces.vtk"  # each block's boundary, smoothed for display
BLOCK_EDGES_VTK = "block_edges.vtk"  # each block's edges, smoothed polylines
HEX_VTK = "hex.vtk"  # the hex mesh of the blocks, when they could be meshed
FILLETED_BREP = "filleted.brep"  # the fillet correction's solid, beside report.json


class AnalysisJob:
    """`framefix analyze <tmp>/shape.brep [--size H] --out <tmp>/out` for one shape, or with
    `method`, `framefix correct ... --method M` (analyze, correct, analyze again), or with
    `blocks`, `framefix hexmesh ... [--method M] [--order 2]` (the blocks and, when they can
    be meshed, their hex mesh: both in report["block_mesh"]). The
    methods are the backend's to check (runs.check_method asks it first). `out_dir`: where
    the backend writes (kept), else a folder in the job's temporary one. `fillet_rims`: the
    fillet correction also fillets the convex rims across a strip from each concave edge."""

    def __init__(self, shape, size=None, backend=None, timeout=None, method=None, blocks=False,
                 out_dir=None, fillet_rims=False, hex_order=1):
        self.backend = backend or find_backend()
        self.timeout = timeout_from_env() if timeout is None else float(timeout)
        self.workdir = tempfile.mkdtemp(prefix="framefix_")
        self.brep_path = os.path.join(self.workdir, "shape.brep")
        self.out_dir = out_dir or os.path.join(self.workdir, "out")
        os.makedirs(self.out_dir, exist_ok=True)
        shape.exportBrep(self.brep_path)
        self.command = command = "blocks" if blocks else "correct" if method else "analyze"
        subcommand = "hexmesh" if blocks else command  # a block run meshes its blocks too
        self.argv = self.backend.argv + [subcommand, self.brep_path, "--out", self.out_dir]
        if blocks and hex_order != 1:
            self.argv += ["--order", str(int(hex_order))]
        if size:
            self.argv += ["--size", repr(float(size))]
        if method:
            self.argv += ["--method", method]
        if fillet_rims:
            self.argv += ["--fillet-rims"]
        self.env = self.backend.environment()
        self.lines = collections.deque(maxlen=KEPT_LINES)  # the last output lines
        self.error_line = None  # (stage, message) of the backend's last `framefix: error` line

    def add_line(self, line):
        """Record one output line; returns (stage, fraction) if it is a progress line."""
        line = line.rstrip("\r\n")[:MAX_LINE]
        self.lines.append(line)
        m = _ERROR.match(line)
        if m:
            self.error_line = (m.group(1) or "", m.group(2))
        return parse_progress(line)

    def overall_fraction(self, stage, fraction):
        """Fraction of this run done when `stage` is `fraction` done (None: unknown stage)."""
        return overall_fraction(stage, fraction, COMMAND_STAGE_WEIGHTS[self.command])

    def _tail(self, n=5):
        tail = [l for l in self.lines if l.strip() and not parse_progress(l)][-n:]
        return ("; last output: " + " | ".join(tail)[:400]) if tail else ""

    def finish(self, exit_code, crashed=False, signal_number=None):
        """The checked report of a finished run, or a BackendError saying why there is none."""
        if crashed or (exit_code is not None and exit_code < 0):
            sig = signal_number or (-exit_code if exit_code and exit_code < 0 else None)
            name = signal.Signals(sig).name if sig in signal.Signals._value2member_map_ else "a signal"
            raise BackendError("the backend crashed (killed by %s)%s; your document is unchanged"
                               % (name, self._tail()), "crash")
        if exit_code != 0:
            stage, message = self.error_line or ("", "no error message")
            what = {2: "rejected the input", 3: "hit an internal error"}.get(
                exit_code, "failed with exit code %s" % exit_code)
            where = " in stage %s" % stage if stage else ""
            raise BackendError("the backend %s%s: %s" % (what, where, message), stage)
        report = load_report(os.path.join(self.out_dir, "report.json"))
        if self.command == "blocks":
            if report["blocks"] is None:
                raise BackendError("the backend's report.json has no blocks section")
            mesh = read_tets(os.path.join(self.out_dir, BLOCKS_VTK), ("block", "block_valid"))
            if len(mesh["tets"]) and (mesh["block"].min() < -1
                                      or mesh["block"].max() >= report["blocks"]["count"]):
                raise BackendError("the backend's %s names blocks its report does not have"
                                   % BLOCKS_VTK)
            count = report["blocks"]["count"]
            mesh["surfaces"] = self._block_cells(BLOCK_SURFACES_VTK, VTK_TRIANGLE, ("block",), count)
            mesh["edges"] = self._block_cells(BLOCK_EDGES_VTK, VTK_POLY_LINE, ("block",), count)
            mesh["hexes"] = self._hexes(report)
            report["block_mesh"] = mesh
        filleted = os.path.join(self.out_dir, FILLETED_BREP)
        if os.path.exists(filleted):
            with open(filleted) as f:
                report["filleted_brep"] = f.read()
        return report

    def _hexes(self, report):
        """The hex mesh as {"points", "cells" ((m, 8 or 20) ints), "block", "scaled_jacobian"},
        or None when the run made none."""
        h = report.get("hexmesh")
        if not h or not h["done"]:
            return None
        cell_type = VTK_QUADRATIC_HEXAHEDRON if h["order"] == 2 else VTK_HEXAHEDRON
        # A block split in three by the flat-edge refinement gives its parts new ids, from the
        # cut blocks' count up to the meshed complex's (one entry each in hexmesh.blocks).
        count = max(report["blocks"]["count"], h["blocks"])
        hexes = self._block_cells(HEX_VTK, cell_type, ("block",), count, ("scaled_jacobian",))
        if len(hexes["cells"]) != h["hexes"]:
            raise BackendError("the backend's %s has %d hexes, its report %d"
                               % (HEX_VTK, len(hexes["cells"]), h["hexes"]))
        hexes["cells"] = numpy.array(hexes["cells"]).reshape(len(hexes["cells"]), -1)
        return hexes

    def _block_cells(self, name, cell_type, arrays, count, floats=()):
        """The cells of a VTK file whose `block` ids must lie in [0, count)."""
        cells = read_cells(os.path.join(self.out_dir, name), cell_type, arrays, floats)
        blocks = cells["block"]
        if len(blocks) and (blocks.min() < 0 or blocks.max() >= count):
            raise BackendError("the backend's %s names blocks its report does not have" % name)
        return cells

    def timeout_error(self):
        return BackendError("the backend did not finish within %.0f s and was stopped%s"
                            % (self.timeout, self._tail()), "timeout")

    def cleanup(self):
        shutil.rmtree(self.workdir, ignore_errors=True)
