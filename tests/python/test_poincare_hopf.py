"""Surface singular nodes obey Poincare-Hopf on every boundary patch (docs/algorithms.md#valence-sign-rule
for the indices).

On a patch P bounded by feature curves: sum of the indices of the curve ends in P (+1/4 for a
valence-3 curve, -1/4 for a valence-5 curve) = chi(P) - sum over its corners of (2 - k_c)/4, with
k_c = round(interior angle / 90 deg). The right side is computed from the mesh alone, so the test
checks the field against the topology of the part.
"""
import numpy as np
import pytest

import framefix
from conftest import SAMPLES

SAMPLE_NAMES = ["cube", "l_prism", "cylinder", "notch", "box_arc", "box_arc_curved", "half_sphere_box", "groove",
                "two_cylinders", "sphere", "rounded_box", "tube"]


def patch_labels(mesh, valence):
    """Boundary triangles joined across non-feature edges -> one label per triangle."""
    feature = {tuple(sorted(e)) for e, tag in zip(mesh.feature_edges.tolist(), mesh.edge_tags) if valence.get(int(tag), 0)}
    parent = list(range(len(mesh.boundary_faces)))

    def find(x):
        while parent[x] != x:
            parent[x] = parent[parent[x]]
            x = parent[x]
        return x

    by_edge = {}
    for t, tri in enumerate(mesh.boundary_faces.tolist()):
        for k in range(3):
            by_edge.setdefault(tuple(sorted((tri[k], tri[(k + 1) % 3]))), []).append(t)
    for e, ts in by_edge.items():
        if e not in feature and len(ts) == 2:
            parent[find(ts[0])] = find(ts[1])
    return np.array([find(t) for t in range(len(parent))])


def expected_index(points, tris):
    """chi(P) - sum over boundary vertices of (2 - round(angle / 90)) / 4."""
    edges = {}
    for tri in tris.tolist():
        for k in range(3):
            e = tuple(sorted((tri[k], tri[(k + 1) % 3])))
            edges[e] = edges.get(e, 0) + 1
    chi = len(np.unique(tris)) - len(edges) + len(tris)
    rim = {v for e, n in edges.items() if n == 1 for v in e}
    angle = dict.fromkeys(rim, 0.0)
    for tri in tris.tolist():
        for k in range(3):
            if tri[k] in angle:
                a = points[tri[(k + 1) % 3]] - points[tri[k]]
                b = points[tri[(k + 2) % 3]] - points[tri[k]]
                angle[tri[k]] += np.degrees(np.arccos(np.clip(a @ b / np.linalg.norm(a) / np.linalg.norm(b), -1, 1)))
    return chi - sum((2 - round(t / 90)) / 4 for t in angle.values())


@pytest.mark.parametrize("name", SAMPLE_NAMES)
def test_surface_nodes_satisfy_poincare_hopf_on_every_patch(name):
    r = framefix.analyze(str(SAMPLES / f"{name}.step"))
    mesh = r.mesh
    labels = patch_labels(mesh, {f.edge: f.valence for f in r.features})
    centroids = mesh.points[mesh.boundary_faces].mean(axis=1)
    found = {}
    for node in r.singularities.nodes:
        if node.boundary:
            patch = labels[np.argmin(np.linalg.norm(centroids - node.position, axis=1))]
            found[patch] = found.get(patch, 0) + (node.n3 - node.n5) / 4
    for patch in np.unique(labels):
        tags = sorted(set(mesh.face_tags[labels == patch].tolist()))
        want = expected_index(mesh.points, mesh.boundary_faces[labels == patch])
        assert found.get(patch, 0) == pytest.approx(want), f"{name}: patch of faces {tags}"
