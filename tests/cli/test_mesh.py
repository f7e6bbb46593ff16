"""framefix mesh: report.json sections and a VTK file ParaView opens, on every sample."""
import json

import pytest

from conftest import SAMPLES, progress_stages, run

SAMPLE_FILES = sorted(p.name for p in SAMPLES.glob("*.step"))


def test_samples_exist():
    assert {"notch.step", "cube.step", "cylinder.step", "l_prism.step"} <= set(SAMPLE_FILES)


@pytest.mark.parametrize("name", SAMPLE_FILES)
def test_mesh_writes_report_and_vtk(name, tmp_path):
    code, out, err = run("mesh", SAMPLES / name, "--out", tmp_path, "--size-factor", "1.6")
    assert code == 0, err
    assert "report.json" in out
    report = json.loads((tmp_path / "report.json").read_text())
    assert report["version"] == 1
    assert report["input"]["kind"] == "step"
    assert report["input"]["path"].endswith(name)
    assert report["mesh"]["tets"] > 1000
    assert report["mesh"]["vertices"] > 100
    # The nominal size is the mean edge length (gmsh's is about 0.71 of its mean edge); shorter
    # edges on narrow faces that keep the default size lower the mean.
    ratio = report["mesh"]["mean_edge"] / report["mesh"]["size"]
    assert (0.9 if "narrow_faces" not in report["mesh"] else 0.5) < ratio < 1.1, ratio
    assert set(report["features"]["by_valence"]) == {"1", "2", "3", "4"}
    assert {"load", "mesh", "total"} <= set(report["timings_s"])
    assert "singularities" not in report  # mesh does not analyse
    vtk = (tmp_path / "mesh.vtk").read_text().splitlines()
    assert vtk[0].startswith("# vtk DataFile")
    assert any(l.startswith("SCALARS face_tag") for l in vtk)
    assert any(l.startswith("SCALARS edge_tag") for l in vtk)


# Feature curves per sample: (curves, convex valence 1, flat 2, concave 3). Each count is one per
# B-rep edge with a dihedral angle away from 180 degrees (seams and imprint-free smooth joins are
# not features): a box has 12 convex edges, an L-prism 17 convex and its inner concave one.
FEATURES = {
    "cube.step": (12, 12, 0, 0), "l_prism.step": (18, 17, 0, 1), "notch.step": (18, 17, 0, 1),
    "cylinder.step": (2, 2, 0, 0), "groove.step": (24, 22, 0, 2), "half_sphere_box.step": (13, 12, 0, 1),
    "two_cylinders.step": (5, 3, 0, 2), "box_arc.step": (15, 14, 1, 0), "box_arc_curved.step": (16, 15, 1, 0),
    # A fillet replaces a concave edge by a tangent face: its two new edges are smooth joins.
    "notch_filleted.step": (19, 19, 0, 0), "half_sphere_box_filleted.step": (12, 12, 0, 0),
    "groove_filleted.step": (26, 26, 0, 0),
    "notch_wide.step": (18, 17, 0, 1), "notch_shallow.step": (18, 17, 0, 1),
    "half_sphere_box_small.step": (13, 12, 0, 1), "half_sphere_box_large.step": (13, 12, 0, 1),
    "groove_wide.step": (24, 22, 0, 2), "groove_narrow.step": (24, 22, 0, 2),
    # groove_wide without its 2 rims and 2 floor arcs, plus each fillet's profile arc on the 2 side faces.
    "groove_wide_filleted.step": (28, 28, 0, 0),
    "box_arc_wide.step": (15, 14, 1, 0), "box_arc_small.step": (15, 14, 1, 0),
    # The arc's end and the roof's seam (y = 0.5) split the roof's edge at x = 1 in three (box_arc_curved's
    # arc ends at the seam); the steep roof's seam also splits the arc in two.
    "box_arc_curved_flat.step": (17, 16, 1, 0), "box_arc_curved_steep.step": (18, 16, 2, 0),
    "sphere.step": (0, 0, 0, 0),  # its seam and pole edges are no features
    "rounded_box.step": (0, 0, 0, 0),  # every edge is a fillet's tangent seam
    "tube.step": (4, 4, 0, 0),  # its four circles; the two seams are no features
    # A chamfer's two 135 degree edges round to valence 2; the four chamfers' mitres (120 degrees) to 1.
    "chamfer_box.step": (15, 13, 2, 0), "chamfer_top.step": (20, 12, 8, 0),
    # The L's inner edge split in two by the gusset, the gusset's sides meeting both legs (4), its two 225 degree edges.
    "gusset.step": (27, 19, 0, 8),
}


def test_every_sample_has_its_feature_counts():
    assert set(FEATURES) == set(SAMPLE_FILES)


@pytest.mark.parametrize("name", sorted(FEATURES))
def test_feature_curves_are_counted_per_valence(analyze, name):
    report = analyze(name, "--size-factor", "1.6", command="mesh")
    curves, convex, flat, concave = FEATURES[name]
    f = report["features"]
    assert f["curves"] == curves
    assert (f["by_valence"]["1"], f["by_valence"]["2"], f["by_valence"]["3"], f["by_valence"]["4"]) == (convex, flat, concave, 0)
    assert len({c["edge"] for c in report["feature_curves"]}) == len(report["feature_curves"]) == curves


@pytest.mark.parametrize("command,stages", [
    ("mesh", ["load", "mesh"]),
    ("analyze", ["load", "mesh", "field", "singularities"]),
])
def test_progress_lines_go_forward_in_stage_order(tmp_path, command, stages):
    code, out, err = run(command, SAMPLES / "cube.step", "--out", tmp_path, "--size-factor", "1.6")
    assert code == 0, err
    assert progress_stages(err) == stages
    assert err.splitlines()[-1] == "progress %s 1.000" % stages[-1]


@pytest.mark.parametrize("name,kind", [("notch.igs", "iges"), ("notch.brep", "brep")])
def test_iges_and_brep_inputs_give_the_same_part_as_step(analyze, name, kind):
    from conftest import TESTDATA
    other = analyze(TESTDATA / name)
    step = analyze("notch.step")
    assert other["input"]["kind"] == kind
    assert other["features"]["by_valence"] == step["features"]["by_valence"]
    assert other["singularities"]["summary"]["curves_3_5"] == 1


def test_a_coarse_size_coarsens_only_the_faces_wide_enough_for_it(tmp_path):
    """At 2.5 x the default size the groove's 0.2-wide floor would be one edge across, and its
    two 3-5 curves would merge: its narrow faces keep the default size, the rest coarsens."""
    reports = {}
    for factor in ("1", "2.5"):
        code, _, err = run("analyze", SAMPLES / "groove.step", "--out", tmp_path / factor,
                           "--size-factor", factor, "--quiet")
        assert code == 0, err
        reports[factor] = json.loads((tmp_path / factor / "report.json").read_text())
    default, coarse = reports["1"], reports["2.5"]
    assert "narrow_faces" not in default["mesh"]
    assert coarse["mesh"]["narrow_faces"] >= 1
    assert coarse["mesh"]["tets"] < default["mesh"]["tets"] / 4
    for r in (default, coarse):
        assert r["singularities"]["summary"]["curves_3_5"] == 2
    code, _, err = run("mesh", SAMPLES / "cube.step", "--out", tmp_path / "cube", "--size-factor", "2.5")
    assert code == 0, err
    assert "narrow_faces" not in json.loads((tmp_path / "cube" / "report.json").read_text())["mesh"]
