"""mesher="hxt" from Python: the extension finds the framefix-hxt worker from its own folder, and
HXT keeps the very surface TetGen keeps (same triangles, same face tags, same corners)."""
import numpy as np
import pytest

import framefix
from conftest import SAMPLES


def oriented(triangle):
    """A triangle's three points turned to start at the smallest: the same orientation."""
    k = min(range(3), key=lambda i: triangle[i])
    return tuple(triangle[k:] + triangle[:k])


def surface(result):
    """The boundary as sorted (oriented triangle, face tag) rows, and the corner points."""
    m = result.mesh
    p, faces = np.asarray(m.points), np.asarray(m.boundary_faces)
    triangles = [oriented([tuple(p[v]) for v in f]) for f in faces]
    return sorted(zip(triangles, np.asarray(m.face_tags).tolist())), p[np.asarray(m.corner_vertices)]


def volume(result):
    p, t = np.asarray(result.mesh.points), np.asarray(result.mesh.tets)
    a, b, c = (p[t[:, k]] - p[t[:, 0]] for k in (1, 2, 3))
    return np.einsum("ij,ij->i", a, np.cross(b, c)).sum() / 6


@pytest.mark.parametrize("name", ["notch.step", "half_sphere_box.step"])
def test_hxt_keeps_tetgens_surface_and_tags(name):
    hxt = framefix.mesh_part(str(SAMPLES / name), mesher="hxt", threads=1)
    tetgen = framefix.mesh_part(str(SAMPLES / name), threads=1)
    assert framefix.report(hxt)["mesh"]["mesher"] == "hxt"
    (rows_h, corners_h), (rows_t, corners_t) = surface(hxt), surface(tetgen)
    assert rows_h == rows_t
    assert np.array_equal(corners_h, corners_t)
    assert volume(hxt) == pytest.approx(volume(tetgen), rel=1e-9)  # both fill the same closed surface


def test_an_unknown_mesher_raises():
    with pytest.raises(framefix.Error, match="unknown mesher 'fast'"):
        framefix.mesh_part(str(SAMPLES / "cube.step"), mesher="fast")
