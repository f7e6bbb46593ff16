"""Default target size and tet count estimate (replace when the backend exposes its own).

A regular tet of edge h has volume h^3 / (6 sqrt 2), so a near-uniform mesh of size h of a
solid of volume V has about 6 sqrt(2) V / h^3 tets, times CALIBRATION: the backend's count
over that ideal, 1.75 on the notch at its default size (63k tets at h = 0.0596). Coarser
meshes have relatively more (x1.9 at 29k tets, x3 at 23k) as the boundary layer dominates.
"""
import math

TARGET_TETS = 50000  # the backend's own default, DESIGN.md
CALIBRATION = 1.75


def estimate_tets(volume, size):
    """Tets of a mesh of target edge length `size` (model units) of a solid of `volume`."""
    if size <= 0:
        return float("inf")
    return CALIBRATION * 6.0 * math.sqrt(2.0) * abs(volume) / size ** 3


def default_size(volume, target_tets=TARGET_TETS):
    """The size giving about `target_tets` tets, rounded to 2 significant digits."""
    raw = (CALIBRATION * 6.0 * math.sqrt(2.0) * abs(volume) / target_tets) ** (1.0 / 3.0)
    if raw <= 0 or not math.isfinite(raw):
        return 1.0
    return round(raw, 1 - int(math.floor(math.log10(raw))))
