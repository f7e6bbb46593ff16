"""Default target size and tet count estimate, the backend's own model (keep in sync with
backend/framefix/tetgen/size_model.cpp, kMeanTetVolume).

A regular tet of edge h has volume h^3 / (6 sqrt 2), so a near-uniform mesh of size h of a
solid of volume V has about 6 sqrt(2) V / h^3 tets, times CALIBRATION. TetGen's tets are
smaller than regular ones: the backend measured a mean tet volume of 0.085 h^3 on the
samples, so CALIBRATION = 1 / (6 sqrt(2) 0.085) = 1.39 (the notch at the default size:
63.6k tets for 50k estimated; coarse meshes have relatively more, the boundary dominating).
"""
import math

TARGET_TETS = 50000  # the backend's default, DESIGN.md
MEAN_TET_VOLUME = 0.085  # in h^3, backend/framefix/tetgen/size_model.cpp
CALIBRATION = 1.0 / (6.0 * math.sqrt(2.0) * MEAN_TET_VOLUME)


def estimate_tets(volume, size):
    """Tets of a mesh of target edge length `size` (model units) of a solid of `volume`."""
    if size <= 0:
        return float("inf")
    return CALIBRATION * 6.0 * math.sqrt(2.0) * abs(volume) / size ** 3


def default_size(volume, target_tets=TARGET_TETS):
    """The size the backend picks when given none: about `target_tets` tets."""
    raw = (CALIBRATION * 6.0 * math.sqrt(2.0) * abs(volume) / target_tets) ** (1.0 / 3.0)
    return raw if raw > 0 and math.isfinite(raw) else 1.0
