#!/usr/bin/env python3
"""Writes parts that stress the mesh stage into a folder: thin curved shells, lofted blades (some
of which OCCT's self-intersection check flags) and seeded machined blocks with holes, counterbores,
filleted pockets and chamfers. For robustness runs, not for ctest:

    /usr/bin/python3 scripts/make_stress_parts.py DIR [--machined N]
    /usr/bin/python3 scripts/run_hexme.py --folder DIR --command mesh --size-factor 0.6
"""
import argparse
import math
import os
import random
import sys

sys.path.append('/usr/lib/freecad-python3/lib')
import FreeCAD  # noqa: E402
import Part  # noqa: E402

V = FreeCAD.Vector


def shell_sector(radius, thickness, angle_deg, height):
    outer = Part.makeCylinder(radius, height, V(0, 0, 0), V(0, 0, 1), angle_deg)
    return outer.cut(Part.makeCylinder(radius - thickness, height, V(0, 0, 0), V(0, 0, 1), angle_deg)).removeSplitter()


def sphere_cap(radius, thickness):
    shell = Part.makeSphere(radius).cut(Part.makeSphere(radius - thickness))
    return shell.common(Part.makeBox(4 * radius, 4 * radius, 2 * radius, V(-2 * radius, -2 * radius, 0.3 * radius)))


def airfoil(chord, thickness, camber, twist_deg, z, round_te, n=40):
    """Closed airfoil points: NACA thickness (sharp trailing edge) or a rounded sqrt profile."""
    pts = []
    for i in range(n):
        x = 0.5 * (1 + math.cos(2 * math.pi * i / n))
        if round_te:
            yt = 1.3 * thickness * math.sqrt(x * (1 - x)) * (1 - 0.4 * x)
        else:
            yt = 5 * thickness * (0.2969 * math.sqrt(x) - 0.126 * x - 0.3516 * x ** 2 + 0.2843 * x ** 3 - 0.1036 * x ** 4)
        y = camber * 4 * x * (1 - x) + (yt if i < n / 2 else -yt) * (i != 0)
        pts.append(((x - 0.3) * chord, y * chord))
    c, s = math.cos(math.radians(twist_deg)), math.sin(math.radians(twist_deg))
    return [V(c * x - s * y, s * x + c * y, z) for x, y in pts]


def blade(sections, twist_deg, round_te, span=100.0):
    wires = []
    for j in range(sections):
        f = j / (sections - 1)
        curve = Part.BSplineCurve()
        curve.interpolate(airfoil(40 - 15 * f, 0.12 - 0.04 * f, 0.05, twist_deg * f, span * f, round_te), PeriodicFlag=True)
        wires.append(Part.Wire([curve.toShape()]))
    solid = Part.makeLoft(wires, True, False).Solids[0]
    return solid if solid.Volume > 0 else solid.reversed()


def machined(seed):
    rng = random.Random(seed)
    length, width, height = 100.0, 60.0, rng.choice([15.0, 20.0, 30.0])
    part = Part.makeBox(length, width, height)
    for _ in range(rng.randint(3, 8)):
        r = rng.uniform(2, 6)
        x, y = rng.uniform(r + 3, length - r - 3), rng.uniform(r + 3, width - r - 3)
        part = part.cut(Part.makeCylinder(r, height + 2, V(x, y, -1)))
        if rng.random() < 0.4:
            part = part.cut(Part.makeCylinder(1.7 * r, 3, V(x, y, height - 3)))
    for _ in range(rng.randint(1, 3)):
        w, d = rng.uniform(10, 30), rng.uniform(8, 20)
        x, y, depth = rng.uniform(2, length - w - 2), rng.uniform(2, width - d - 2), rng.uniform(3, 0.6 * height)
        pocket = Part.makeBox(w, d, depth + 1, V(x, y, height - depth))
        vertical = [e for e in pocket.Edges if abs(e.tangentAt(e.FirstParameter).z) > 0.9]
        pocket = pocket.makeFillet(rng.uniform(1, 3), vertical)
        part = part.cut(pocket)
    if rng.random() < 0.5:
        bottom = [e for e in part.Edges if abs(e.BoundBox.ZMax) < 1e-6 and e.Length > 50]
        part = part.makeChamfer(1.5, bottom)
    return part.removeSplitter()


def parts(machined_count):
    yield 'shell_thin', lambda: shell_sector(50, 0.5, 90, 30)
    yield 'shell_mid', lambda: shell_sector(20, 1.0, 120, 40)
    yield 'cap_thin', lambda: sphere_cap(20, 0.4)
    for k, (sections, twist, round_te) in enumerate([(2, 40, False), (5, 40, False), (2, 30, True), (5, 60, True)]):
        yield 'blade%d' % k, lambda s=sections, t=twist, r=round_te: blade(s, t, r)
    for seed in range(machined_count):
        yield 'machined%02d' % seed, lambda s=seed: machined(s)


def main():
    p = argparse.ArgumentParser()
    p.add_argument('folder')
    p.add_argument('--machined', type=int, default=24)
    args = p.parse_args()
    os.makedirs(args.folder, exist_ok=True)
    for name, make in parts(args.machined):
        try:
            solids = make().Solids
        except Exception as e:  # a seed whose fillet or chamfer OCCT refuses
            print('%-12s not made: %s' % (name, e))
            continue
        if len(solids) != 1 or not solids[0].isValid():
            print('%-12s not made: %d solids' % (name, len(solids)))
            continue
        try:
            solids[0].check(True)
            bop = 'sound'
        except Exception:
            bop = 'self-intersecting (BOP check)'
        solids[0].exportStep(os.path.join(args.folder, name + '.step'))
        print('%-12s volume %10.1f  %s' % (name, solids[0].Volume, bop))


if __name__ == '__main__':
    main()
