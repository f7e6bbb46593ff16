"""framefix.run: one pipeline, stopped where the caller says; the registry read from Python."""
import ctypes

import numpy as np
import pytest

import framefix
from conftest import SAMPLES, TESTDATA

CUBE, NOTCH = str(SAMPLES / "cube.step"), str(SAMPLES / "notch.step")
COARSE = 1.6  # size factor: a few thousand tets are enough for these facts


@pytest.mark.parametrize("stop,present", [
    ("mesh", {"mesh"}),
    ("field", {"mesh", "field"}),
    ("singularities", {"mesh", "field", "singularities"}),
])
def test_run_returns_exactly_the_stages_it_reached(stop, present):
    r = framefix.run(CUBE, stop, size_factor=COARSE)
    stages = {"mesh", "field", "singularities", "correction", "blocks"}
    assert {s for s in stages if getattr(r, s) is not None} == present
    report = framefix.report(r)
    assert ("field" in report) == ("field" in present)
    assert ("singularities" in report) == ("singularities" in present)
    assert "correction" not in report and "blocks" not in report


def test_cube_analysis_has_no_singular_curve():
    r = framefix.analyze(CUBE, size_factor=COARSE)
    assert r.singularities.summary["curves"] == 0
    assert r.mesh.num_vertices == r.field.axes.shape[0]
    assert len(r.features) == 12


def test_correct_notch_keeps_what_it_corrected():
    r = framefix.correct(NOTCH, method="snap")
    c = r.correction
    assert c.method == "snap" and c.changed
    assert c.before["curves_3_5"] == 1 and c.graph_before.summary["curves_3_5"] == 1
    assert r.singularities.summary["curves_3_5"] == 0
    assert len(c.snapped_paths) == 1 and c.snapped_paths[0].shape[1] == 3
    assert 0 < c.rotated_fraction < 0.05
    assert r.blocks is None


def test_extrusion_from_python_lists_its_streamlines_and_failures():
    r = framefix.correct(NOTCH, method="extrude-curves")
    c = r.correction
    assert c.method == "extrude-curves" and c.remeshed and c.constrained_points > 0
    assert r.singularities.summary["meshable"]
    used = [s for s in c.streamlines if s["used"]]
    assert used and all(s["stop"] == "left_solid" and s["points"].shape[1] == 3 for s in used)
    assert isinstance(c.failures, list)
    assert r.mesh.num_vertices == r.field.axes.shape[0]  # the new mesh carries the new field


def test_auto_is_the_default_and_lists_its_tries():
    r = framefix.correct(NOTCH)
    c = r.correction
    assert c.method == "auto" and c.chosen == "snap" and c.changed
    assert [t["method"] for t in c.tries] == ["snap"]  # hex-meshable at the first try
    assert c.tries[0]["ran"] and c.tries[0]["kept"] and c.tries[0]["after"]["meshable"]
    assert r.singularities.summary["meshable"] and c.snap_rounds[-1]["meshable"]
    assert len(c.snapped_paths) == 1  # the kept method's own record


def test_fillet_from_python_maps_its_graph_onto_the_original_part():
    r = framefix.correct(str(SAMPLES / "half_sphere_box.step"), method="fillet")
    c = r.correction
    assert c.method == "fillet" and c.remeshed and "CASCADE Topology" in c.filleted_brep
    assert c.mapped.summary["meshable"] and c.mapped.summary["valence5"] >= 4
    assert c.flat_corners is not None and c.flat_corners.summary["curves_3_5"] == 0
    assert r.mesh.num_vertices == r.field.axes.shape[0]  # the run's mesh is the filleted part's


def test_fillet_rims_from_python():
    """The notch's arc and, with fillet_rims, the top edge across its wall: two fillets."""
    plain = framefix.report(framefix.correct(str(SAMPLES / "notch.step"), method="fillet", size_factor=COARSE))
    rims = framefix.report(framefix.correct(str(SAMPLES / "notch.step"), method="fillet", size_factor=COARSE,
                                            fillet_rims=True))
    assert len(plain["correction"]["fillets"]) == 1
    assert len(rims["correction"]["fillets"]) == 2 and all(f["done"] for f in rims["correction"]["fillets"])


def test_blocks_of_the_l_prism_without_correction():
    r = framefix.build_blocks(str(SAMPLES / "l_prism.step"), method="none", size=0.05)
    assert r.correction is None
    assert (r.blocks.count, r.blocks.valid) == (3, 3)
    assert r.blocks.tet_block.shape == (r.mesh.num_tets,)
    assert set(np.unique(r.blocks.tet_block)) == {0, 1, 2}


def test_blocks_of_the_half_sphere_box_report_its_convex_paths():
    """Snapping puts the dome's 3-5 curves onto the dome: every path is convex, four reach the base
    circle and give its curtain four corner lines; the dome over an O-grid is 10 valid blocks."""
    r = framefix.build_blocks(str(SAMPLES / "half_sphere_box.step"), method="snap")
    assert sorted(r.blocks.convex_paths) == list(range(len(r.correction.snapped_paths)))
    assert r.blocks.curtain_corners == 4
    cut = framefix.report(r)["blocks"]["before_refinement"]
    assert (cut["count"], cut["valid"]) == (10, 10) and r.blocks.valid == r.blocks.count >= 10
    assert framefix.report(r)["blocks"]["convex_paths"] == list(r.blocks.convex_paths)
    assert (r.blocks.junction_tries, r.blocks.junction_mode) == ([], "")  # snapped: no interior node


def test_the_notchs_flat_block_is_refined_in_the_blocks_unless_turned_off():
    """The snapped notch: 7 blocks as cut, the one under the arc with a flat edge; cut in three
    with its neighbour along the edge, 9 blocks, each tet in one of them."""
    r = framefix.build_blocks(NOTCH, method="snap")
    b = framefix.report(r)["blocks"]
    assert b["flat_refinement"]["kept"] and b["before_refinement"]["count"] == 7
    assert (r.blocks.count, r.blocks.valid) == (9, 9) and set(np.unique(r.blocks.tet_block)) == set(range(9))
    plain = framefix.build_blocks(NOTCH, method="snap", refine=False)
    assert (plain.blocks.count, plain.blocks.valid) == (7, 7)
    assert "turned off" in framefix.report(plain)["blocks"]["flat_refinement"]["reason"]


def test_blocks_at_a_junction_node_list_each_mode_tried_and_keep_the_best():
    """notch_filleted's interior node (1 valence-3 and 3 valence-5 curves, the fillet's curve
    running straight on through it): the five ways of carrying sheets past it are tried, and the
    kept one has the most valid blocks."""
    r = framefix.build_blocks(str(SAMPLES / "notch_filleted.step"), method="none")
    tries = r.blocks.junction_tries
    assert [t["mode"] for t in tries] == ["continue", "drop", "drop+close", "drop+zip", "drop+close+zip", "continue+close"]
    kept = next(t for t in tries if t["mode"] == r.blocks.junction_mode)
    cut = framefix.report(r)["blocks"]["before_refinement"]  # the tries' blocks, before the flat refinement
    assert (kept["count"], kept["valid"]) == (cut["count"], cut["valid"])
    assert kept["valid"] == max(t["valid"] for t in tries)
    assert framefix.report(r)["blocks"]["junction_tries"] == tries


def test_blocks_of_the_tube_are_its_ring_cut_in_four_and_thin_refinement_can_be_turned_off():
    """The tube's one block would be a solid torus: four meridian sheets cut it into quarters.
    Every block is then valid, so no finer mesh is tried; remesh_thin=False says it is off."""
    tube = str(SAMPLES / "tube.step")
    r = framefix.build_blocks(tube, method="none")
    assert (r.blocks.ring_cuts, r.blocks.count, r.blocks.valid) == (4, 4, 4)
    thin = framefix.report(r)["blocks"]["thin_refinement"]
    assert not thin["tried"] and "every block is valid" in thin["reason"]
    off = framefix.report(framefix.build_blocks(tube, method="none", size_factor=COARSE, remesh_thin=False))
    assert not off["blocks"]["thin_refinement"]["tried"] and "turned off" in off["blocks"]["thin_refinement"]["reason"]


def test_a_shape_runs_like_its_file():
    shape = framefix.load_shape(CUBE)
    a = framefix.report(framefix.run(shape, "mesh", size_factor=COARSE))
    b = framefix.report(framefix.run(CUBE, "mesh", size_factor=COARSE))
    assert a["mesh"] == b["mesh"] and a["features"] == b["features"]


def test_registry_from_python_matches_what_run_accepts():
    methods = framefix.correction_methods()
    assert methods[0] == framefix.info()["correction_methods"][0]
    for m in methods:
        if m["available"]:
            continue
        # refused before the (missing) part is even opened
        with pytest.raises(framefix.Error, match="^correct: method '%s' is not available yet" % m["name"]):
            framefix.correct("/nonexistent/part.step", method=m["name"])
    with pytest.raises(framefix.Error, match="^correct: unknown method 'magic'"):
        framefix.correct("/nonexistent/part.step", method="magic")


def test_thread_count_is_per_call_and_results_do_not_depend_on_it():
    gomp = ctypes.CDLL("libgomp.so.1")  # the OpenMP runtime _core runs on, already loaded
    threads_before = gomp.omp_get_max_threads()
    one = framefix.report(framefix.analyze(NOTCH, size_factor=COARSE, threads=1))
    two = framefix.report(framefix.analyze(NOTCH, size_factor=COARSE, threads=2))
    for r in (one, two):
        del r["timings_s"], r["peak_memory_mb"]
    assert one == two
    assert gomp.omp_get_max_threads() == threads_before  # the host process is left as it was


def test_tetgen_crash_in_process_is_retried_and_the_interpreter_lives(monkeypatch):
    """TetGen crashing (injected) inside framefix.analyze: the worker dies, not this interpreter,
    and the mesh stage meshes on its second way."""
    monkeypatch.setenv("FRAMEFIX_FAULT", "tetgen-keep-boundary")
    r = framefix.analyze(NOTCH, size_factor=COARSE)
    assert [a["failure"] is None for a in r.mesh_attempts] == [False, True]
    assert "crashed" in r.mesh_attempts[0]["failure"]
    assert r.singularities.summary["curves_3_5"] == 1


def test_self_intersecting_solid_raises_framefix_error():
    with pytest.raises(framefix.Error, match="the solid self-intersects"):
        framefix.analyze(str(TESTDATA / "looped_blade.step"))
