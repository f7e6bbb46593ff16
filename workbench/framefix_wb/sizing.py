"""Tet count estimate and default size from the backend's own size model, whose constants
come from `framefix info` (runs.backend_info): the workbench copies none of them.

A regular tet of edge h has volume h^3 / (6 sqrt 2); TetGen's tets are smaller: their mean
volume is `mean_tet_volume_h3` h^3 (measured by the backend on its samples), so a mesh of
size h of a solid of volume V has about V / (mean_tet_volume_h3 h^3) tets.
"""
import math


def estimate_tets(volume, size, info):
    """Tets of a mesh of target edge length `size` (model units) of a solid of `volume`."""
    if size <= 0:
        return float("inf")
    return abs(volume) / (info["mean_tet_volume_h3"] * size ** 3)


def default_size(volume, info):
    """The size the backend picks when given none: about info's default_target_tets tets."""
    raw = (abs(volume) / (info["mean_tet_volume_h3"] * info["default_target_tets"])) ** (1 / 3)
    return raw if raw > 0 and math.isfinite(raw) else 1.0
