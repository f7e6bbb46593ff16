"""FrameFix: frame fields, singular curves and 3-5 curves of CAD solids, for hex meshing.

A thin package over the private extension ``framefix._core``. Arrays are numpy arrays.
Backend errors arrive as :class:`framefix.Error` with the backend's message.
"""
import json as _json

from . import _core
from ._core import (Error, Shape, EdgeFeature, TetMesh, FrameField, SingularityGraph,
                    SingularCurve, SingularNode, Analysis, load_shape, load_brep_string,
                    to_brep_string, classify_features, default_size, tetrahedralize,
                    mesh_quality, solve_frame_field, extract_singularities, mesh_part)

__all__ = ["Error", "Shape", "TetMesh", "FrameField", "SingularityGraph", "Analysis",
           "load_shape", "load_brep_string", "to_brep_string", "classify_features",
           "default_size", "tetrahedralize", "mesh_quality", "solve_frame_field",
           "extract_singularities", "mesh_part", "analyze", "correct", "build_blocks", "report"]


def analyze(part, size=None, size_factor=1.0, threads=0):
    """The whole pipeline on a file path, a :class:`Shape`, or a BREP string.

    Returns an :class:`Analysis`; ``report(result)`` gives report.json's content as a dict.
    """
    size = float(size or 0.0)
    if isinstance(part, Shape):
        return _core.analyze_shape(part, size, size_factor, threads)
    if isinstance(part, str) and part.lstrip().startswith("DBRep_DrawableShape"):
        return _core.analyze_shape(load_brep_string(part), size, size_factor, threads)
    return _core.analyze_file(str(part), size, size_factor, threads)


def correct(part, method="snap", size=None, size_factor=1.0, threads=0):
    """Analyse a CAD file, correct its 3-5 curves with `method` (snap), analyse again.

    Returns a ``Corrected``: ``.result`` is the corrected :class:`Analysis`; ``report(c)`` has the
    ``correction`` section with the before and after summaries.
    """
    return _core.correct_file(str(part), method, float(size or 0.0), size_factor, threads)


def build_blocks(part, method="snap", size=None, size_factor=1.0, threads=0):
    """Analyse a CAD file, correct it (`method`: snap, or none), cut it into blocks.

    Returns a ``BlockRun``: ``.tet_block`` (block id per tet), ``.count``, ``.valid``,
    ``.result`` the corrected :class:`Analysis`; ``report(b)["blocks"]`` the validation.
    """
    return _core.blocks_file(str(part), method, float(size or 0.0), size_factor, threads)


def report(result):
    """report.json's content (DESIGN.md, version 1) as a dict."""
    return _json.loads(result.report_json)
