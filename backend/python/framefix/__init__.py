"""FrameFix: frame fields, singular curves and 3-5 curves of CAD solids, for hex meshing.

A thin package over the private extension ``framefix._core``. Arrays are numpy arrays.
Backend errors arrive as :class:`framefix.Error` with the backend's message.
"""
import json as _json

from . import _core
from ._core import (Error, Shape, EdgeFeature, TetMesh, FrameField, SingularityGraph,
                    SingularCurve, SingularNode, Analysis, Correction, Blocks, HexMesh, load_shape,
                    load_brep_string, to_brep_string, classify_features, default_size,
                    tetrahedralize, mesh_quality, solve_frame_field, extract_singularities)

__all__ = ["Error", "Shape", "TetMesh", "FrameField", "SingularityGraph", "Analysis",
           "Correction", "Blocks", "HexMesh", "load_shape", "load_brep_string", "to_brep_string",
           "classify_features", "default_size", "tetrahedralize", "mesh_quality",
           "solve_frame_field", "extract_singularities", "run", "mesh_part", "analyze",
           "correct", "build_blocks", "hex_mesh", "info", "correction_methods", "report"]


def run(part, stop_after="singularities", method="auto", size=None, size_factor=1.0, threads=0,
        budget_s=0.0, fillet_rims=False, hex_size=None, layers=0, order=1, mesher="tetgen", refine=True,
        remesh_thin=True):
    """The pipeline on a file path, a :class:`Shape`, or a BREP string, up to `stop_after`
    (load, mesh, field, singularities, correct, blocks, hexmesh); `method` is the correction (see
    :func:`correction_methods`), or "none"; `budget_s` is method auto's time budget (0: 120 s
    per 50k tets); `fillet_rims` makes method fillet fillet the rims across the wall from each
    concave edge too (a groove turns smooth). Returns an :class:`Analysis` whose stages past
    `stop_after` are None; ``report(result)`` gives report.json's content as a dict.
    `hex_size`, `layers`, `order` and `refine` are the hex mesh's (see :func:`hex_mesh`). `mesher` is the
    volume mesher: "tetgen" (the default) or "hxt" (gmsh's HXT: several times faster on large
    meshes; with more than one thread its tets differ slightly from run to run). With `remesh_thin`,
    blocks that come out invalid where they are thinner than 3 tet edges get a finer mesh next to
    them (report.json's blocks.thin_refinement).
    """
    size = float(size or 0.0)
    hex_args = (float(hex_size or 0.0), int(layers), int(order))
    if isinstance(part, str) and part.lstrip().startswith("DBRep_DrawableShape"):
        part = load_brep_string(part)
    args = (stop_after, method, size, size_factor, threads, budget_s, fillet_rims, *hex_args)
    if isinstance(part, Shape):
        return _core.run_shape(part, *args, mesher=mesher, refine=refine, remesh_thin=remesh_thin)
    return _core.run_file(str(part), *args, mesher=mesher, refine=refine, remesh_thin=remesh_thin)


def mesh_part(part, size=None, size_factor=1.0, threads=0, mesher="tetgen"):
    """Load, classify feature curves, tet mesh. Returns an :class:`Analysis` (field None)."""
    return run(part, "mesh", size=size, size_factor=size_factor, threads=threads, mesher=mesher)


def analyze(part, size=None, size_factor=1.0, threads=0, mesher="tetgen"):
    """Mesh, frame field and singularity graph of a part (path, :class:`Shape` or BREP string)."""
    return run(part, "singularities", size=size, size_factor=size_factor, threads=threads, mesher=mesher)


def correct(part, method="auto", size=None, size_factor=1.0, threads=0, budget_s=0.0, fillet_rims=False):
    """Analyse a part, correct its 3-5 curves with `method`, analyse again.

    The result's field and singularities are the corrected ones; ``.correction`` says what
    changed (``.before``, ``.snapped_paths``, ``.rotated_fraction``; for auto ``.chosen`` and
    ``.tries``).
    """
    return run(part, "correct", method, size, size_factor, threads, budget_s, fillet_rims)


def build_blocks(part, method="auto", size=None, size_factor=1.0, threads=0, budget_s=0.0, fillet_rims=False,
                 remesh_thin=True, refine=True):
    """Analyse a part, correct it (`method`, or "none"), cut it into blocks.

    ``.blocks`` has ``.tet_block`` (block id per tet), ``.count``, ``.valid``;
    ``report(result)["blocks"]`` the validation. With `remesh_thin`, invalid blocks thinner than 3
    tet edges get a finer mesh next to them (``report(result)["blocks"]["thin_refinement"]``).
    With `refine`, where every block is valid and conforming, a block with a flat edge is cut in
    three where that gives better hexes: the blocks are then the refined ones, and
    ``report(result)["blocks"]["before_refinement"]`` has the figures of the blocks as cut.
    """
    return run(part, "blocks", method, size, size_factor, threads, budget_s, fillet_rims, refine=refine,
               remesh_thin=remesh_thin)


def hex_mesh(part, method="auto", size=None, size_factor=1.0, threads=0, budget_s=0.0, fillet_rims=False,
             hex_size=None, layers=0, order=1, refine=True, remesh_thin=True):
    """Analyse, correct, cut into blocks, then mesh the blocks with hexahedra.

    `hex_size` is the target hex edge length (default: two tet edges), `layers` the hexes along
    the shortest block edge (overrides it), `order` 1 (8-node) or 2 (20-node). With `refine`,
    a block with a flat edge is split in three where that gives better hexes. ``.hexmesh`` has
    ``.done`` (and ``.reason`` when not), ``.points``, ``.hexes`` (VTK order), ``.hex_block``,
    ``.scaled_jacobian``, ``.quality`` and ``.refinement``.
    """
    return run(part, "hexmesh", method, size, size_factor, threads, budget_s, fillet_rims, hex_size, layers, order,
               refine=refine, remesh_thin=remesh_thin)


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
