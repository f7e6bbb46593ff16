"""FrameFix: frame fields, singular curves and 3-5 curves of CAD solids, for hex meshing.

A thin package over the private extension ``framefix._core``. Arrays are numpy arrays.
Backend errors arrive as :class:`framefix.Error` with the backend's message.
"""
import json as _json

from . import _core
from ._core import (Error, Shape, EdgeFeature, TetMesh, FrameField, SingularityGraph,
                    SingularCurve, SingularNode, Analysis, Correction, Blocks, load_shape,
                    load_brep_string, to_brep_string, classify_features, default_size,
                    tetrahedralize, mesh_quality, solve_frame_field, extract_singularities)

__all__ = ["Error", "Shape", "TetMesh", "FrameField", "SingularityGraph", "Analysis",
           "Correction", "Blocks", "load_shape", "load_brep_string", "to_brep_string",
           "classify_features", "default_size", "tetrahedralize", "mesh_quality",
           "solve_frame_field", "extract_singularities", "run", "mesh_part", "analyze",
           "correct", "build_blocks", "info", "correction_methods", "report"]


def run(part, stop_after="singularities", method="auto", size=None, size_factor=1.0, threads=0,
        budget_s=0.0, fillet_rims=False):
    """The pipeline on a file path, a :class:`Shape`, or a BREP string, up to `stop_after`
    (load, mesh, field, singularities, correct, blocks); `method` is the correction (see
    :func:`correction_methods`), or "none"; `budget_s` is method auto's time budget (0: 120 s
    per 50k tets); `fillet_rims` makes method fillet fillet the rims across the wall from each
    concave edge too (a groove turns smooth). Returns an :class:`Analysis` whose stages past
    `stop_after` are None; ``report(result)`` gives report.json's content as a dict.
    """
    size = float(size or 0.0)
    if isinstance(part, str) and part.lstrip().startswith("DBRep_DrawableShape"):
        part = load_brep_string(part)
    if isinstance(part, Shape):
        return _core.run_shape(part, stop_after, method, size, size_factor, threads, budget_s, fillet_rims)
    return _core.run_file(str(part), stop_after, method, size, size_factor, threads, budget_s, fillet_rims)


def mesh_part(part, size=None, size_factor=1.0, threads=0):
    """Load, classify feature curves, tet mesh. Returns an :class:`Analysis` (field None)."""
    return run(part, "mesh", size=size, size_factor=size_factor, threads=threads)


def analyze(part, size=None, size_factor=1.0, threads=0):
    """Mesh, frame field and singularity graph of a part (path, :class:`Shape` or BREP string)."""
    return run(part, "singularities", size=size, size_factor=size_factor, threads=threads)


def correct(part, method="auto", size=None, size_factor=1.0, threads=0, budget_s=0.0, fillet_rims=False):
    """Analyse a part, correct its 3-5 curves with `method`, analyse again.

    The result's field and singularities are the corrected ones; ``.correction`` says what
    changed (``.before``, ``.snapped_paths``, ``.rotated_fraction``; for auto ``.chosen`` and
    ``.tries``).
    """
    return run(part, "correct", method, size, size_factor, threads, budget_s, fillet_rims)


def build_blocks(part, method="auto", size=None, size_factor=1.0, threads=0, budget_s=0.0, fillet_rims=False):
    """Analyse a part, correct it (`method`, or "none"), cut it into blocks.

    ``.blocks`` has ``.tet_block`` (block id per tet), ``.count``, ``.valid``;
    ``report(result)["blocks"]`` the validation.
    """
    return run(part, "blocks", method, size, size_factor, threads, budget_s, fillet_rims)


def info():
    """`framefix info` as a dict: default_target_tets, mean_tet_volume_h3, correction_methods
    (name, available, description), block_methods."""
    return _json.loads(_core.info_json())


def correction_methods():
    """The correction methods, in the order users see them: dicts of name, available, description."""
    return info()["correction_methods"]


def report(result):
    """report.json's content (docs/design.md, version 1) as a dict."""
    return _json.loads(result.report_json)
