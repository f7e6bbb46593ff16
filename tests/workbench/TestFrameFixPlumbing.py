"""Headless workbench plumbing with fake backends (run: freecadcmd -t TestFrameFixPlumbing
-M workbench -M tests/workbench). The canned backend's curves are made up: these tests check
that objects, reruns, undo and failures behave, never what the analysis finds."""
import ast
import json
import os
import tempfile
import time
import unittest

import FreeCAD
import Part

from framefix_wb import analysis, backend, info, job, make, report, runner, runs, shapes, sizing, style
from framefix_wb.errors import BackendError, FrameFixError, SelectionError
from framefix_wb.objects.properties import report_of

from ffworkbench_testing import FAKES, alive


def use_backend(name):
    os.environ["FRAMEFIX_BACKEND"] = os.path.join(FAKES, name)
    os.environ.pop("FRAMEFIX_PYTHONPATH", None)


CANNED_INFO = {"version": 1, "default_target_tets": 50000, "mean_tet_volume_h3": 0.085,
               "correction_methods": [{"name": "snap", "available": True, "description": "d"}],
               "block_methods": ["snap", "none"]}


class Pure(unittest.TestCase):
    def test_default_size_gives_the_target_tets(self):
        i = info.check_info(CANNED_INFO)
        h = sizing.default_size(1.0, i)
        self.assertAlmostEqual(h, (1.0 / (0.085 * 50000)) ** (1 / 3))
        self.assertAlmostEqual(sizing.estimate_tets(1.0, h, i), 50000)

    def test_info_with_a_bad_field_is_rejected(self):
        for key, bad in (("version", 2), ("default_target_tets", 0), ("block_methods", []),
                         ("correction_methods", [{"name": "snap"}])):
            with self.assertRaisesRegex(BackendError, key):
                info.check_info(dict(CANNED_INFO, **{key: bad}))

    def test_info_after_stderr_noise_is_read(self):
        text = "warning: something\n" + json.dumps(CANNED_INFO) + "\n"
        self.assertEqual(info.parse_info(text)["block_methods"], ["snap", "none"])

    def test_progress_lines(self):
        self.assertEqual(job.parse_progress("progress mesh 0.25\n"), ("mesh", 0.25))
        self.assertIsNone(job.parse_progress("progress mesh notanumber"))
        self.assertAlmostEqual(job.overall_fraction("singularities", 1.0), 1.0)

    def test_report_without_summary_is_rejected(self):
        with self.assertRaisesRegex(BackendError, "summary"):
            report.check_report({"version": 1, "singularities": {"curves": []}})

    def test_unknown_curve_kind_is_kept_and_counted_as_other(self):
        summary = dict(dict.fromkeys(report.SUMMARY_KEYS, 0), curves=2, valence5=1)
        r = report.check_report({"version": 1, "singularities": {"summary": summary, "curves": [
            {"kind": "valence5", "points": []}, {"kind": "other", "points": []}]}})
        self.assertEqual([c["kind"] for c in r["curves"]], ["valence5", "other"])
        self.assertEqual(report.curve_breakdown(r["summary"]), "1 valence 5, 1 other")

    def test_report_with_bad_point_is_rejected(self):
        bad = {"version": 1, "singularities": {
            "summary": dict.fromkeys(report.SUMMARY_KEYS, 0),
            "curves": [{"kind": "3-5", "points": [[0, 0, "x"]]}]}}
        with self.assertRaisesRegex(BackendError, r"curves\[0\]"):
            report.check_report(bad)

    def test_fillets_are_listed_with_their_radii_and_outcomes(self):
        summary = dict.fromkeys(report.SUMMARY_KEYS, 0)
        r = report.check_report({"version": 1, "singularities": {"summary": summary, "curves": []},
                                 "correction": {"method": "fillet", "before": summary, "fillets": [
                                     {"edge": 18, "radius": 0.0884, "done": True},
                                     {"edge": 3, "radius": 0.03, "done": False, "reason": "OCCT could not"}],
                                     "notes": ["3-5 curve 2 has no concave feature curve"]}})
        self.assertEqual(report.fillet_lines(r["correction"]),
                         ["Edge18 filleted, radius 0.0884", "Edge3 not filleted: OCCT could not",
                          "3-5 curve 2 has no concave feature curve"])
        self.assertIn("1 of 2 edges filleted (Edge18 r 0.0884)", report.run_text(r))
        with self.assertRaisesRegex(BackendError, r"fillets\[0\]"):
            report.check_report({"version": 1, "singularities": {"summary": summary, "curves": []},
                                 "correction": {"before": summary, "fillets": [{"edge": "x"}]}})


    def test_mapped_graph_and_its_flat_corner_solve_are_listed(self):
        summary = dict.fromkeys(report.SUMMARY_KEYS, 0)
        summary.update(meshable=True)
        flat = dict(summary, curves_3_5=1, meshable=False)
        r = report.check_report({"version": 1, "singularities": {"summary": summary, "curves": []},
                                 "correction": {"method": "fillet", "before": summary, "fillets": [],
                                                "mapped": {"summary": summary, "curves": [],
                                                           "flat_corners": {"solved": True, "turned_vertices": 15,
                                                                            "summary": flat}}}})
        lines = report.fillet_lines(r["correction"])
        self.assertEqual(len(lines), 2)
        self.assertTrue(lines[0].startswith("Mapped onto the original part: 0 3-5 curves") and
                        lines[0].endswith(": hex-meshable"))
        self.assertIn("(15 edge vertices turned): 1 3-5 curves", lines[1])
        self.assertTrue(lines[1].endswith("NOT hex-meshable"))
        with self.assertRaisesRegex(BackendError, r"mapped\.summary"):
            report.check_report({"version": 1, "singularities": {"summary": summary, "curves": []},
                                 "correction": {"before": summary, "mapped": {"curves": []}}})


class Layers(unittest.TestCase):
    """objects/ (stored in documents) sits below the make layer, panels and commands."""

    FORBIDDEN = ("make", "analysis", "taskpanels", "commands", "viewproviders")

    def imported(self, path):
        tree = ast.parse(open(path).read())
        for node in ast.walk(tree):
            if isinstance(node, ast.ImportFrom):
                yield from ((node.module or "").split(".") + [a.name for a in node.names])
            elif isinstance(node, ast.Import):
                yield from (p for a in node.names for p in a.name.split("."))

    def test_proxies_import_no_layer_above_them(self):
        folder = os.path.join(os.path.dirname(runs.__file__), "objects")
        for name in sorted(os.listdir(folder)):
            if name.endswith(".py"):
                bad = set(self.imported(os.path.join(folder, name))) & set(self.FORBIDDEN)
                self.assertEqual(bad, set(), name)

    def test_make_recognises_proxies_by_class(self):
        class Fake:  # an object whose proxy class is only named like one
            Proxy = type("Blocks", (), {})()
        self.assertIsNone(make.blocks_of(type("Curves", (), {"InList": [Fake()]})()))


class BackendInfo(unittest.TestCase):
    def test_canned_info_is_read_once_per_backend(self):
        use_backend("canned.py")
        first = runs.backend_info()
        self.assertIs(runs.backend_info(), first)
        self.assertEqual([m["name"] for m in first["correction_methods"]],
                         ["auto", "snap", "fillet", "extrude-curves", "extrude-nodes"])
        self.assertEqual(first["block_methods"], ["auto", "snap", "none"])
        self.assertEqual(first["default_target_tets"], 50000)

    def test_backend_without_info_is_a_clear_error(self):
        for fake in ("reject.sh", "garbage.sh", "segv.sh"):
            use_backend(fake)
            with self.assertRaisesRegex(BackendError, "framefix info"):
                runs.backend_info()

    def test_canned_backend_refuses_what_its_info_does_not_offer(self):
        use_backend("canned.py")
        methods = runs.backend_info()["correction_methods"]
        self.assertIn(False, [m["available"] for m in methods])
        for m in methods:
            j = job.AnalysisJob(Part.makeBox(1, 1, 1), 0.2, method=m["name"])
            try:
                if m["available"]:
                    self.assertEqual(runner.run_sync(j)["correction"]["method"], m["name"])
                else:
                    with self.assertRaisesRegex(BackendError, "rejected the input in stage "
                                                "correct: method '%s' is not available yet"
                                                % m["name"]):
                        runner.run_sync(j)
            finally:
                j.cleanup()


class Selection(unittest.TestCase):
    def setUp(self):
        self.doc = FreeCAD.newDocument("FrameFixSelection")

    def tearDown(self):
        FreeCAD.closeDocument(self.doc.Name)

    def test_two_solids_are_refused_with_their_count(self):
        obj = self.doc.addObject("Part::Feature", "Two")
        obj.Shape = Part.makeCompound([Part.makeBox(1, 1, 1),
                                       Part.makeBox(1, 1, 1, FreeCAD.Vector(3, 0, 0))])
        with self.assertRaisesRegex(SelectionError, "2 solids"):
            shapes.solid_of(obj)

    def test_a_face_is_refused(self):
        obj = self.doc.addObject("Part::Feature", "Face")
        obj.Shape = Part.makePlane(1, 1)
        with self.assertRaisesRegex(SelectionError, "exactly one solid"):
            shapes.solid_of(obj)

    def test_two_selected_objects_are_refused(self):
        a = self.doc.addObject("Part::Box", "A")
        b = self.doc.addObject("Part::Box", "B")
        with self.assertRaisesRegex(SelectionError, "2 objects selected"):
            shapes.source_from_selection([a, b])

    def test_link_gives_the_moved_solid(self):
        box = self.doc.addObject("Part::Box", "Box")
        link = self.doc.addObject("App::Link", "Link")
        link.LinkedObject = box
        link.Placement.Base = FreeCAD.Vector(10, 0, 0)
        self.doc.recompute()
        self.assertAlmostEqual(shapes.solid_of(link).BoundBox.XMin, 10.0)

    def test_body_gives_its_solid(self):
        body = self.doc.addObject("PartDesign::Body", "Body")
        body.addObject(self.doc.addObject("PartDesign::AdditiveBox", "Pad"))
        self.doc.recompute()
        self.assertAlmostEqual(shapes.solid_of(body).Volume, 1000.0)


class FailingBackends(unittest.TestCase):
    def run_fake(self, name, timeout=20.0):
        use_backend(name)
        j = job.AnalysisJob(Part.makeBox(1, 1, 1), 0.2, timeout=timeout)
        try:
            return runner.run_sync(j)
        finally:
            j.cleanup()

    def test_segfault_is_reported_as_a_crash(self):
        with self.assertRaisesRegex(BackendError, "crashed.*SIGSEGV"):
            self.run_fake("segv.sh")

    def test_hang_is_stopped_by_the_timeout(self):
        start = time.monotonic()
        with self.assertRaisesRegex(BackendError, "did not finish within 2 s"):
            self.run_fake("hang.sh", timeout=2.0)
        self.assertLess(time.monotonic() - start, 10.0)

    def test_timeout_kills_what_the_backend_started(self):
        pidfile = tempfile.NamedTemporaryFile(suffix=".pids", delete=False).name
        os.environ["FAKE_BACKEND_PIDFILE"] = pidfile
        try:
            with self.assertRaises(BackendError):
                self.run_fake("hang.sh", timeout=1.0)
            with open(pidfile) as f:
                pids = [int(p) for p in f.read().split()]
        finally:
            os.environ.pop("FAKE_BACKEND_PIDFILE")
            os.unlink(pidfile)
        self.assertEqual([p for p in pids if alive(p)], [])

    def test_garbage_report_is_refused(self):
        with self.assertRaisesRegex(BackendError, "not valid JSON"):
            self.run_fake("garbage.sh")

    def test_output_flood_ends_in_missing_report(self):
        start = time.monotonic()
        with self.assertRaisesRegex(BackendError, "wrote no report.json"):
            self.run_fake("flood.sh")
        self.assertLess(time.monotonic() - start, 60.0)

    def test_rejected_input_shows_the_backends_message(self):
        with self.assertRaisesRegex(BackendError, r"rejected the input in stage load: .*2 solids"):
            self.run_fake("reject.sh")

    def test_internal_error_shows_the_backends_message(self):
        j = job.AnalysisJob(Part.makeBox(1, 1, 1), 0.2, backend=backend.Backend(["true"]))
        j.add_line("framefix: internal error: unknown exception\n")
        with self.assertRaisesRegex(BackendError, "internal error: unknown exception"):
            j.finish(3)
        j.cleanup()

    def test_missing_backend_says_what_to_set(self):
        os.environ["FRAMEFIX_BACKEND"] = os.path.join(FAKES, "does-not-exist")
        with self.assertRaisesRegex(BackendError, "FRAMEFIX_BACKEND"):
            job.AnalysisJob(Part.makeBox(1, 1, 1), 0.2)


class Objects(unittest.TestCase):
    def setUp(self):
        self.doc = FreeCAD.newDocument("FrameFixObjects")
        self.box = self.doc.addObject("Part::Box", "Box")
        self.box.Label = "Bracket"
        self.doc.recompute()
        self.runs = tempfile.NamedTemporaryFile(suffix=".log", delete=False).name
        os.environ["FAKE_BACKEND_LOG"] = self.runs
        use_backend("canned.py")

    def tearDown(self):
        FreeCAD.closeDocument(self.doc.Name)
        os.environ.pop("FAKE_BACKEND_LOG", None)
        os.unlink(self.runs)

    def run_count(self):
        with open(self.runs) as f:
            return len(f.readlines())

    def test_objects_are_grouped_under_the_part_label(self):
        curves = analysis.make_analysis(self.box, 0.5)
        group = curves.getParentGroup()
        self.assertEqual(group.Label, "FrameFix analysis of Bracket")
        self.assertEqual(len(group.Group), 3)

    def test_curves_have_one_kind_per_edge(self):
        curves = analysis.make_analysis(self.box, 0.5)
        self.assertEqual(len(curves.EdgeKinds), len(curves.Shape.Edges))
        self.assertEqual(sorted(set(curves.EdgeKinds)), [3, 5, 35])
        self.assertEqual(curves.Curves35, 1)
        self.assertFalse(curves.Meshable)

    def test_nodes_mark_the_invalid_one(self):
        analysis.make_analysis(self.box, 0.5)
        nodes = self.doc.getObject("SingularNodes")
        self.assertEqual(list(nodes.NodeValid), [0, 1])
        self.assertEqual(len(nodes.Shape.Vertexes), 2)

    def test_feature_curve_without_points_uses_the_parts_edge(self):
        analysis.make_analysis(self.box, 0.5)
        features = self.doc.getObject("FeatureCurves")
        self.assertEqual(len(features.Shape.Edges), 2)
        self.assertEqual(sorted(features.EdgeValences), [1, 3])

    def test_recompute_without_change_does_not_rerun(self):
        analysis.make_analysis(self.box, 0.5)
        self.doc.recompute()
        self.assertEqual(self.run_count(), 1)

    def test_editing_the_part_touches_and_reruns(self):
        curves = analysis.make_analysis(self.box, 0.5)
        self.box.Length = 2
        self.doc.recompute([self.box])
        self.assertIn("Touched", curves.State)
        self.doc.recompute()
        self.assertEqual(self.run_count(), 2)
        self.assertTrue(curves.isValid())

    def test_changing_the_size_reruns_with_it(self):
        curves = analysis.make_analysis(self.box, 0.5)
        curves.Size = 0.25
        self.doc.recompute()
        self.assertEqual(report_of(curves)["mesh"]["size"], 0.25)

    def test_undo_removes_the_analysis(self):
        self.doc.UndoMode = 1
        names = sorted(o.Name for o in self.doc.Objects)
        analysis.make_analysis(self.box, 0.5)
        self.doc.undo()
        self.assertEqual(sorted(o.Name for o in self.doc.Objects), names)

    def test_redo_brings_it_back(self):
        self.doc.UndoMode = 1
        analysis.make_analysis(self.box, 0.5)
        self.doc.undo()
        self.doc.redo()
        curves = self.doc.getObject("SingularCurves")
        self.assertEqual(curves.Curves35, 1)
        self.assertIs(self.doc.getObject("SingularNodes").Analysis, curves)

    def test_saved_document_reloads_without_rerun(self):
        analysis.make_analysis(self.box, 0.5)
        path = os.path.join(tempfile.mkdtemp(), "saved.FCStd")
        self.doc.saveAs(path)
        FreeCAD.closeDocument(self.doc.Name)
        self.doc = FreeCAD.openDocument(path)
        curves = self.doc.getObject("SingularCurves")
        curves.touch()
        self.doc.recompute()
        self.assertTrue(curves.isValid())
        self.assertEqual(self.run_count(), 1)

    def test_correction_shows_the_curves_after_and_counts_before(self):
        curves = analysis.make_analysis(self.box, 0.5, method="snap")
        self.assertEqual((curves.Curves35, curves.Before35), (0, 1))
        self.assertEqual(curves.getParentGroup().Label, "FrameFix correction (snap) of Bracket")

    def test_correction_shows_the_snapped_paths(self):
        analysis.make_analysis(self.box, 0.5, method="snap")
        self.assertEqual(len(self.doc.getObject("SnappedPaths").Shape.Edges), 1)

    def test_unavailable_method_is_refused_before_running(self):
        curves = analysis.make_analysis(self.box, 0.5, method="snap")
        curves.Method = "fillet"
        self.doc.recompute()
        self.assertFalse(curves.isValid())
        self.assertIn("not available yet", curves.getStatusString())
        self.assertEqual(self.run_count(), 1)
        self.assertEqual(report_of(curves)["correction"]["method"], "snap")

    def test_unavailable_method_is_refused_by_make_too(self):
        with self.assertRaisesRegex(FrameFixError, "'extrude-nodes' is not available yet"):
            analysis.make_analysis(self.box, 0.5, method="extrude-nodes")
        self.assertEqual(self.run_count(), 0)

    def test_unknown_method_is_an_error_on_the_object_only(self):
        curves = analysis.make_analysis(self.box, 0.5, method="snap")
        curves.Method = "magic"
        self.doc.recompute()
        self.assertFalse(curves.isValid())
        self.assertEqual(self.run_count(), 1)

    def test_failed_run_leaves_the_document_unchanged(self):
        names = sorted(o.Name for o in self.doc.Objects)
        digest = shapes.shape_digest(self.box.Shape)
        for fake in ("segv.sh", "garbage.sh", "reject.sh"):
            use_backend(fake)
            with self.assertRaises(BackendError):
                analysis.make_analysis(self.box, 0.5)
        self.assertEqual(sorted(o.Name for o in self.doc.Objects), names)
        self.assertEqual(shapes.shape_digest(self.box.Shape), digest)

    def test_recompute_with_crashing_backend_marks_the_error_only(self):
        curves = analysis.make_analysis(self.box, 0.5)
        use_backend("segv.sh")
        self.box.Height = 3
        self.doc.recompute()
        self.assertFalse(curves.isValid())
        self.assertTrue(self.box.isValid())


class BlocksPlumbing(unittest.TestCase):
    """FrameFix_Blocks' path (`framefix blocks`) with the fake backends; the canned blocks
    (2 blocks of 3 tets each, block 1 invalid) are made up."""

    def setUp(self):
        self.doc = FreeCAD.newDocument("FrameFixBlocks")
        self.doc.UndoMode = 1
        self.box = self.doc.addObject("Part::Box", "Box")
        self.doc.recompute()
        use_backend("canned.py")

    def tearDown(self):
        FreeCAD.closeDocument(self.doc.Name)

    def test_blocks_summary_texts(self):
        b = dict(count=7, valid=7, conforming_pairs=10, pairs=10, flat_corners=0, flat_edges=1)
        self.assertEqual(report.blocks_text(b), "7 blocks, all valid, 1 flat edge")
        b.update(valid=6, conforming_pairs=9)
        self.assertEqual(report.blocks_text(b), "7 blocks, 6 valid, 9/10 pairs conforming, 1 flat edge")
        b = dict(count=9, valid=9, conforming_pairs=12, pairs=12, flat_corners=0, flat_edges=0, refined=1, cut=7)
        self.assertEqual(report.blocks_text(b), "9 blocks (7 cut, 1 with a flat edge cut in three), all valid")

    def test_blocks_job_command_line_and_progress(self):
        j = job.AnalysisJob(Part.makeBox(1, 1, 1), 0.2, method="snap", blocks=True)
        try:
            self.assertEqual(j.argv[-2:], ["--method", "snap"])
            self.assertIn("hexmesh", j.argv)  # a block run meshes its blocks too
            self.assertNotIn("--order", j.argv)
            self.assertAlmostEqual(j.overall_fraction("hexmesh", 1.0), 1.0)
            self.assertLess(j.overall_fraction("blocks", 1.0), 1.0)
            self.assertLess(j.overall_fraction("correct", 0.0), 1.0)
        finally:
            j.cleanup()

    def test_blocks_objects_every_tet_has_a_block(self):
        blocks = analysis.make_blocks(self.box, 0.5)
        self.assertTrue(blocks.isValid())
        self.assertEqual((blocks.Count, blocks.Valid), (2, 1))
        self.assertEqual(blocks.FemMesh.VolumeCount, 6)
        self.assertEqual(list(blocks.BlockIds), [0, 0, 0, 1, 1, 1])
        self.assertEqual(list(blocks.BlockValid), [1, 0])
        self.assertEqual(blocks.Summary, "2 blocks, 1 valid, 0/1 pairs conforming, 1 flat edge")
        group = blocks.getParentGroup()
        self.assertEqual(group.Label, "FrameFix blocks (auto: snap) of Box")  # auto kept snap
        names = sorted(type(o.Proxy).__name__ for o in group.Group)
        self.assertEqual(names, ["BlockEdges", "BlockSurfaces", "Blocks", "FeatureCurves", "HexMesh",
                                 "SingularCurves", "SingularNodes", "SnappedPaths"])
        self.assertEqual(blocks.Analysis.Curves35, 0)

    def test_block_surfaces_one_shell_per_block_coloured_on_the_app_side(self):
        blocks = analysis.make_blocks(self.box, 0.5)
        surfaces = self.doc.getObject("BlockSurfaces")
        self.assertEqual(len(surfaces.Shape.Faces), 12)
        self.assertEqual(len(surfaces.Shape.Shells), 2)
        self.assertEqual(list(surfaces.BlockOfFace), [0] * 6 + [1] * 6)
        self.assertAlmostEqual(surfaces.Shape.Area, 6.0)
        red = tuple(style.INVALID_BLOCK_COLOR)
        colours = [tuple(round(c, 3) for c in col[:3]) for col in surfaces.BlockColors]
        self.assertEqual(colours[1], tuple(round(c, 3) for c in red))  # block 1 is invalid
        self.assertNotEqual(colours[0], colours[1])
        self.assertEqual(len(blocks.BlockColors), 2)
        edges = self.doc.getObject("BlockEdges")
        self.assertEqual(len(edges.Shape.Edges), 5)  # polylines of 3 and 4 points

    def test_neighbouring_blocks_get_different_colours(self):
        ring = [{"id": i, "valid": True, "neighbours": [(i - 1) % 5, (i + 1) % 5]} for i in range(5)]
        colours = style.block_colors(ring)
        for i in range(5):
            self.assertNotEqual(colours[i], colours[(i + 1) % 5])
        self.assertNotIn(tuple(style.INVALID_BLOCK_COLOR), [tuple(c) for c in colours])

    def test_blocks_without_correction_have_no_snapped_paths(self):
        blocks = analysis.make_blocks(self.box, 0.5, method="none")
        self.assertEqual(blocks.Analysis.Curves35, 1)
        self.assertIsNone(self.doc.getObject("SnappedPaths"))

    def test_changing_the_method_reruns_with_it(self):
        blocks = analysis.make_blocks(self.box, 0.5)
        curves = blocks.Analysis
        curves.Method = "none"
        self.doc.recompute()
        self.assertTrue(blocks.isValid())
        self.assertIsNone(report_of(curves)["correction"])
        self.assertEqual(curves.Curves35, 1)
        self.assertEqual(blocks.MeshDigest, curves.InputDigest)

    def test_changing_the_size_reruns_and_rebuilds_the_mesh(self):
        blocks = analysis.make_blocks(self.box, 0.5)
        curves = blocks.Analysis
        curves.Size = 0.25
        self.doc.recompute()
        self.assertTrue(blocks.isValid())
        self.assertEqual(blocks.MeshDigest, curves.InputDigest)

    def test_undo_removes_the_blocks_and_redo_restores_them(self):
        names = sorted(o.Name for o in self.doc.Objects)
        analysis.make_blocks(self.box, 0.5)
        self.doc.undo()
        self.assertEqual(sorted(o.Name for o in self.doc.Objects), names)
        self.doc.redo()
        self.assertEqual(self.doc.getObject("Blocks").FemMesh.VolumeCount, 6)

    def test_saved_document_keeps_the_block_mesh(self):
        analysis.make_blocks(self.box, 0.5)
        path = os.path.join(tempfile.mkdtemp(), "blocks.FCStd")
        self.doc.saveAs(path)
        FreeCAD.closeDocument(self.doc.Name)
        runs.forget_block_meshes()
        self.doc = FreeCAD.openDocument(path)
        blocks = self.doc.getObject("Blocks")
        blocks.touch()
        self.doc.recompute()
        self.assertTrue(blocks.isValid())
        self.assertEqual(blocks.FemMesh.VolumeCount, 6)
        surfaces = self.doc.getObject("BlockSurfaces")
        surfaces.touch()
        self.doc.recompute()
        self.assertTrue(surfaces.isValid())
        self.assertEqual(len(surfaces.Shape.Faces), 12)

    def test_failing_backends_through_blocks_leave_the_document_unchanged(self):
        names = sorted(o.Name for o in self.doc.Objects)
        digest = shapes.shape_digest(self.box.Shape)
        for fake, message in (("segv.sh", "crashed.*SIGSEGV"), ("garbage.sh", "not valid JSON"),
                              ("reject.sh", "rejected the input"),
                              ("flood.sh", "wrote no report.json")):
            use_backend(fake)
            with self.assertRaisesRegex(BackendError, message):
                analysis.make_blocks(self.box, 0.5)
        os.environ["FRAMEFIX_TIMEOUT"] = "2"
        try:
            use_backend("hang.sh")
            with self.assertRaisesRegex(BackendError, "did not finish within 2 s"):
                analysis.make_blocks(self.box, 0.5)
        finally:
            os.environ.pop("FRAMEFIX_TIMEOUT")
        self.assertEqual(sorted(o.Name for o in self.doc.Objects), names)
        self.assertEqual(shapes.shape_digest(self.box.Shape), digest)

    def test_report_without_blocks_vtk_is_refused(self):
        use_backend("canned.py")
        j = job.AnalysisJob(Part.makeBox(1, 1, 1), 0.5, blocks=True)
        try:
            runner.run_sync(j)
            os.unlink(os.path.join(j.out_dir, "blocks.vtk"))
            with self.assertRaisesRegex(BackendError, "wrote no blocks.vtk"):
                j.finish(0)
            with open(os.path.join(j.out_dir, "blocks.vtk"), "w") as f:
                f.write("# vtk DataFile Version 3.0\nx\nASCII\nDATASET UNSTRUCTURED_GRID\n"
                        "POINTS 8 double\n0 0 0\n")
            with self.assertRaisesRegex(BackendError, "blocks.vtk is unusable"):
                j.finish(0)
        finally:
            j.cleanup()

    def test_hex_mesh_is_a_fem_mesh_of_hexa8(self):
        hexes = analysis.make_hex_mesh(self.box, 0.5)
        self.assertTrue(hexes.isDerivedFrom("Fem::FemMeshObject"))
        fem = hexes.FemMesh
        self.assertEqual((fem.NodeCount, fem.VolumeCount, fem.HexaCount), (8, 1, 1))
        # FreeCAD's node order (as its .inp reader maps C3D8): node 1 is C3D8's node 6 = (1, 0, 1)
        self.assertEqual(tuple(fem.getNodeById(fem.getElementNodes(1)[0])), (1.0, 0.0, 1.0))
        self.assertEqual(list(hexes.ScaledJacobians), [1.0])
        self.assertEqual((hexes.Hexes, hexes.Inverted), (1, 0))
        self.assertEqual(hexes.Summary, "1 hex, min scaled Jacobian 1.00, 0 inverted")
        self.assertEqual(hexes.getParentGroup().Label, "FrameFix blocks (auto: snap) of Box")

    def test_hex_mesh_of_order_two_is_hexa20_and_reruns_when_the_order_changes(self):
        hexes = analysis.make_hex_mesh(self.box, 0.5, order=2)
        self.assertEqual((hexes.FemMesh.NodeCount, hexes.FemMesh.VolumeCount), (20, 1))
        self.assertEqual(len(hexes.FemMesh.getElementNodes(1)), 20)
        self.assertIn("(20-node)", hexes.Summary)
        curves = hexes.Analysis
        curves.HexOrder = 1
        curves.touch()
        self.doc.recompute()
        self.assertEqual((hexes.FemMesh.NodeCount, hexes.FemMesh.VolumeCount), (8, 1))

    def test_blocks_that_cannot_be_meshed_are_a_message_and_no_hex_mesh(self):
        use_backend("canned.py")
        j = job.AnalysisJob(Part.makeBox(1, 1, 1), 0.5, blocks=True)
        try:
            runner.run_sync(j)
            path = os.path.join(j.out_dir, "report.json")
            with open(path) as f:
                data = json.load(f)
            data["hexmesh"] = {"done": False, "reason": "block 1 is not a hexahedron (faces 5)"}
            with open(path, "w") as f:
                json.dump(data, f)
            report_ = j.finish(0)
            self.assertIsNone(report_["block_mesh"]["hexes"])
            self.assertEqual(report.hexmesh_text(report_["hexmesh"]),
                             "no hex mesh: block 1 is not a hexahedron (faces 5)")
        finally:
            j.cleanup()

    def test_hex_mesh_text_names_the_blocks_split_in_three(self):
        h = {"done": True, "order": 1, "hexes": 825, "vertices": 1139, "inverted": 0, "min_scaled_jacobian": 0.67,
             "mean_scaled_jacobian": 0.96, "share_sj_ge_0_5": 1.0, "refinement": {"kept": True, "refined": 1}}
        self.assertEqual(report.hexmesh_text(report._hexmesh(h)),
                         "825 hexes, min scaled Jacobian 0.67, 0 inverted (1 block with a flat edge split in three)")
        h["refinement"]["kept"] = False  # tried, and the plain blocks gave the better hexes
        self.assertEqual(report.hexmesh_text(report._hexmesh(h)), "825 hexes, min scaled Jacobian 0.67, 0 inverted")

    def test_bad_hex_vtk_is_refused(self):
        use_backend("canned.py")
        j = job.AnalysisJob(Part.makeBox(1, 1, 1), 0.5, blocks=True)
        try:
            runner.run_sync(j)
            path = os.path.join(j.out_dir, "hex.vtk")
            with open(path) as f:
                text = f.read()
            with open(path, "w") as f:
                f.write(text.replace("8 0 1 2 3 4 5 6 7", "8 0 1 2 3 4 5 6 99"))
            with self.assertRaisesRegex(BackendError, "hex.vtk is unusable: a cell names"):
                j.finish(0)
        finally:
            j.cleanup()

    def test_bad_block_surfaces_are_refused(self):
        use_backend("canned.py")
        j = job.AnalysisJob(Part.makeBox(1, 1, 1), 0.5, blocks=True)
        try:
            runner.run_sync(j)
            path = os.path.join(j.out_dir, "block_surfaces.vtk")
            with open(path) as f:
                text = f.read()
            with open(path, "w") as f:
                f.write(text.replace("3 0 2 3", "3 0 2 99"))
            with self.assertRaisesRegex(BackendError, "block_surfaces.vtk is unusable: a cell names"):
                j.finish(0)
            os.unlink(path)
            with self.assertRaisesRegex(BackendError, "wrote no block_surfaces.vtk"):
                j.finish(0)
        finally:
            j.cleanup()
