"""The framefix Python module (built for /usr/bin/python3, the interpreter FreeCAD embeds)."""
import numpy as np
import pytest

import framefix
from conftest import SAMPLES, TESTDATA


def test_load_and_classify_cube():
    shape = framefix.load_shape(str(SAMPLES / "cube.step"))
    assert (shape.num_faces, shape.num_edges, shape.num_vertices) == (6, 12, 8)
    features = framefix.classify_features(shape)
    assert len(features) == 12
    assert [f.edge for f in features] == list(range(1, 13))
    assert all(f.valence == 1 for f in features)
    assert all(80 < f.angle_min_deg <= f.angle_max_deg < 100 for f in features)


def test_brep_string_round_trip():
    shape = framefix.load_shape(str(SAMPLES / "notch.step"))
    again = framefix.load_brep_string(framefix.to_brep_string(shape))
    assert again.num_edges == shape.num_edges
    assert again.volume == pytest.approx(shape.volume, rel=1e-9)


def test_tetrahedralize_returns_numpy_arrays():
    shape = framefix.load_shape(str(SAMPLES / "cube.step"))
    h = framefix.default_size(shape, 8000)
    mesh = framefix.tetrahedralize(shape, h)
    assert isinstance(mesh.points, np.ndarray) and mesh.points.shape[1] == 3
    assert mesh.tets.shape == (mesh.num_tets, 4)
    assert mesh.boundary_faces.shape[0] == mesh.face_tags.shape[0]
    assert set(np.unique(mesh.face_tags)) == set(range(1, 7))
    assert set(np.unique(mesh.edge_tags)) == set(range(1, 13))
    p = mesh.points[mesh.tets]
    vol = np.einsum("ij,ij->i", p[:, 1] - p[:, 0], np.cross(p[:, 2] - p[:, 0], p[:, 3] - p[:, 0])) / 6
    assert vol.min() > 0
    q = framefix.mesh_quality(mesh)
    assert q.edge_fraction_in_range >= 0.9


@pytest.mark.parametrize("name,words", [
    ("empty.step", ["empty"]), ("garbage.step", ["garbage.step"]), ("truncated.step", ["truncated.step"]),
    ("face.brep", ["solid"]), ("open_shell.brep", ["open_shell.brep"]), ("two_solids.step", ["2 solids"]),
])
def test_bad_files_raise_framefix_error(name, words):
    with pytest.raises(framefix.Error) as e:
        framefix.load_shape(str(TESTDATA / name))
    for w in words:
        assert w in str(e.value)


def test_missing_file_and_bad_brep_string_raise_framefix_error():
    with pytest.raises(framefix.Error, match="^load: /nonexistent/x.step does not exist"):
        framefix.load_shape("/nonexistent/x.step")
    with pytest.raises(framefix.Error, match="^load: .*BREP"):
        framefix.load_brep_string("this is not a BREP")


def test_errors_name_the_stage_and_what_to_do():
    with pytest.raises(framefix.Error, match=r"^load: 'part\.xyz' has an unknown extension; give a \.step"):
        framefix.analyze("part.xyz")
    with pytest.raises(framefix.Error, match=r"^options: unknown stage 'solve'; use load, mesh"):
        framefix.run(str(SAMPLES / "cube.step"), stop_after="solve")


def test_field_extrapolation_is_an_option_that_keeps_the_notch_graph():
    """Extrapolation at the MBO floor (evaluated, off by default): the notch keeps its one 3-5 curve."""
    a = framefix.mesh_part(str(SAMPLES / "notch.step"), threads=1)
    plain = framefix.solve_frame_field(a.mesh, a.features, threads=1)
    jumped = framefix.solve_frame_field(a.mesh, a.features, threads=1, extrapolate=True)
    assert plain.extrapolations == 0 and plain.converged
    assert jumped.extrapolations >= 1 and jumped.converged
    for field in (plain, jumped):
        s = framefix.extract_singularities(a.mesh, field, threads=1).summary
        assert (s["curves"], s["curves_3_5"], s["meshable"]) == (1, 1, False)


def test_large_mesh_settings_keep_the_notch_graph_and_an_explicit_cap_is_hard():
    """The large-mesh settings (coarse correction, raised MBO cap) forced on a default-size mesh:
    the same graph, a converged field; max_iterations given is a hard cap even then."""
    a = framefix.mesh_part(str(SAMPLES / "notch.step"), threads=1)
    plain = framefix.solve_frame_field(a.mesh, a.features, threads=1)
    large = framefix.solve_frame_field(a.mesh, a.features, threads=1, large_mesh_vertices=1)
    assert "coarse" in large.solver and "coarse" not in plain.solver
    assert plain.iteration_cap == 60 and large.iteration_cap >= 60 and large.converged
    s = framefix.extract_singularities(a.mesh, large, threads=1).summary
    assert (s["curves"], s["curves_3_5"], s["meshable"]) == (1, 1, False)
    capped = framefix.solve_frame_field(a.mesh, a.features, max_iterations=5, threads=1, large_mesh_vertices=1)
    assert capped.iteration_cap == 5 and capped.iterations == 5
