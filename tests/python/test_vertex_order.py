"""The singularity graph does not depend on the order of the mesh's vertices (issue 12): the same
tets written to a Medit file twice, the second time with the vertices shuffled, analyse alike."""
import numpy as np
import pytest

import framefix
from conftest import SAMPLES


def write_medit(path, points, tets, triangles, tags):
    with open(path, "w") as f:
        f.write("MeshVersionFormatted 2\nDimension 3\nVertices\n%d\n" % len(points))
        f.writelines("%.17g %.17g %.17g 0\n" % tuple(p) for p in points)
        f.write("Tetrahedra\n%d\n" % len(tets))
        f.writelines("%d %d %d %d 1\n" % tuple(t + 1) for t in tets)
        f.write("Triangles\n%d\n" % len(triangles))
        f.writelines("%d %d %d %d\n" % (t[0] + 1, t[1] + 1, t[2] + 1, g) for t, g in zip(triangles, tags))
        f.write("End\n")


@pytest.mark.parametrize("name,curves_3_5", [("notch.step", 1), ("half_sphere_box.step", 4), ("two_cylinders.step", 4)])
def test_shuffled_vertices_give_the_same_graph(name, curves_3_5, tmp_path):
    m = framefix.run(str(SAMPLES / name), "mesh", size_factor=1.3).mesh
    points, tets = np.array(m.points), np.array(m.tets)
    triangles, tags = np.array(m.boundary_faces), np.array(m.face_tags)
    write_medit(tmp_path / "a.mesh", points, tets, triangles, tags)
    order = np.random.default_rng(20261201).permutation(len(points))
    new_index = np.argsort(order)  # vertex i of the first file is vertex new_index[i] of the second
    write_medit(tmp_path / "b.mesh", points[order], new_index[tets], new_index[triangles], tags)
    a = framefix.analyze(str(tmp_path / "a.mesh")).singularities
    b = framefix.analyze(str(tmp_path / "b.mesh")).singularities
    assert a.summary == b.summary
    assert a.summary["curves_3_5"] == curves_3_5
    assert sorted(c.kind for c in a.curves) == sorted(c.kind for c in b.curves)
    assert sorted(round(c.length, 6) for c in a.curves) == pytest.approx(sorted(round(c.length, 6) for c in b.curves), abs=1e-3)
