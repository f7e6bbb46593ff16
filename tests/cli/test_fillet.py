"""framefix correct --method fillet (paper section 4.3): the concave edges behind the 3-5 curves are
filleted on the B-rep, and the filleted part's graph is the paper's (Figs. 1b, 3b, 5b), at the
default size and at 0.7 x."""
import json
import math
import subprocess

import pytest

from conftest import SAMPLES, run

SIZES = [[], ["--size-factor", "0.7"]]


def fillet(tmp_path, name, *flags):
    out = tmp_path / "out"
    code, _, err = run("correct", SAMPLES / name, "--method", "fillet", "--out", out, "--quiet", *flags, timeout=600)
    assert code == 0, err
    return json.loads((out / "report.json").read_text()), out


def interior(r):
    return [(n["n3"], n["n5"], n["valid"]) for n in r["singularities"]["nodes"] if not n["boundary"]]


def check_filleted(r, out):
    c = r["correction"]
    assert c["method"] == "fillet" and c["remeshed"]
    assert c["before"]["curves_3_5"] >= 1
    assert c["fillets"] and all(f["done"] and f["radius"] > 0 for f in c["fillets"])
    assert r["singularities"]["summary"] == c["after"]
    assert c["after"]["meshable"] and c["after"]["curves_3_5"] == 0 and c["after"]["invalid_nodes"] == 0
    assert (out / "filleted.brep").stat().st_size > 0
    assert (out / "filleted.step").read_text().startswith("ISO-10303-21")


@pytest.mark.parametrize("flags", SIZES, ids=["default", "x0.7"])
def test_notch_gets_the_papers_valid_node(tmp_path, flags):
    r, out = fillet(tmp_path, "notch.step", *flags)
    check_filleted(r, out)
    assert [f["edge"] for f in r["correction"]["fillets"]] == [18]  # the concave floor arc
    assert interior(r) == [(1, 3, True)]  # one valence-3 curve down to the fillet, three valence-5


def test_notch_graph_maps_back_onto_the_concave_arc(tmp_path):
    """The node and curve ends on the fillet go to the arc it replaced (radius 0.5 about x = y = 1,
    at z = 0.5), so the corrected graph lies on the original part."""
    r, out = fillet(tmp_path, "notch.step")
    m = r["correction"]["mapped"]
    assert m["summary"]["meshable"] and m["moved_nodes"] >= 1 and m["moved_points"] > 0
    on_arc = [n for n in m["nodes"] if abs(((n["position"][0] - 1) ** 2 + (n["position"][1] - 1) ** 2) ** 0.5 - 0.5) < 1e-6
              and abs(n["position"][2] - 0.5) < 1e-6]
    assert len(on_arc) == m["moved_nodes"] and all(n["boundary"] and n["valid"] for n in on_arc)
    assert (out / "mapped_curves.vtk").stat().st_size > 0


@pytest.mark.parametrize("flags", SIZES, ids=["default", "x0.7"])
def test_half_sphere_box_gets_four_extra_valence5_curves(tmp_path, flags):
    r, out = fillet(tmp_path, "half_sphere_box.step", *flags)
    check_filleted(r, out)
    before = r["correction"]["curves_before"]
    assert r["correction"]["after"]["valence5"] >= sum(c["kind"] == "valence5" for c in before) + 4
    assert all(valid for _, _, valid in interior(r))


@pytest.mark.parametrize("flags", SIZES, ids=["default", "x0.7"])
def test_half_sphere_box_original_part_is_valid_with_flat_corners(tmp_path, flags):
    """The mapped graph as a correction of the original part: its valence-5 curves on the concave
    circle turn the circle's frames by 45 deg, and the original mesh solved again has no 3-5
    curve left (the four of the input are gone)."""
    r, out = fillet(tmp_path, "half_sphere_box.step", *flags)
    flat = r["correction"]["mapped"]["flat_corners"]
    assert flat["solved"] and flat["runs"] >= 4 and flat["turned_vertices"] > 0
    assert flat["summary"]["meshable"] and flat["summary"]["curves_3_5"] == 0
    assert (out / "flat_corner_curves.vtk").stat().st_size > 0


@pytest.mark.parametrize("flags", SIZES, ids=["default", "x0.7"])
def test_groove_gets_valid_internal_nodes(tmp_path, flags):
    r, out = fillet(tmp_path, "groove.step", *flags)
    check_filleted(r, out)
    assert len(r["correction"]["fillets"]) == 2  # both concave floor arcs
    nodes = interior(r)
    assert len(nodes) >= 2 and all(valid for _, _, valid in nodes)


@pytest.mark.parametrize("flags", SIZES, ids=["default", "x0.7"])
def test_groove_with_its_rims_filleted_gets_the_papers_four_nodes(tmp_path, flags):
    """--fillet-rims: each floor arc's rim (radius 0.4 or 0.6 about x = y = 1, at z = 1) is filleted
    too, as the paper's Fig. 5b. The groove is 0.2 wide, so r = 0.05, below h at the default size,
    where the fillets are meshed finer; each rim then carries valence-3 curves, and the graph is
    the paper's: the curves rising from the floor arcs' nodes cross the rims' curves just under the
    top face, in a (2, 2) node under the outer rim and a (4, 0) node under the inner one."""
    r, out = fillet(tmp_path, "groove.step", "--fillet-rims", *flags)
    check_filleted(r, out)
    c = r["correction"]
    assert len(c["fillets"]) == 4
    assert c["fine_fillet_faces"] == (4 if c["fillets"][0]["radius"] < r["mesh"]["size"] else 0)
    def on_rim(p, rim):
        return p[2] > 0.9 and abs(((p[0] - 1) ** 2 + (p[1] - 1) ** 2) ** 0.5 - rim) < 0.05
    def length_on_rim(curve, rim):  # the crossing nodes lie off the rim, between two curves
        pts = curve["points"]
        return sum(math.dist(p, q) for p, q in zip(pts, pts[1:]) if on_rim(p, rim) and on_rim(q, rim))
    for rim in (0.4, 0.6):  # valence-3 curves run the rim's whole quarter circle (nodes split them)
        along = sum(length_on_rim(cv, rim) for cv in r["singularities"]["curves"] if cv["kind"] == "valence3")
        assert along >= 0.8 * math.pi / 2 * (rim - 0.05)
    assert sorted(interior(r)) == [(1, 3, True), (1, 3, True), (2, 2, True), (4, 0, True)]


@pytest.mark.parametrize("flags", SIZES, ids=["default", "x0.7"])
def test_wide_groove_with_its_rims_filleted_gets_the_papers_four_nodes(tmp_path, flags):
    """Fig. 5b: with all four curves of the groove filleted (r = 0.075 on the floor arcs, 0.053 on
    the rims; h = 0.06 at the default size), the new curves along the groove join the two 3-5
    curves in four valid internal nodes: (1, 3) at each floor arc, (2, 2) under the outer rim and
    (4, 0) under the inner one."""
    r, out = fillet(tmp_path, "groove_wide.step", "--fillet-rims", *flags)
    check_filleted(r, out)
    assert len(r["correction"]["fillets"]) == 4
    assert sorted(interior(r)) == [(1, 3, True), (1, 3, True), (2, 2, True), (4, 0, True)]


def test_part_without_three_five_curves_is_unchanged(tmp_path):
    r, out = fillet(tmp_path, "cylinder.step")
    c = r["correction"]
    assert c["fillets"] == [] and not c["remeshed"]
    assert c["before"] == c["after"]
    assert not (out / "filleted.brep").exists()


def test_three_five_curve_without_concave_edge_is_reported(tmp_path):
    """box_arc's 3-5 curve comes from an imprinted arc (valence 2), which is never filleted."""
    r, _ = fillet(tmp_path, "box_arc.step")
    c = r["correction"]
    assert c["fillets"] == []
    assert any("no concave feature curve" in n for n in c["notes"])
    assert c["after"] == c["before"]


def test_tet_mesh_input_is_refused(tmp_path):
    """A tet mesh has no B-rep to fillet (gmsh, installed by scripts/deps.sh, makes one)."""
    mesh = tmp_path / "cube.msh"
    subprocess.run(["gmsh", str(SAMPLES / "cube.step"), "-3", "-nt", "1", "-clmax", "0.3", "-format", "msh4",
                    "-o", str(mesh), "-v", "1"], check=True, timeout=120)
    code, _, err = run("correct", mesh, "--method", "fillet", "--out", tmp_path / "out", timeout=120)
    assert code == 2
    assert "tet mesh" in err and "--method snap" in err
