"""Headless workbench and macro API on the real backend (run: freecadcmd -t TestFrameFixApp
-M workbench -M tests/workbench with FRAMEFIX_BACKEND and FRAMEFIX_PYTHONPATH set, as ctest
does). Oracle: the notch (box [0,1]^3 minus a vertical cylinder r=0.5 through (1,1)) has
exactly one 3-5 curve, wherever it is placed."""
import os
import unittest

import FreeCAD
import Part

from framefix_wb import analysis, make, runs, shapes
from framefix_wb.objects.properties import report_of

SAMPLES = os.environ.get("FRAMEFIX_SAMPLES") or os.path.join(
    os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))), "samples")
NOTCH = os.path.join(SAMPLES, "notch.step")


def count_3_5(kinds):
    return sum(1 for k in kinds if k == "3-5")


def _normal(face, point):
    u, v = face.Surface.parameter(point)
    return face.normalAt(u, v)


def feature_edges(solid):
    """Indices (1-based, FreeCAD's Edge<i>) of the solid's edges that are feature curves: two
    different faces meeting at an angle (not a seam, not a tangent join), from the shape."""
    found = []
    for i, edge in enumerate(solid.Edges, 1):
        faces = []
        for f in solid.ancestorsOfType(edge, Part.Face):
            if not any(f.isSame(g) for g in faces):
                faces.append(f)
        if len(faces) != 2:
            continue  # a seam: one face on both sides
        p = edge.valueAt(sum(edge.ParameterRange) / 2)
        if _normal(faces[0], p).cross(_normal(faces[1], p)).Length > 0.05:
            found.append(i)
    return found


class MacroApi(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        import framefix.freecad
        cls.ff = framefix.freecad
        cls.notch = Part.read(NOTCH)
        cls.result = cls.ff.analyze(cls.notch)

    def test_notch_has_exactly_one_3_5_curve(self):
        self.assertEqual(self.result.summary["curves_3_5"], 1)

    def test_curves_list_agrees_with_the_summary(self):
        self.assertEqual(count_3_5(c.kind for c in self.result.curves), 1)

    def test_notch_is_not_meshable(self):
        self.assertFalse(self.result.meshable)

    def test_curve_points_are_n_by_3_inside_the_box(self):
        points = [c for c in self.result.curves if c.kind == "3-5"][0].points
        self.assertEqual(points.shape[1], 3)
        self.assertTrue(((points > -1e-6) & (points < 1 + 1e-6)).all())

    def test_two_solids_raise_framefix_error(self):
        import framefix
        two = Part.makeCompound([Part.makeBox(1, 1, 1), Part.makeBox(1, 1, 1, FreeCAD.Vector(2, 0, 0))])
        with self.assertRaises(framefix.Error):
            self.ff.analyze(two)


class MacroApiRunner(unittest.TestCase):
    """framefix.freecad runs its backend through the workbench's runner (framefix_wb.runs):
    the same lookup, the same failure messages, as framefix.Error."""

    def with_backend(self, name):
        from ffworkbench_testing import FAKES
        import framefix.freecad as ff
        saved = os.environ.get("FRAMEFIX_BACKEND")
        os.environ["FRAMEFIX_BACKEND"] = os.path.join(FAKES, name)
        try:
            return ff.analyze(Part.makeBox(1, 1, 1), size=0.5)
        finally:
            if saved is None:
                os.environ.pop("FRAMEFIX_BACKEND")
            else:
                os.environ["FRAMEFIX_BACKEND"] = saved

    def test_a_crash_is_the_workbenchs_message_as_framefix_error(self):
        import framefix
        with self.assertRaisesRegex(framefix.Error, r"crashed \(killed by SIGSEGV\).*unchanged"):
            self.with_backend("segv.sh")

    def test_the_found_backend_is_the_one_run(self):
        self.assertEqual(self.with_backend("canned.py").summary["curves"], 3)


class Objects(unittest.TestCase):
    """One analysis of the notch at the workbench's default size."""

    @classmethod
    def setUpClass(cls):
        cls.doc = FreeCAD.newDocument("FrameFixApp")
        cls.part = cls.doc.addObject("Part::Feature", "Notch")
        cls.part.Shape = Part.read(NOTCH)
        cls.doc.recompute()
        cls.curves = analysis.make_analysis(cls.part)

    @classmethod
    def tearDownClass(cls):
        FreeCAD.closeDocument(cls.doc.Name)

    def test_analysis_shows_one_3_5_curve(self):
        self.assertEqual(self.curves.Curves35, 1)

    def test_the_3_5_curve_has_its_colour_code(self):
        self.assertIn(35, self.curves.EdgeKinds)

    def test_nodes_and_feature_curves_are_valid(self):
        for name in ("SingularNodes", "FeatureCurves"):
            self.assertTrue(self.doc.getObject(name).isValid(), name)

    def test_feature_curves_cover_the_parts_edges(self):
        """As many feature curves as the part has feature edges, each edge drawn end to end,
        nothing drawn elsewhere."""
        from framefix_wb.objects.properties import report_of
        solid = self.part.Shape.Solids[0]
        expected = feature_edges(solid)
        self.assertGreater(len(expected), 8)
        reported = sorted(f["edge"] for f in report_of(self.curves)["feature_curves"])
        self.assertEqual(reported, expected)
        shown = self.doc.getObject("FeatureCurves").Shape
        self.assertEqual(len(shown.Edges), len(self.doc.getObject("FeatureCurves").EdgeValences))
        tol = 0.01 * solid.BoundBox.DiagonalLength
        for i in expected:
            edge = solid.Edges[i - 1]
            a, b = edge.ParameterRange
            for t in (a, (a + b) / 2, b):
                self.assertLess(shown.distToShape(Part.Vertex(edge.valueAt(t)))[0], tol,
                                "Edge%d not shown at %.3g" % (i, t))
        features = Part.Compound([solid.Edges[i - 1] for i in expected])
        for e in shown.Edges:
            mid = Part.Vertex(e.valueAt(sum(e.ParameterRange) / 2))
            self.assertLess(features.distToShape(mid)[0], tol, "a curve off the part's edges")


class Correction(unittest.TestCase):
    def setUp(self):
        self.doc = FreeCAD.newDocument("FrameFixCorrection")
        self.part = self.doc.addObject("Part::Feature", "Notch")
        self.part.Shape = Part.read(NOTCH)
        self.doc.recompute()

    def tearDown(self):
        FreeCAD.closeDocument(self.doc.Name)

    def test_boundary_snapping_removes_the_notchs_3_5_curve(self):
        curves = analysis.make_analysis(self.part, method="snap")
        self.assertEqual((curves.Before35, curves.Curves35), (1, 0))

    def test_auto_keeps_snapping_on_the_notch_and_lists_its_tries(self):
        curves = analysis.make_analysis(self.part, method="auto")
        self.assertEqual((curves.Before35, curves.Curves35, curves.Method), (1, 0, "auto"))
        group = [o for o in curves.InList if o.isDerivedFrom("App::DocumentObjectGroup")][0]
        self.assertTrue(group.Label.startswith("FrameFix correction (auto: snap) of"), group.Label)
        self.assertGreater(len(self.doc.getObject("SnappedPaths").Shape.Edges), 0)
        from framefix_wb.objects.properties import report_of
        from framefix_wb.report import tries_lines
        lines = tries_lines(report_of(curves)["correction"])
        self.assertTrue(lines[0].startswith("input: 1 3-5 curves"), lines)
        self.assertTrue(lines[1].startswith("snap: 0 3-5 curves, 0 invalid nodes, hex-meshable"), lines)
        self.assertEqual(lines[-1], "kept: snap")

    def test_fillet_adds_the_filleted_part_and_leaves_the_users_part(self):
        part = self.part
        volume, faces = part.Shape.Volume, len(part.Shape.Faces)
        curves = analysis.make_analysis(part, method="fillet")
        self.assertEqual((curves.Before35, curves.Curves35), (1, 0))
        filleted = self.doc.getObject("FilletedPart")
        self.assertEqual(len(filleted.Shape.Faces), faces + 1)  # the fillet's face
        self.assertGreater(filleted.Shape.Volume, volume)  # a concave edge gains material
        self.assertEqual((part.Shape.Volume, len(part.Shape.Faces)), (volume, faces))
        self.check_mapped_curves_on_the_arc(0)
        # A run from the panel on the same analysis replaces the filleted solid.
        solid = shapes.solid_of(part)
        report = runs.run(solid, None, method="fillet")
        make.update_analysis(curves, 0, report, runs.input_digest(solid, 0, "fillet"), "fillet")
        filleted = [o for o in self.doc.Objects if o.Name.startswith("FilletedPart")]
        self.assertEqual(len(filleted), 1)
        self.assertEqual(len(filleted[0].Shape.Faces), faces + 1)
        # Moving the part reruns the analysis on recompute, and its filleted solid moves along.
        x_min = filleted[0].Shape.BoundBox.XMin
        part.Placement.Base = FreeCAD.Vector(2, 0, 0)
        self.doc.recompute()
        self.assertTrue(filleted[0].isValid())
        self.assertAlmostEqual(filleted[0].Shape.BoundBox.XMin, x_min + 2, places=6)
        self.assertEqual(len(filleted[0].Shape.Faces), faces + 1)
        self.check_mapped_curves_on_the_arc(2)

    def check_mapped_curves_on_the_arc(self, dx):
        """The corrected graph mapped onto the user's part: valid, and some of its curve points
        on the concave arc the fillet replaced (radius 0.5 about x = 1 + dx, y = 1, z = 0.5)."""
        mapped = [o for o in self.doc.Objects if o.Name.startswith("MappedCurves")]
        self.assertEqual(len(mapped), 1)
        self.assertTrue(mapped[0].Valid)
        self.assertEqual(len(mapped[0].EdgeKinds), len(mapped[0].Shape.Edges))
        on_arc = [v for v in mapped[0].Shape.Vertexes if abs(v.Point.z - 0.5) < 1e-6 and
                  abs(((v.Point.x - 1 - dx) ** 2 + (v.Point.y - 1) ** 2) ** 0.5 - 0.5) < 1e-6]
        self.assertGreater(len(on_arc), 2)

    def test_fillet_rims_from_a_macro_fillet_the_grooves_four_edges(self):
        """The groove (two concave floor arcs, two convex rims above them): with fillet_rims
        the filleted part has the four fillet faces, the setting is kept on the analysis and
        in what a recompute compares, and the user's part is unchanged."""
        self.part.Shape = Part.read(os.path.join(SAMPLES, "groove.step"))
        self.doc.recompute()
        faces, volume = len(self.part.Shape.Faces), self.part.Shape.Volume
        curves = analysis.make_analysis(self.part, method="fillet", fillet_rims=True)
        self.assertTrue(curves.FilletRims)
        self.assertTrue(curves.InputDigest.endswith(" rims"), curves.InputDigest)
        filleted = self.doc.getObject("FilletedPart")
        self.assertEqual(len(filleted.Shape.Faces), faces + 4)
        done = [f for f in report_of(curves)["correction"]["fillets"] if f["done"]]
        self.assertEqual(len(done), 4)
        self.assertEqual((len(self.part.Shape.Faces), self.part.Shape.Volume), (faces, volume))
        # Switching the rims off reruns on recompute: the floor arcs only.
        curves.FilletRims = False
        curves.touch()
        self.doc.recompute()
        self.assertFalse(curves.InputDigest.endswith(" rims"))
        self.assertEqual(len(filleted.Shape.Faces), faces + 2)


    def test_extrusions_show_their_streamlines_inside_the_part(self):
        """Both extrusions remove the notch's 3-5 curve; the streamlines they traced are shown
        (used ones and failed ones told apart by their edge code) and lie in the part."""
        part = self.part
        volume = part.Shape.Volume
        for method in ("extrude-curves", "extrude-nodes"):
            curves = analysis.make_analysis(part, method=method)
            self.assertEqual((curves.Before35, curves.Curves35), (1, 0), method)
            lines = [o for o in curves.getParentGroup().Group if o.Name.startswith("Streamlines")]
            self.assertEqual(len(lines), 1, method)
            self.assertGreater(len(lines[0].Shape.Edges), 10, method)
            box = part.Shape.BoundBox
            box.enlarge(1e-6)
            self.assertTrue(box.isInside(lines[0].Shape.BoundBox), method)
        self.assertEqual(part.Shape.Volume, volume)


class MovedPart(unittest.TestCase):
    def test_moving_the_part_reruns_and_keeps_one_3_5_curve(self):
        doc = FreeCAD.newDocument("FrameFixMoved")
        try:
            part = doc.addObject("Part::Feature", "Notch")
            part.Shape = Part.read(NOTCH)
            doc.recompute()
            curves = analysis.make_analysis(part)
            part.Placement.Base = FreeCAD.Vector(10, 0, 0)
            doc.recompute()
            self.assertTrue(curves.isValid())
            self.assertEqual(curves.Curves35, 1)
            self.assertGreater(curves.Shape.BoundBox.XMin, 9.0)
        finally:
            FreeCAD.closeDocument(doc.Name)


class Blocks(unittest.TestCase):
    """framefix blocks (snap) on the notch through the workbench's objects."""

    def test_notch_blocks_every_tet_in_a_block(self):
        from framefix_wb.objects.properties import report_of
        doc = FreeCAD.newDocument("FrameFixBlocks")
        try:
            part = doc.addObject("Part::Feature", "Notch")
            part.Shape = Part.read(NOTCH)
            doc.recompute()
            blocks = analysis.make_blocks(part)
            report = report_of(blocks.Analysis)
            self.assertTrue(blocks.isValid())
            self.assertEqual(report["blocks"]["cut"], 7)  # docs/results.md: the notch cut after snapping
            self.assertEqual(blocks.Count, 9)  # its flat block and the one along the edge, each in three
            self.assertEqual(blocks.Count, report["blocks"]["count"])
            tets = blocks.FemMesh.VolumeCount
            self.assertEqual(tets, int(report["mesh"]["tets"]))
            self.assertEqual(len(blocks.BlockIds), tets)
            self.assertTrue(all(0 <= b < blocks.Count for b in blocks.BlockIds))
            self.assertEqual(blocks.Analysis.Curves35, 0)
            self.assertGreater(len(doc.getObject("SnappedPaths").Shape.Edges), 0)
        finally:
            FreeCAD.closeDocument(doc.Name)


class HexMeshFem(unittest.TestCase):
    """The notch's hex mesh in FreeCAD's FEM workbench: a CalculiX static analysis, fixed on the
    bottom face with a pressure on the top face, gives displacements (downwards on top)."""

    def setUp(self):
        self.doc = FreeCAD.newDocument("FrameFixHexMesh")
        self.part = self.doc.addObject("Part::Feature", "Notch")
        self.part.Shape = Part.read(NOTCH)
        self.doc.recompute()

    def tearDown(self):
        FreeCAD.closeDocument(self.doc.Name)

    def _face(self, pick):
        """Name of the planar face with normal +-z whose height `pick` (min or max) selects."""
        flat = [(f.CenterOfMass.z, "Face%d" % (i + 1)) for i, f in enumerate(self.part.Shape.Faces)
                if f.Surface.__class__.__name__ == "Plane" and abs(abs(f.normalAt(0, 0).z) - 1) < 1e-9]
        return pick(flat)[1]

    @unittest.skipUnless(os.path.exists("/usr/bin/ccx"), "CalculiX (calculix-ccx) is not installed")
    def test_calculix_runs_on_the_notchs_hex_mesh(self):
        import ObjectsFem
        from femtools import ccxtools
        hexes = make.make_hex_mesh(self.part, method="snap")
        report = report_of(hexes.Analysis)["hexmesh"]
        self.assertEqual(hexes.FemMesh.HexaCount, report["hexes"])
        self.assertEqual(hexes.FemMesh.VolumeCount, report["hexes"])
        fem = ObjectsFem.makeAnalysis(self.doc, "Analysis")
        solver = ObjectsFem.makeSolverCalculixCcxTools(self.doc, "CalculiX")
        material = ObjectsFem.makeMaterialSolid(self.doc, "Steel")
        material.Material = {"Name": "Steel", "YoungsModulus": "210000 MPa", "PoissonRatio": "0.3",
                             "Density": "7900 kg/m^3"}
        fixed = ObjectsFem.makeConstraintFixed(self.doc, "Fixed")
        fixed.References = [(self.part, self._face(min))]
        pressure = ObjectsFem.makeConstraintPressure(self.doc, "Pressure")
        pressure.References = [(self.part, self._face(max))]
        pressure.Pressure = 1.0
        for obj in (solver, material, fixed, pressure, hexes):
            fem.addObject(obj)
        self.doc.recompute()
        fea = ccxtools.FemToolsCcx(fem, solver)
        fea.update_objects()
        fea.setup_working_dir()
        fea.setup_ccx()
        self.assertEqual(fea.check_prerequisites(), "")
        fea.write_inp_file()
        fea.ccx_run()
        fea.load_results()
        results = [o for o in fem.Group if o.isDerivedFrom("Fem::FemResultObject")]
        self.assertEqual(len(results), 1, fea.ccx_stdout if hasattr(fea, "ccx_stdout") else "")
        lengths = list(results[0].DisplacementLengths)
        self.assertEqual(len(lengths), hexes.FemMesh.NodeCount)
        self.assertGreater(max(lengths), 0)
        self.assertEqual(len(self.part.Shape.Faces), len(Part.read(NOTCH).Faces))  # the part is untouched


class BackendInfo(unittest.TestCase):
    """The workbench's methods and sizing come from the real backend's `framefix info`."""

    def test_the_registry_reaches_the_workbench(self):
        from framefix_wb import runs
        info = runs.backend_info()
        methods = {m["name"]: m["available"] for m in info["correction_methods"]}
        self.assertEqual(methods, {"auto": True, "snap": True, "fillet": True, "extrude-curves": True,
                                   "extrude-nodes": True})
        self.assertEqual(info["block_methods"], ["auto", "snap", "fillet", "extrude-curves", "extrude-nodes",
                                                 "none"])
        self.assertEqual(info["default_target_tets"], 50000)

    def test_an_unknown_method_is_refused_before_a_run(self):
        from framefix_wb import runs
        from framefix_wb.errors import FrameFixError
        with self.assertRaises(FrameFixError) as e:
            runs.check_method("extrude-sheets")
        self.assertIn("extrude-sheets", str(e.exception))
        self.assertIn("extrude-curves", str(e.exception))  # the names it offers instead
