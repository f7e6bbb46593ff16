"""framefix blocks: the block decomposition of the corrected field, through the command line."""
import json

import pytest

from conftest import SAMPLES, progress_stages, run


def cut_figures(b):
    """(count, valid, conforming pairs, pairs) of the blocks as the sheets cut them."""
    c = b["before_refinement"]
    return c["count"], c["valid"], c["conforming_pairs"], c["pairs"]


def assert_refined_from_cut(b):
    """The flat refinement keeps blocks all valid and conforming, and only adds blocks."""
    f = b["flat_refinement"]
    assert (b["valid"], b["conforming_pairs"]) == (b["count"], b["pairs"])
    if f["kept"]:
        assert b["count"] > b["before_refinement"]["count"] and f["refined"] >= 1
    else:
        assert cut_figures(b) == (b["count"], b["valid"], b["conforming_pairs"], b["pairs"]) and f["reason"]


def assert_face_lists(b):
    """Each valid block lists 6 faces of 4 corners, each across the part's boundary or a neighbour (a
    neighbour touching only along an edge has none), and a conforming pair one face on each side."""
    faces = {k["id"]: k["face_list"] for k in b["blocks"]}
    for k in b["blocks"]:
        if k["valid"]:
            assert [f["corners"] for f in k["face_list"]] == [4] * 6
        assert {f["across"] for f in k["face_list"] if f["across"] >= 0} <= set(k["neighbours"])
    for p in b["neighbour_pairs"]:
        a, c = p["blocks"]
        if p["conforming"]:
            assert [f["across"] for f in faces[a]].count(c) == 1 and [f["across"] for f in faces[c]].count(a) == 1


def block_ids(vtk_path):
    """Block id of every tet, from blocks.vtk's CELL_DATA "block"."""
    lines = vtk_path.read_text().splitlines()
    at = next(i for i, l in enumerate(lines) if l.startswith("SCALARS block "))
    n = int(next(l for l in lines if l.startswith("CELL_DATA")).split()[1])
    return [int(float(x)) for x in lines[at + 2: at + 2 + n]]


@pytest.mark.parametrize("name,count,pairs", [("cube.step", 1, 0), ("l_prism.step", 3, 2)])
def test_sanity_parts_give_the_expected_valid_blocks(analyze, tmp_path, name, count, pairs):
    r = analyze(name, command="blocks")
    b = r["blocks"]
    assert b["count"] == count
    assert b["valid"] == count
    assert (b["conforming_pairs"], b["pairs"]) == (pairs, pairs)
    assert len(b["blocks"]) == count
    assert all(k["faces"] == 6 and k["edges"] == 12 and k["corners"] == 8 for k in b["blocks"])
    assert_face_lists(b)
    # every tet belongs to exactly one block, and every block has tets
    ids = block_ids(tmp_path / "out" / "blocks.vtk")
    assert len(ids) == r["mesh"]["tets"]
    assert sorted(set(ids)) == list(range(count))
    assert sum(k["tets"] for k in b["blocks"]) == r["mesh"]["tets"]


@pytest.mark.parametrize("size", ["1", "0.7"])
def test_a_chamfered_box_is_one_hexahedron_with_the_chamfer_folded_into_one_face(tmp_path, size):
    """docs/algorithms.md#curves-along-ambiguous-edges: the field lays curves along the chamfer's
    135 degree edges; glued to them, the box has no singular curve, and its one block is a
    hexahedron once the chamfer joins one of its two neighbouring faces (never both)."""
    code, _, err = run("blocks", SAMPLES / "chamfer_box.step", "--size-factor", size, "--out", tmp_path, "--quiet")
    assert code == 0, err
    r = json.loads((tmp_path / "report.json").read_text())
    ambiguous = sorted(e["edge"] for e in r["features"]["ambiguous"])
    assert len(ambiguous) == 2
    s = r["singularities"]
    assert s["summary"]["curves"] == 0 and s["summary"]["meshable"]
    assert s["absorbed"] and all(c["ends"] == [-1, -1] for c in s["absorbed"])
    b = r["blocks"]
    assert (b["count"], b["valid"]) == (1, 1)
    assert len(b["joined_edges"]) == 1 and b["joined_edges"][0] in ambiguous


def test_notch_after_snapping_gives_seven_valid_conforming_blocks(tmp_path):
    # The snapped 3-5 curve leaves the notch with no singular curve; the sheets of its 18 feature
    # curves and of the snapped path cut it into 7 hexahedral blocks with 9 neighbour pairs.
    code, out, err = run("blocks", SAMPLES / "notch.step", "--out", tmp_path)
    assert code == 0, err
    r = json.loads((tmp_path / "report.json").read_text())
    assert r["correction"]["before"]["curves_3_5"] == 1
    assert r["correction"]["after"]["curves_3_5"] == 0
    b = r["blocks"]
    assert cut_figures(b) == (7, 7, 9, 9)
    # The block under the snapped arc has a flat edge (the paper's Fig. 6b): the template cuts it
    # in three, with its neighbour along the edge (Fig. 6c), and the flat corners go.
    f = b["flat_refinement"]
    assert f["tried"] and f["kept"] and f["refined"] == 1, f["reason"]
    assert (b["count"], b["valid"], b["conforming_pairs"], b["pairs"]) == (9, 9, 12, 12)
    assert b["before_refinement"]["flat_corners"] > 0 and b["flat_corners"] == 0
    assert len(b["blocks"]) == 9 and sorted(k["id"] for k in b["blocks"]) == list(range(9))
    assert_face_lists(b)
    ids = block_ids(tmp_path / "blocks.vtk")
    assert sorted(set(ids)) == list(range(9)) and len(ids) == r["mesh"]["tets"]
    assert {"correct", "blocks"} <= set(r["timings_s"])
    assert progress_stages(err) == ["load", "mesh", "field", "singularities", "correct", "blocks"]
    assert err.splitlines()[-1] == "progress blocks 1.000"
    assert "9 blocks, all valid, 12/12 pairs conforming (1 block with a flat edge split in three, from 7)" in out
    assert (b["junction_tries"], b["junction_mode"]) == ([], "")  # no interior node where curves meet


@pytest.mark.parametrize("threads", ["1", "2"])
def test_filleted_notch_gives_the_papers_seven_blocks_through_its_junction_node(tmp_path, threads):
    # The paper's Fig. 1b / 6a: filleting the notch's floor arc leaves one interior node where the
    # fillet's two valence-5 halves, a vertical valence-5 curve and a valence-3 stub meet. Carried
    # past the node, each half's curtain lands beside the other's, and a wedge cuts a fifth face
    # into the corner blocks; the modes that do not continue them give 7 hexahedra, as the paper.
    code, out, err = run("blocks", SAMPLES / "notch_filleted.step", "--threads", threads, "--out", tmp_path)
    assert code == 0, err
    r = json.loads((tmp_path / "report.json").read_text())
    nodes = [n for n in r["singularities"]["nodes"] if not n["boundary"]]
    assert [(n["n3"], n["n5"], n["valid"]) for n in nodes] == [(1, 3, True)]
    b = r["blocks"]
    assert cut_figures(b) == (7, 7, 9, 9)
    assert_refined_from_cut(b)
    tries = {t["mode"]: t for t in b["junction_tries"]}
    assert list(tries) == ["continue", "drop", "drop+close", "drop+zip", "drop+close+zip", "continue+close"]
    kept = tries[b["junction_mode"]]
    assert (kept["count"], kept["valid"], kept["conforming_pairs"], kept["pairs"]) == (7, 7, 9, 9)
    assert b["junction_mode"] != "continue"
    assert not b["thin_refinement"]["tried"]  # every block valid: no finer mesh


@pytest.mark.parametrize("threads", ["1", "2"])
@pytest.mark.parametrize("size", ["1", "0.7"])
def test_fillet_correction_of_the_notch_is_cut_into_the_papers_seven_blocks(tmp_path, threads, size):
    # The correction's own fillet (r about 0.09, wider than the sample's) leaves the same node, but
    # the two fillet halves' sheets part round it: the field turns there, and the quadrant between
    # their end streamlines stayed open unless zipped across the node (7 blocks, 5 valid before).
    # At 0.7 x the curtains of the two floor curves ended apart under the node, and the two blocks
    # below the floor on the y < 0.5 side were one (5 of 6 valid) until each sheet was carried
    # 0.5 h past the node (continue+close).
    code, out, err = run("blocks", SAMPLES / "notch.step", "--method", "fillet", "--threads", threads,
                         "--size-factor", size, "--out", tmp_path)
    assert code == 0, err
    r = json.loads((tmp_path / "report.json").read_text())
    assert r["correction"]["method"] == "fillet"
    assert [f["done"] for f in r["correction"]["fillets"]] == [True]
    nodes = [n for n in r["singularities"]["nodes"] if not n["boundary"]]
    assert [(n["n3"], n["n5"], n["valid"]) for n in nodes] == [(1, 3, True)]
    b = r["blocks"]
    assert cut_figures(b) == (7, 7, 9, 9)
    assert_refined_from_cut(b)
    assert b["junction_mode"] != "continue"


def test_blocks_without_correction_has_no_correction_section(tmp_path):
    code, out, err = run("blocks", SAMPLES / "l_prism.step", "--method", "none", "--out", tmp_path)
    assert code == 0, err
    r = json.loads((tmp_path / "report.json").read_text())
    assert "correction" not in r and "correct" not in r["timings_s"]
    assert r["blocks"]["count"] == 3
    assert progress_stages(err) == ["load", "mesh", "field", "singularities", "blocks"]
    assert not (tmp_path / "snapped_curves.vtk").exists()


def thin_blocks(tmp_path, *flags, command="blocks"):
    code, out, err = run(command, SAMPLES / "rounded_box.step", "--method", "none", "--out", tmp_path, "--quiet",
                         *flags, timeout=900)
    assert code == 0, err
    return json.loads((tmp_path / "report.json").read_text()), out


@pytest.mark.parametrize("factor", ["1", "0.7"])
def test_rounded_box_thin_cushions_get_a_finer_mesh(tmp_path, factor):
    """rounded_box: a box inside (20 valence-3 curves) under cushions about 0.1 thick, under 3 h
    at both sizes, so the first mesh cannot carve them. Meshed again with shorter surface edges
    under the curves and under the sheets parallel to the walls, within the tet budget (6 x), it
    gives the graph's 7 blocks, the box and six cushions, all valid and meeting face to face. At the
    default size they are meshed too: no hex inverted, the volume within 1 % (the corners of a
    cushion one mesh edge apart stay two corners of the complex)."""
    r, out = thin_blocks(tmp_path, "--size-factor", factor, command="hexmesh" if factor == "1" else "blocks")
    t, b = r["blocks"]["thin_refinement"], r["blocks"]
    assert t["tried"] and t["kept"], t["reason"]
    assert t["before"]["valid"] < t["before"]["count"] or t["before"]["count"] < 7
    assert t["faces"] == 26 and t["spots"] > 0 and 0 < t["min_size"] < r["mesh"]["size"]
    assert r["mesh"]["tets"] == t["tets_after"] and t["tets_before"] < t["tets_after"] <= 6 * t["tets_before"]
    assert r["singularities"]["summary"]["valence3"] == 20 and r["singularities"]["summary"]["meshable"]
    assert cut_figures(b) == (7, 7, 18, 18)
    assert_refined_from_cut(b)
    if not b["flat_refinement"]["kept"]:  # the box and its six cushions
        cube = max(b["blocks"], key=lambda k: k["volume"])
        assert sorted(cube["neighbours"]) == sorted(k["id"] for k in b["blocks"] if k is not cube)
    assert "meshed again finer next to 26 faces" in out
    if factor == "1":
        h = r["hexmesh"]
        assert h["done"], h["reason"]
        assert h["inverted"] == 0 and h["min_scaled_jacobian"] > 0.1
        assert abs(h["volume"] - h["part_volume"]) < 0.01 * h["part_volume"]


def test_a_finer_runs_own_thin_blocks_are_meshed_finer_again(tmp_path):
    """The groove at 0.7 x: the first finer mesh, kept, still leaves a block that is no hexahedron;
    one more round from it (its own thin places and thin blocks, its face sizes kept) makes every
    block valid and every pair conforming, within the cap of 6 x the first mesh's tets
    (docs/algorithms.md#thin-blocks)."""
    code, out, err = run("blocks", SAMPLES / "groove.step", "--method", "snap", "--size-factor", "0.7", "--out",
                         tmp_path, "--quiet", timeout=900)
    assert code == 0, err
    r = json.loads((tmp_path / "report.json").read_text())
    t = r["blocks"]["thin_refinement"]
    assert t["kept"] and t["rounds"] == 2, t["reason"]
    assert r["mesh"]["tets"] == t["tets_after"] and t["tets_before"] < t["tets_after"] <= 6 * t["tets_before"]
    b = r["blocks"]
    assert (b["valid"], b["conforming_pairs"]) == (b["count"], b["pairs"])
    assert "then again: blocks thinner than 3 h" in out


def test_glued_sheets_do_not_keep_the_gusset_from_its_finer_mesh(tmp_path):
    """The gusset at 1.5 x: the sheets of the curves glued to its web's edges make thinner blocks,
    whose finer mesh would pass the cap of 6 x. The thin places are read from the blocks without
    those sheets (set aside for the estimate, or kept from the start since its web folds into a
    hexahedron: docs/algorithms.md#triangular-prisms), they fit the cap, and the finer mesh's
    blocks are better than the first mesh's."""
    code, _, err = run("blocks", SAMPLES / "gusset.step", "--method", "snap", "--size-factor", "1.5", "--threads", "1",
                       "--out", tmp_path, "--quiet", timeout=900)
    assert code == 0, err
    r = json.loads((tmp_path / "report.json").read_text())
    t, b = r["blocks"]["thin_refinement"], r["blocks"]
    assert t["without_glued"] or t["before"]["glued_sources"] == 0
    assert t["tried"] and t["kept"], t["reason"]
    assert t["tets_after"] <= 6 * t["tets_before"] and r["mesh"]["tets"] == t["tets_after"]
    assert 2 * b["valid"] - b["count"] > 2 * t["before"]["valid"] - t["before"]["count"]


def test_thin_refinement_can_be_turned_off_and_is_not_tried_when_blocks_are_valid(tmp_path):
    r, _ = thin_blocks(tmp_path / "off", "--size-factor", "0.7", "--no-remesh-thin")
    t = r["blocks"]["thin_refinement"]
    assert not t["tried"] and "turned off" in t["reason"]
    assert r["blocks"]["valid"] < 7  # what the default mesh carves alone
    code, _, err = run("blocks", SAMPLES / "l_prism.step", "--method", "none", "--out", tmp_path / "prism", "--quiet")
    assert code == 0, err
    t = json.loads((tmp_path / "prism" / "report.json").read_text())["blocks"]["thin_refinement"]
    assert not t["tried"] and "every block is valid" in t["reason"]


@pytest.mark.parametrize("size", ["1", "0.7"])
def test_a_box_chamfered_all_round_is_one_hexahedron_each_chamfer_folded_one_way(tmp_path, size):
    """chamfer_top: four chamfers and four mitres, all ambiguous. Each chamfer folds into the top or
    its side, never both (which would give a face wrapping three sides and 2-cornered strips), and
    the mitres between chamfers folded the same way are joined with them."""
    code, _, err = run("blocks", SAMPLES / "chamfer_top.step", "--method", "snap", "--size-factor", size,
                       "--out", tmp_path, "--quiet")
    assert code == 0, err
    r = json.loads((tmp_path / "report.json").read_text())
    assert r["singularities"]["summary"]["curves"] == 0
    b = r["blocks"]
    assert (b["count"], b["valid"]) == (1, 1), b["blocks"][0]["reason"]
    edges = {c["edge"]: c["points"] for c in r["feature_curves"]}
    chamfers = [e["edge"] for e in r["features"]["ambiguous"] if e["angle_min_deg"] > 130]
    assert len(chamfers) == 8
    # A chamfer strip's two long edges are parallel: at most one of each such pair is joined.
    joined = set(b["joined_edges"])
    for a in chamfers:
        for c in chamfers:
            if a < c and a in joined and c in joined:
                da = [q - p for p, q in zip(edges[a][0], edges[a][-1])]
                dc = [q - p for p, q in zip(edges[c][0], edges[c][-1])]
                across = [q - p for p, q in zip(edges[a][0], edges[c][0])]
                parallel = abs(sum(x * y for x, y in zip(da, dc))) > 0.99 * (sum(x * x for x in da) * sum(x * x for x in dc)) ** 0.5
                assert not (parallel and sum(x * x for x in across) ** 0.5 < 0.3), (a, c, joined)
