"""The mesh stage tries again another way when TetGen fails, and blames the solid only when OCCT
finds the solid itself self-intersecting (issue 11)."""
import json
import os

from conftest import SAMPLES, TESTDATA, run


def mesh(tmp_path, part, *flags, env=None):
    old = dict(os.environ)
    os.environ.update(env or {})
    try:
        code, out, err = run("analyze", part, "--out", tmp_path, "--quiet", *flags)
    finally:
        os.environ.clear()
        os.environ.update(old)
    report = json.loads((tmp_path / "report.json").read_text()) if code == 0 else None
    return code, err, report


def test_samples_mesh_on_the_first_try(tmp_path):
    code, err, report = mesh(tmp_path, SAMPLES / "notch.step")
    assert code == 0, err
    assert report["mesh"]["attempts"] == [{"how": "surface at 1 h, boundary kept", "failure": None}]


def polyline_length(points):
    return sum(sum((a - b) ** 2 for a, b in zip(p, q)) ** 0.5 for p, q in zip(points, points[1:]))


def test_crash_in_boundary_recovery_is_retried_with_steiner_points(tmp_path):
    """A TetGen crash (injected: the -Y run segfaults) is retried letting TetGen split boundary
    triangles; the edge tags survive, so every feature curve comes back whole, and the notch
    still has its one 3-5 curve."""
    code, err, plain = mesh(tmp_path / "plain", SAMPLES / "notch.step")
    assert code == 0, err
    code, err, report = mesh(tmp_path / "retried", SAMPLES / "notch.step", env={"FRAMEFIX_FAULT": "tetgen-keep-boundary"})
    assert code == 0, err
    tries = report["mesh"]["attempts"]
    assert [t["how"] for t in tries] == ["surface at 1 h, boundary kept", "surface at 1 h, boundary Steiner points allowed"]
    assert "TetGen crashed (Segmentation fault)" in tries[0]["failure"]
    assert tries[1]["failure"] is None
    assert report["singularities"]["summary"]["curves_3_5"] == 1
    lengths = lambda r: sorted((c["edge"], round(polyline_length(c["points"]), 2)) for c in r["feature_curves"])
    assert lengths(report) == lengths(plain)
    assert len(lengths(report)) == 18


def test_thin_curved_shell_meshes_at_a_fine_size(tmp_path):
    """0.4 thick on a radius of 20, at 0.6 x the default size: the surface refinement used to put
    points off the sphere near its pole, and TetGen found the triangulation self-intersecting."""
    code, err, report = mesh(tmp_path, TESTDATA / "thin_cap.step", "--size-factor", "0.6")
    assert code == 0, err
    assert len(report["mesh"]["attempts"]) == 1


def test_self_intersecting_solid_is_named_as_such(tmp_path):
    """BRepCheck passes this loft; OCCT's self-intersection check does not: the message says the
    solid is at fault and names its faces, with exit 2 and no crash."""
    code, err, report = mesh(tmp_path, TESTDATA / "looped_blade.step")
    assert code == 2, err
    assert "the solid self-intersects" in err
    assert "Face1" in err and "repair these faces in the CAD tool" in err
