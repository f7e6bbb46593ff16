"""framefix correct --method extrude-curves / extrude-nodes (paper sections 4.1, 4.2): streamlines
of the initial field, inserted into a new mesh with internal constraints, at the default size and
at 0.7 x. The paper's Figs. 1c-d, 2A.b-c and 3c-d give the expected graphs."""
import json
import os
from pathlib import Path

import pytest

from conftest import SAMPLES, run

SIZES = [[], ["--size-factor", "0.7"]]
METHODS = ["extrude-curves", "extrude-nodes"]


def extrude(tmp_path, name, method, *flags):
    out = tmp_path / "out"
    code, _, err = run("correct", SAMPLES / name, "--method", method, "--out", out, "--quiet", *flags, timeout=600)
    assert code == 0, err
    return json.loads((out / "report.json").read_text()), out


def check_streamlines(c, out):
    """Every streamline is reported with its ends, length, points and stop reason; used ones
    left the solid; the points of used ones were inserted and constrained."""
    assert c["streamlines"]
    for s in c["streamlines"]:
        assert s["points"] == len(s["polyline"]) >= 2 and s["length"] > 0
        assert s["start"] == s["polyline"][0] and s["end"] == s["polyline"][-1]
        assert s["used"] == (s["stop"] == "left_solid" and "failure" not in s)
    assert any(s["used"] for s in c["streamlines"])
    assert c["inserted_points"] > 0 and c["constrained_points"] >= c["inserted_points"] * 0.9
    assert (out / "streamlines.vtk").stat().st_size > 0


def check_valid(r, out):
    c = r["correction"]
    assert c["remeshed"] and c["kept"]
    check_streamlines(c, out)
    assert r["singularities"]["summary"] == c["after"]
    assert c["after"]["meshable"] and c["after"]["curves_3_5"] == 0 and c["after"]["invalid_nodes"] == 0


@pytest.mark.parametrize("flags", SIZES, ids=["default", "x0.7"])
@pytest.mark.parametrize("method", METHODS)
def test_notch_gets_one_valence3_and_one_valence5_curve(tmp_path, method, flags):
    r, out = extrude(tmp_path, "notch.step", method, *flags)
    check_valid(r, out)
    assert r["correction"]["before"]["curves_3_5"] == 1
    kinds = sorted(k["kind"] for k in r["singularities"]["curves"])
    assert kinds == ["valence3", "valence5"]  # Figs. 1c and 1d


@pytest.mark.parametrize("flags", SIZES, ids=["default", "x0.7"])
@pytest.mark.parametrize("method", METHODS)
def test_box_with_imprinted_arc_becomes_valid(tmp_path, method, flags):
    r, out = extrude(tmp_path, "box_arc.step", method, *flags)
    check_valid(r, out)
    if method == "extrude-curves":
        assert r["correction"]["extruded_edges"]  # the imprinted arc (valence 2) is extruded


@pytest.mark.parametrize("flags", SIZES, ids=["default", "x0.7"])
def test_half_sphere_box_becomes_valid_by_feature_curve_extrusion(tmp_path, flags):
    r, out = extrude(tmp_path, "half_sphere_box.step", "extrude-curves", *flags)
    check_valid(r, out)
    assert r["correction"]["before"]["curves_3_5"] == 4


@pytest.mark.parametrize("name", ["half_sphere_box.step", "half_sphere_box_large.step"])
def test_half_sphere_box_node_extrusion_traces_from_the_interior_nodes(tmp_path, name):
    """The paper traced boundary ends only and missed four valence-3 curves; from the interior
    nodes the four 3-5 curves become four valence-5 curves (circle to the bottom) and four
    valence-3 curves (interior node to the bottom)."""
    r, out = extrude(tmp_path, name, "extrude-nodes")
    check_valid(r, out)
    c = r["correction"]
    bottom_z = min(s["end"][2] for s in c["streamlines"])
    interior = [s for s in c["streamlines"] if s["used"] and abs(s["start"][2]) > 0.1]
    assert len(interior) >= 4  # from the interior nodes, down to the box's bottom
    assert all(abs(s["end"][2] - bottom_z) < 1e-3 for s in interior)
    bottom = [k for k in r["singularities"]["curves"] if min(p[2] for p in k["points"]) < bottom_z + 0.01]
    assert sorted(k["kind"] for k in bottom) == ["valence3"] * 4 + ["valence5"] * 4


@pytest.mark.parametrize("method", METHODS)
def test_curved_box_with_arc_never_crashes_and_never_gets_worse(tmp_path, method):
    """The paper's model B: its field had two extra singular lines that the extrusions hit. Ours
    has none (0/0/1/0), so the streamlines reach the boundary; whatever happens is a result."""
    r, out = extrude(tmp_path, "box_arc_curved.step", method)
    c = r["correction"]
    before, after = c["before"], c["after"]
    assert after["curves_3_5"] + after["invalid_nodes"] <= before["curves_3_5"] + before["invalid_nodes"]
    assert after["meshable"] or c["failures"]


@pytest.mark.parametrize("method", METHODS)
def test_part_without_three_five_curves_is_unchanged(tmp_path, method):
    r, out = extrude(tmp_path, "cylinder.step", method)
    c = r["correction"]
    assert c["streamlines"] == [] and c["inserted_points"] == 0 and not c["remeshed"]
    assert c["before"] == c["after"]


def test_a_worse_result_is_dropped_with_its_reason(tmp_path):
    """n01o (two crossing cylinders) has 3-5 curves and invalid nodes; the extruded field is worse
    than the input: the input's graph is kept and
    the failure says why. (n15o, the icosahedron, served here until its curves were glued to its
    138 degree edges: it has none left to extrude.)"""
    folder = os.environ.get("FRAMEFIX_HEXME")  # the HexMe models' folder, when this machine has them
    hexme = Path(folder or ".") / "n01o_cross_cyls_sr.step"
    if not folder or not hexme.exists():
        pytest.skip("set FRAMEFIX_HEXME to the HexMe models' folder to run this test")
    out = tmp_path / "out"
    code, _, err = run("correct", hexme, "--method", "extrude-curves", "--out", out, "--quiet", timeout=600)
    assert code == 0, err
    c = json.loads((out / "report.json").read_text())["correction"]
    assert not c["kept"] and c["after"] == c["before"]
    assert any(f["what"] == "result" and "kept" in f["why"] for f in c["failures"])


@pytest.mark.parametrize("method", METHODS)
def test_one_and_two_threads_give_the_same_extrusion(tmp_path, method):
    reports = []
    for threads in ("1", "2"):
        r, _ = extrude(tmp_path / threads, "notch.step", method, "--threads", threads)
        c = r["correction"]
        reports.append((c["after"], c["inserted_points"], c["constrained_points"], r["mesh"]["tets"],
                        [s["end"] for s in c["streamlines"]]))
    assert reports[0] == reports[1]
