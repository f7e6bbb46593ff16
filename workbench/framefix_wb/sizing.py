"""Default target size and tet count estimate (replace when the backend exposes its own).

A regular tet of edge h has volume h^3 / (6 sqrt 2), so a near-uniform mesh of size h of a
solid of volume V has about 6 sqrt(2) V / h^3 tets, times CALIBRATION (TetGen's actual count
over that ideal; 1.0 until measured on the samples).
"""
import math

TARGET_TETS = 50000  # the backend's own default, DESIGN.md
CALIBRATION = 1.0


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
