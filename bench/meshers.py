#!/usr/bin/python3
"""TetGen against gmsh's HXT (`--mesher hxt`), on the same tagged surface, and gmsh itself side by
side. A benchmark: run it by hand on an otherwise idle machine, never as a test.

    /usr/bin/python3 bench/meshers.py compare [--folder DIR]... [--sizes 0.6,1,1.5] [--threads 2]
    /usr/bin/python3 bench/meshers.py speed [--part samples/notch.step] [--size 0.02045] [--threads 2]

compare: every sample (and every model of each --folder) at each size factor with both meshers:
tets, mesh seconds, the smallest dihedral angle, the share of tets with one below 10 degrees, and
the singularity graph (valence-3 / valence-5 / 3-5 curves / invalid nodes / meshable); the last
line counts the models whose graphs agree.
speed: one large mesh with each mesher, best of --repeats, and gmsh's own HXT from the STEP file
at the characteristic length that gives the same mean edge; tets per second and the ratio to gmsh.
"""
import argparse
import math
import os
import re
import subprocess
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, os.path.join(ROOT, "build", "python"))
import framefix  # noqa: E402

MESHERS = ["tetgen", "hxt"]
SLIVER_DEG = 10.0  # a dihedral angle below this marks a sliver
# gmsh's mean edge is about 1.41 of its characteristic length (docs/results.md, tet density).
GMSH_MEAN_EDGE_PER_CL = 1.41


def dihedral_angles(points, tets):
    """The 6 dihedral angles of every tet, degrees (#T x 6)."""
    p = points[tets]
    faces = [(1, 2, 3), (0, 3, 2), (0, 1, 3), (0, 2, 1)]
    normals = []
    for a, b, c in faces:
        n = np.cross(p[:, b] - p[:, a], p[:, c] - p[:, a])
        normals.append(n / np.linalg.norm(n, axis=1, keepdims=True))
    angles = []
    for i in range(4):
        for j in range(i + 1, 4):
            cos = -np.einsum("ij,ij->i", normals[i], normals[j])
            angles.append(np.degrees(np.arccos(np.clip(cos, -1.0, 1.0))))
    return np.stack(angles, axis=1)


def graph_key(summary):
    return "%d/%d/%d/%d%s" % (summary["valence3"], summary["valence5"], summary["curves_3_5"],
                              summary["invalid_nodes"], " M" if summary["meshable"] else "")


def one_run(part, mesher, factor, threads):
    r = framefix.run(part, "singularities", method="none", size_factor=factor, threads=threads, mesher=mesher)
    rep = framefix.report(r)
    angles = dihedral_angles(np.asarray(r.mesh.points), np.asarray(r.mesh.tets))
    return {"tets": rep["mesh"]["tets"], "seconds": rep["timings_s"]["mesh"], "min_dihedral": float(angles.min()),
            "slivers": float((angles.min(axis=1) < SLIVER_DEG).mean()), "mesher": rep["mesh"].get("mesher", "?"),
            "graph": graph_key(rep["singularities"]["summary"])}


def models(folders):
    found = sorted(os.path.join(ROOT, "samples", f) for f in os.listdir(os.path.join(ROOT, "samples")) if f.endswith(".step"))
    for folder in folders:
        found += sorted(os.path.join(folder, f) for f in os.listdir(folder)
                        if f.lower().endswith((".step", ".stp", ".brep", ".iges", ".igs")))
    return found


def compare(args):
    print("| model | x | tets T / H | mesh s T / H | min dihedral T / H | slivers % T / H | graph T | graph H |")
    print("|---|---|---|---|---|---|---|---|")
    same = total = faster = 0
    for part in models(args.folder):
        for factor in [float(f) for f in args.sizes.split(",")]:
            try:
                t, h = (one_run(part, m, factor, args.threads) for m in MESHERS)
            except framefix.Error as e:
                print("| %s | %g | failed: %s |" % (os.path.basename(part), factor, str(e)[:80]))
                continue
            total += 1
            same += t["graph"] == h["graph"]
            faster += h["seconds"] < t["seconds"]
            print("| %s | %g | %d / %d | %.2f / %.2f | %.1f / %.1f | %.2f / %.2f | %s | %s%s |" % (
                os.path.basename(part), factor, t["tets"], h["tets"], t["seconds"], h["seconds"], t["min_dihedral"],
                h["min_dihedral"], 100 * t["slivers"], 100 * h["slivers"], t["graph"], h["graph"],
                "" if h["mesher"] == "hxt" else " (fell back to %s)" % h["mesher"]))
            sys.stdout.flush()
    print("\nsame graph: %d of %d model-size pairs; HXT faster on %d" % (same, total, faster))


def gmsh_run(part, cl, threads):
    """gmsh's own HXT from the CAD file: tets, meshing seconds (1D + 2D + 3D), wall seconds."""
    out = "/tmp/framefix-bench-gmsh.msh"
    t0 = time.time()
    done = subprocess.run(["gmsh", part, "-3", "-clmax", "%.6g" % cl, "-setnumber", "Mesh.Algorithm3D", "10",
                           "-nt", str(threads), "-o", out], capture_output=True, text=True)
    wall = time.time() - t0
    log = done.stdout + done.stderr
    seconds = sum(float(s) for s in re.findall(r"Done meshing \dD \(Wall ([0-9.e+-]+)s", log))
    tets = [int(n) for n in re.findall(r"contains (\d+) tetrahedra", log)]
    return (tets[-1] if tets else 0), seconds, wall


def speed(args):
    print("| mesher | tets | mean edge | seconds | tets per second |")
    print("|---|---|---|---|---|")
    rates = {}
    for mesher in MESHERS:
        best = None
        for _ in range(args.repeats):
            r = framefix.run(args.part, "mesh", size=args.size, threads=args.threads, mesher=mesher)
            rep = framefix.report(r)
            row = (rep["timings_s"]["mesh"], rep["mesh"]["tets"], rep["mesh"]["mean_edge"])
            best = row if best is None or row[0] < best[0] else best
        rates[mesher] = best[1] / best[0]
        print("| FrameFix, %s (mesh stage) | %d | %.4g | %.2f | %.0fk |" % (mesher, best[1], best[2], best[0], rates[mesher] / 1e3))
    cl = args.size / GMSH_MEAN_EDGE_PER_CL
    best = None
    for _ in range(args.repeats):
        row = gmsh_run(args.part, cl, args.threads)
        best = row if best is None or row[1] < best[1] else best
    tets, seconds, wall = best
    print("| gmsh HXT, -clmax %.4g (1D+2D+3D) | %d | - | %.2f (%.2f wall) | %.0fk |" % (cl, tets, seconds, wall, tets / seconds / 1e3))
    for mesher in MESHERS:
        print("\n%s: %.2f x gmsh's tets per second" % (mesher, rates[mesher] / (tets / seconds)), end="")
    print()


def main():
    p = argparse.ArgumentParser()
    sub = p.add_subparsers(dest="command", required=True)
    c = sub.add_parser("compare")
    c.add_argument("--folder", action="append", default=[])
    c.add_argument("--sizes", default="0.6,1,1.5")
    c.add_argument("--threads", type=int, default=2)
    s = sub.add_parser("speed")
    s.add_argument("--part", default=os.path.join(ROOT, "samples", "notch.step"))
    s.add_argument("--size", type=float, default=0.02045)
    s.add_argument("--threads", type=int, default=2)
    s.add_argument("--repeats", type=int, default=3)
    args = p.parse_args()
    compare(args) if args.command == "compare" else speed(args)


if __name__ == "__main__":
    main()
