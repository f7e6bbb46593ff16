"""Build FrameFix's sample parts (samples/README.md) as STEP files, and the bad inputs
the loader tests use.

Run with the interpreter FreeCAD embeds, from anywhere:
    /usr/bin/python3 samples/make_samples.py [SAMPLE...]
It writes samples/*.step and tests/data/* next to this script, or only the samples named. The
output is committed; rerun only to change a model.
"""
import os
import sys

sys.path.append('/usr/lib/freecad-python3/lib')
import FreeCAD  # noqa: E402
import Part  # noqa: E402

V = FreeCAD.Vector
HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.join(os.path.dirname(HERE), 'tests', 'data')


def single_solid(shape, name):
    solids = shape.Solids
    if len(solids) != 1:
        raise RuntimeError('%s: %d solids' % (name, len(solids)))
    solid = solids[0]
    if not solid.isValid():
        raise RuntimeError('%s: invalid solid' % name)
    return solid


def imprint(solid, edges):
    """The solid with `edges` (lying on its faces) imprinted: split faces, same geometry."""
    pieces, _ = solid.generalFuse(edges)
    return single_solid(pieces, 'imprint')


def notch():
    box = Part.makeBox(1, 1, 1)
    pocket = Part.makeCylinder(0.5, 1, V(1, 1, 0.5), V(0, 0, 1))
    return box.cut(pocket).removeSplitter()


def box_arc():
    box = Part.makeBox(1, 1, 0.5)
    arc = Part.makeCircle(0.5, V(1, 1, 0.5), V(0, 0, 1), 180, 270)
    return imprint(box, [arc])


def curved_box_arc(roof_radius, arc_radius):
    """box [0,1]^3 under a roof cylinder (axis along x, 0.5 high in the middle), its top split by
    the vertical cylinder of `arc_radius` around (1, 1)."""
    box = Part.makeBox(1, 1, 1)
    roof = Part.makeCylinder(roof_radius, 1, V(0, 0.5, 0.5 - roof_radius), V(1, 0, 0))
    part = box.common(roof).removeSplitter()
    top = [f for f in part.Faces if f.Surface.__class__.__name__ == 'Cylinder'][0]
    cutter = Part.makeCylinder(arc_radius, 2, V(1, 1, -0.5), V(0, 0, 1))
    lateral = [f for f in cutter.Faces if f.Surface.__class__.__name__ == 'Cylinder'][0]
    return imprint(part, top.section(lateral).Edges)


def box_arc_curved():
    # Top face: a cylinder of radius 2 with a horizontal axis along x, 0.5 high in the middle.
    return curved_box_arc(2, 0.5)


def box_arc_wide():
    """A box_arc variant: a flat 1.5 x 1 x 0.4 box, the imprinted quarter circle r = 0.7."""
    box = Part.makeBox(1.5, 1, 0.4)
    arc = Part.makeCircle(0.7, V(1.5, 1, 0.4), V(0, 0, 1), 180, 270)
    return imprint(box, [arc])


def box_arc_small():
    """A box_arc variant: a 1 x 1 x 0.8 box, the imprinted quarter circle r = 0.3."""
    box = Part.makeBox(1, 1, 0.8)
    arc = Part.makeCircle(0.3, V(1, 1, 0.8), V(0, 0, 1), 180, 270)
    return imprint(box, [arc])


def box_arc_curved_flat():
    """A box_arc_curved variant: a flatter roof (r = 3), the arc r = 0.4."""
    return curved_box_arc(3, 0.4)


def box_arc_curved_steep():
    """A box_arc_curved variant: a steeper roof (r = 1.2), the arc r = 0.6."""
    return curved_box_arc(1.2, 0.6)


def half_sphere_box():
    box = Part.makeBox(2, 2, 1, V(-1, -1, -1))
    dome = Part.makeSphere(0.6, V(0, 0, 0), V(0, 0, 1), 0, 90)
    return box.fuse(dome).removeSplitter()


def groove():
    box = Part.makeBox(1, 1, 1)
    ring = Part.makeCylinder(0.6, 0.4, V(1, 1, 0.8)).cut(Part.makeCylinder(0.4, 0.4, V(1, 1, 0.8)))
    return box.cut(ring).removeSplitter()


def two_cylinders():
    body = Part.makeCylinder(1, 4, V(-2, 0, 0), V(1, 0, 0))
    boss = Part.makeCylinder(0.5, 2, V(0, 0, 0), V(0, 0, 1))
    return body.fuse(boss).removeSplitter()


def notch_wide():
    """A notch variant: a 2 x 1 x 0.8 box, a pocket of radius 0.7 down to z = 0.3."""
    box = Part.makeBox(2, 1, 0.8)
    return box.cut(Part.makeCylinder(0.7, 1, V(2, 1, 0.3), V(0, 0, 1))).removeSplitter()


def notch_shallow():
    """A notch variant: a unit cube, a pocket of radius 0.3 only 0.2 deep."""
    box = Part.makeBox(1, 1, 1)
    return box.cut(Part.makeCylinder(0.3, 1, V(1, 1, 0.8), V(0, 0, 1))).removeSplitter()


def half_sphere_box_small():
    """A half-sphere box variant: a dome of radius 0.4 on a 2 x 2 x 0.6 box."""
    box = Part.makeBox(2, 2, 0.6, V(-1, -1, -0.6))
    return box.fuse(Part.makeSphere(0.4, V(0, 0, 0), V(0, 0, 1), 0, 90)).removeSplitter()


def half_sphere_box_large():
    """A half-sphere box variant: a dome of radius 0.8 on a 2.4 x 2.4 x 1 box."""
    box = Part.makeBox(2.4, 2.4, 1, V(-1.2, -1.2, -1))
    return box.fuse(Part.makeSphere(0.8, V(0, 0, 0), V(0, 0, 1), 0, 90)).removeSplitter()


def groove_wide():
    """A groove variant: radii 0.3 to 0.7, 0.3 deep."""
    box = Part.makeBox(1, 1, 1)
    ring = Part.makeCylinder(0.7, 0.3, V(1, 1, 0.7)).cut(Part.makeCylinder(0.3, 0.3, V(1, 1, 0.7)))
    return box.cut(ring).removeSplitter()


def groove_narrow():
    """A groove variant: radii 0.45 to 0.55, 0.15 deep, in a 1.2 x 1.2 x 0.8 box."""
    box = Part.makeBox(1.2, 1.2, 0.8)
    ring = Part.makeCylinder(0.55, 0.15, V(1.2, 1.2, 0.65)).cut(Part.makeCylinder(0.45, 0.15, V(1.2, 1.2, 0.65)))
    return box.cut(ring).removeSplitter()


def circle_edges(shape, radius, z):
    """The circular edges of `shape` of this radius lying in the plane at height z."""
    found = []
    for e in shape.Edges:
        try:
            circle = e.Curve.__class__.__name__ == 'Circle'
        except TypeError:  # a degenerate edge (a sphere's pole) has no curve
            continue
        if circle and abs(e.Curve.Radius - radius) < 1e-9 and abs(e.BoundBox.ZMin - z) < 1e-9 and abs(e.BoundBox.ZMax - z) < 1e-9:
            found.append(e)
    return found


def notch_filleted():
    """The paper's Fig. 1b: the notch with its concave floor arc filleted, r = 0.05."""
    part = notch()
    return part.makeFillet(0.05, circle_edges(part, 0.5, 0.5))


def half_sphere_box_filleted():
    """The paper's Fig. 3b: the half-sphere box with its concave circle filleted, r = 0.1."""
    part = half_sphere_box()
    return part.makeFillet(0.1, circle_edges(part, 0.6, 0.0))


def groove_filleted():
    """The paper's Fig. 5b: the groove with its two concave floor arcs filleted, r = 0.05."""
    part = groove()
    return part.makeFillet(0.05, circle_edges(part, 0.4, 0.8) + circle_edges(part, 0.6, 0.8))


def groove_wide_filleted():
    """The paper's Fig. 5b proper: every curve of groove_wide's groove, floor arcs (concave) and
    rims (convex), filleted, r = 0.08: the groove becomes smooth."""
    part = groove_wide()
    arcs = [e for r in (0.3, 0.7) for z in (0.7, 1.0) for e in circle_edges(part, r, z)]
    return part.makeFillet(0.08, arcs)


def cube():
    return Part.makeBox(1, 1, 1)


def cylinder():
    return Part.makeCylinder(0.5, 1)


def sphere():
    """The smooth part whose field is known: a cube inside a sphere (20 valence-3 curves, 7 blocks)."""
    return Part.makeSphere(0.5)


def rounded_box():
    """A machined block: a 1.2 x 1 x 0.8 box with every edge filleted, r = 0.15. Like the sphere, a
    box inside (20 valence-3 curves, 7 blocks), under cushions about 0.1 thick: under 3 h at the
    default size, so its blocks need the finer mesh of docs/algorithms.md#thin-blocks."""
    box = Part.makeBox(1.2, 1, 0.8)
    return box.makeFillet(0.15, box.Edges)


def tube():
    """A machined bushing: a tube of radii 0.3 and 0.5, 0.6 long. No singular curve and no
    concave edge: nothing but its ring cuts it into blocks (docs/algorithms.md#ring-cuts)."""
    return Part.makeCylinder(0.5, 0.6).cut(Part.makeCylinder(0.3, 0.6))


def l_prism():
    pts = [V(0, 0, 0), V(1, 0, 0), V(1, 0.5, 0), V(0.5, 0.5, 0), V(0.5, 1, 0), V(0, 1, 0), V(0, 0, 0)]
    return Part.Face(Part.makePolygon(pts)).extrude(V(0, 0, 0.5))


def top_edges(box, z, along=None):
    """The box's edges at height z, all or only those along the axis `along` (0 x, 1 y)."""
    def flat(e):
        a, b = e.Vertexes[0].Point, e.Vertexes[-1].Point
        return abs(a.z - z) < 1e-9 and abs(b.z - z) < 1e-9
    def runs(e):
        a, b = e.Vertexes[0].Point, e.Vertexes[-1].Point
        return along is None or abs((a - b)[1 - along]) < 1e-9
    return [e for e in box.Edges if flat(e) and runs(e)]


def chamfer_box():
    """A machined block: a 2 x 1 x 0.6 box with its back top edge chamfered 0.25 (135 degree edges)."""
    box = Part.makeBox(2, 1, 0.6)
    back = [e for e in top_edges(box, 0.6, along=0) if e.Vertexes[0].Point.y > 0.5]
    return box.makeChamfer(0.25, back)


def chamfer_top():
    """The 2 x 1 x 0.6 box with all four top edges chamfered 0.15, mitred at the corners."""
    box = Part.makeBox(2, 1, 0.6)
    return box.makeChamfer(0.15, top_edges(box, 0.6))


def gusset():
    """An L bracket (2 long, legs 1 x 0.2) stiffened by a 45 degree triangular gusset 0.2 thick."""
    bracket = Part.makeBox(2, 0.2, 1).fuse(Part.makeBox(2, 1, 0.2))
    pts = [V(0.9, 0.2, 0.2), V(0.9, 0.8, 0.2), V(0.9, 0.2, 0.8), V(0.9, 0.2, 0.2)]
    web = Part.Face(Part.makePolygon(pts)).extrude(V(0.2, 0, 0))
    return bracket.fuse(web).removeSplitter()


SAMPLES = [notch, box_arc, box_arc_curved, half_sphere_box, groove, two_cylinders, cube, cylinder, l_prism,
           notch_filleted, half_sphere_box_filleted, groove_filleted,
           notch_wide, notch_shallow, half_sphere_box_small, half_sphere_box_large, groove_wide, groove_narrow,
           groove_wide_filleted, box_arc_wide, box_arc_small, box_arc_curved_flat, box_arc_curved_steep, sphere,
           rounded_box, tube, chamfer_box, chamfer_top, gusset]


def write_bad_inputs():
    os.makedirs(DATA, exist_ok=True)
    two = Part.makeCompound([Part.makeBox(1, 1, 1), Part.makeBox(1, 1, 1, V(2, 0, 0))])
    two.exportStep(os.path.join(DATA, 'two_solids.step'))
    box = Part.makeBox(1, 1, 1)
    Part.Shell(box.Faces[:5]).exportBrep(os.path.join(DATA, 'open_shell.brep'))
    box.Faces[0].exportBrep(os.path.join(DATA, 'face.brep'))
    with open(os.path.join(HERE, 'cube.step'), 'rb') as f:
        text = f.read()
    with open(os.path.join(DATA, 'truncated.step'), 'wb') as f:
        f.write(text[:len(text) // 2])
    with open(os.path.join(DATA, 'garbage.step'), 'w') as f:
        f.write('this is not a STEP file\n' * 20)
    open(os.path.join(DATA, 'empty.step'), 'w').close()
    # Good inputs in the other formats: the notch as IGES (loose faces, sewn by the loader) and BREP.
    notch_solid = Part.read(os.path.join(HERE, 'notch.step'))
    notch_solid.exportIges(os.path.join(DATA, 'notch.igs'))
    notch_solid.exportBrep(os.path.join(DATA, 'notch.brep'))


def thin_cap():
    """A spherical shell 0.4 thick on a radius of 20, cut below its pole: thin and curved, sound."""
    shell = Part.makeSphere(20).cut(Part.makeSphere(19.6))
    return shell.common(Part.makeBox(80, 80, 40, V(-40, -40, 6))).removeSplitter()


def looped_blade():
    """A blade lofted through two airfoil sections whose spline loops at the sharp trailing edge:
    BRepCheck passes it, OCCT's self-intersection check does not."""
    import math
    wires = []
    for z, chord, twist in [(0, 40, 0), (100, 25, 40)]:
        pts = []
        for i in range(16):
            x = 0.5 * (1 + math.cos(2 * math.pi * i / 16))
            yt = 0.6 * (0.2969 * math.sqrt(x) - 0.126 * x - 0.3516 * x ** 2 + 0.2843 * x ** 3 - 0.1036 * x ** 4)
            y = 0.16 * x * (1 - x) + (yt if i < 8 else -yt) * (i != 0)
            c, s = math.cos(math.radians(twist)), math.sin(math.radians(twist))
            px, py = (x - 0.3) * chord, y * chord
            pts.append(V(c * px - s * py, s * px + c * py, z))
        curve = Part.BSplineCurve()
        curve.interpolate(pts, PeriodicFlag=True)
        wires.append(Part.Wire([curve.toShape()]))
    solid = Part.makeLoft(wires, True, False).Solids[0]
    return solid if solid.Volume > 0 else solid.reversed()


def write_meshing_cases():
    """Parts that test the meshing's own robustness (tests/cli/test_mesh_recovery.py)."""
    single_solid(thin_cap(), 'thin_cap').exportStep(os.path.join(DATA, 'thin_cap.step'))
    blade = looped_blade()
    if not blade.isValid():
        raise RuntimeError('looped_blade: BRepCheck must pass it')
    blade.exportStep(os.path.join(DATA, 'looped_blade.step'))


def main(names):
    """Every sample and the test data, or only the samples named (the others keep their files)."""
    for make in SAMPLES:
        if names and make.__name__ not in names:
            continue
        solid = single_solid(make(), make.__name__)
        path = os.path.join(HERE, make.__name__ + '.step')
        solid.exportStep(path)
        print('%-16s faces %2d edges %2d volume %.5f' % (make.__name__, len(solid.Faces),
                                                          len(solid.Edges), solid.Volume))
    if not names:
        write_bad_inputs()
        write_meshing_cases()


if __name__ == '__main__':
    main(sys.argv[1:])
