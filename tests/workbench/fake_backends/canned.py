#!/usr/bin/python3
"""Fake backend for GUI and object plumbing tests: the CLI's interface, a canned report.

NOT an oracle: its curves are made up. FAKE_BACKEND_LOG (if set) gets one line per run, so
tests can count reruns; FAKE_BACKEND_DELAY slows the progress lines down (seconds each).
`blocks` cuts the unit cube's 6 Kuhn tets into 2 made-up blocks (block 1 invalid); `hexmesh`
does the same and meshes the cube as one hex.
`info` prints INFO (the contract of the real `framefix info`); `correct` and `blocks` refuse,
as the real backend does, every method INFO does not offer as available.
"""
import json
import os
import sys
import time


# the unit cube's corners (bit 0: x, 1: y, 2: z) and its 6 Kuhn tets around the diagonal 0-7
CUBE = [[i & 1, (i >> 1) & 1, (i >> 2) & 1] for i in range(8)]
KUHN = [[0, 1, 3, 7], [0, 3, 2, 7], [0, 2, 6, 7], [0, 6, 4, 7], [0, 4, 5, 7], [0, 5, 1, 7]]
# The cube's 12 boundary triangles: the first 6 bound block 0, the last 6 block 1.
CUBE_TRIANGLES = [[0, 2, 3], [0, 3, 1], [4, 5, 7], [4, 7, 6], [0, 1, 5], [0, 5, 4],
                  [2, 6, 7], [2, 7, 3], [0, 4, 6], [0, 6, 2], [1, 3, 7], [1, 7, 5]]


INFO = {
    "version": 1, "default_target_tets": 50000, "mean_tet_volume_h3": 0.085,
    "correction_methods": [
        {"name": "auto", "available": True,
         "description": "try the methods and keep the best"},
        {"name": "snap", "available": True,
         "description": "snap 3-5 curves onto the boundary (the paper's recommendation)"},
        {"name": "fillet", "available": False,
         "description": "round the edges the 3-5 curves end on"},
        {"name": "extrude-curves", "available": False,
         "description": "extrude feature curves to move the 3-5 curves away"},
        {"name": "extrude-nodes", "available": False,
         "description": "extrude around invalid singular nodes"}],
    "block_methods": ["auto", "snap", "none"]}


def refusal(command, method):
    """The real backend's message for a method it does not run (None: it runs it)."""
    if command == "blocks":
        names = INFO["block_methods"]
    else:
        offered = {m["name"]: m for m in INFO["correction_methods"]}
        names = list(offered)
        if method in offered and not offered[method]["available"]:
            return ("framefix: error [correct]: method '%s' is not available yet; use one of %s"
                    % (method, ", ".join(n for n in names if offered[n]["available"])))
    if method not in names:
        return "framefix: error [cli]: unknown method '%s'; use one of %s" % (
            method, ", ".join(names))
    return None


def write_blocks(report, out):
    """Report section and blocks.vtk: tets 0-2 block 0 (valid), 3-5 block 1 (invalid)."""
    tet_block, valid = [0, 0, 0, 1, 1, 1], [1, 0]
    report["blocks"] = {
        "count": 2, "valid": 1, "conforming_pairs": 0, "pairs": 1, "flat_corners": 0,
        "flat_edges": 1, "seconds": {"total": 0.01}, "neighbour_pairs": [
            {"blocks": [0, 1], "conforming": False, "reason": "made up"}],
        "blocks": [{"id": b, "tets": 3, "volume": 0.5, "valid": bool(valid[b]), "faces": 6,
                    "edges": 12, "corners": 8, "flat_edges": b, "flat_corners": 0,
                    "neighbours": [1 - b], "centroid": [0.5, 0.5, 0.5],
                    "reason": "" if valid[b] else "made up"} for b in range(2)]}
    lines = ["# vtk DataFile Version 3.0", "canned blocks", "ASCII", "DATASET UNSTRUCTURED_GRID",
             "POINTS 8 double"] + ["%d %d %d" % tuple(p) for p in CUBE]
    lines += ["CELLS 6 30"] + ["4 %d %d %d %d" % tuple(t) for t in KUHN]
    lines += ["CELL_TYPES 6"] + ["10"] * 6 + ["CELL_DATA 6", "SCALARS block double 1",
                                              "LOOKUP_TABLE default"] + [str(b) for b in tet_block]
    lines += ["SCALARS block_valid double 1", "LOOKUP_TABLE default"]
    lines += [str(valid[b]) for b in tet_block]
    with open(os.path.join(out, "blocks.vtk"), "w") as f:
        f.write("\n".join(lines) + "\n")
    write_cells(os.path.join(out, "block_surfaces.vtk"), CUBE_TRIANGLES, 5, [0] * 6 + [1] * 6)
    write_cells(os.path.join(out, "block_edges.vtk"), [[0, 1, 3], [4, 5, 7, 6]], 4, [0, 1])


def write_cells(path, cells, cell_type, block):
    """A legacy VTK grid of the cube's points with `cells` of one type and a block per cell."""
    lines = ["# vtk DataFile Version 3.0", "canned", "ASCII", "DATASET UNSTRUCTURED_GRID",
             "POINTS 8 double"] + ["%d %d %d" % tuple(p) for p in CUBE]
    lines += ["CELLS %d %d" % (len(cells), sum(len(c) + 1 for c in cells))]
    lines += [" ".join(str(i) for i in [len(c)] + c) for c in cells]
    lines += ["CELL_TYPES %d" % len(cells)] + [str(cell_type)] * len(cells)
    lines += ["CELL_DATA %d" % len(cells), "SCALARS block double 1", "LOOKUP_TABLE default"]
    lines += [str(b) for b in block]
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def write_hexmesh(report, out, order):
    """Report section and hex.vtk: the unit cube as one hex (block 0), scaled Jacobian 1; at
    order 2 with its 12 edge midpoints."""
    corners = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]
    edges = [(0, 1), (1, 2), (2, 3), (3, 0), (4, 5), (5, 6), (6, 7), (7, 4), (0, 4), (1, 5), (2, 6), (3, 7)]
    points = corners + ([tuple((a + b) / 2 for a, b in zip(corners[i], corners[j])) for i, j in edges]
                        if order == 2 else [])
    n = len(points)
    report["hexmesh"] = {"done": True, "hexes": 1, "vertices": n, "order": order, "size": 1.0,
                         "min_scaled_jacobian": 1.0, "mean_scaled_jacobian": 1.0,
                         "share_sj_ge_0_5": 1.0, "inverted": 0, "volume": 1.0, "part_volume": 1.0,
                         "blocks": [{"counts": [1, 1, 1], "hexes": 1, "min_scaled_jacobian": 1.0}]}
    lines = ["# vtk DataFile Version 3.0", "canned hexes", "ASCII", "DATASET UNSTRUCTURED_GRID",
             "POINTS %d double" % n] + ["%g %g %g" % p for p in points]
    lines += ["CELLS 1 %d" % (n + 1), " ".join(map(str, [n] + list(range(n)))),
              "CELL_TYPES 1", "12" if order == 1 else "25", "CELL_DATA 1",
              "SCALARS block double 1", "LOOKUP_TABLE default", "0",
              "SCALARS scaled_jacobian double 1", "LOOKUP_TABLE default", "1"]
    with open(os.path.join(out, "hex.vtk"), "w") as f:
        f.write("\n".join(lines) + "\n")


def main(argv):
    if argv[:1] == ["info"]:
        print(json.dumps(INFO, indent=1))
        return 0
    if len(argv) < 4 or argv[0] not in ("analyze", "correct", "blocks", "hexmesh") or "--out" not in argv:
        print("framefix: error [cli]: usage: framefix analyze|correct|blocks|hexmesh PART [--size H] "
              "[--method M] --out DIR", file=sys.stderr)
        return 2
    part, out = argv[1], argv[argv.index("--out") + 1]
    size = float(argv[argv.index("--size") + 1]) if "--size" in argv else 0.1
    if not os.path.isfile(part) or os.path.getsize(part) == 0:
        print("framefix: error [load]: cannot read %s" % part, file=sys.stderr)
        return 2
    if os.environ.get("FAKE_BACKEND_LOG"):
        with open(os.environ["FAKE_BACKEND_LOG"], "a") as f:
            f.write("%s %s size=%r\n" % (argv[0], os.path.basename(part), size))
    delay = float(os.environ.get("FAKE_BACKEND_DELAY", "0.02"))
    stages = ["load", "mesh", "field", "singularities"]
    method = argv[argv.index("--method") + 1] if "--method" in argv else (
        "auto" if argv[0] != "analyze" else "")
    hexmesh = argv[0] == "hexmesh"  # blocks, then a hex mesh of them
    if hexmesh:
        argv = ["blocks"] + argv[1:]
    refused = refusal(argv[0], method) if argv[0] != "analyze" else None
    if refused:
        print(refused, file=sys.stderr)
        return 2
    if argv[0] == "blocks":
        stages += ["correct", "blocks"] if method != "none" else ["blocks"]
        stages += ["hexmesh"] if hexmesh else []
    for stage in stages:
        for fraction in (0.0, 0.5, 1.0):
            print("progress %s %.2f" % (stage, fraction), file=sys.stderr, flush=True)
            time.sleep(delay)
    print("fake backend: canned report", flush=True)
    curves = [
        {"id": 0, "kind": "valence3", "length": 1.0, "ends": [0, 1],
         "points": [[0.2, 0.2, 0.0], [0.2, 0.2, 0.5], [0.2, 0.2, 1.0]]},
        {"id": 1, "kind": "valence5", "length": 1.0, "ends": [2, 3],
         "points": [[0.8, 0.2, 0.0], [0.8, 0.2, 1.0]]},
        {"id": 2, "kind": "3-5", "length": 0.8, "ends": [4, 5],
         "points": [[0.5, 0.5, 0.1], [0.45, 0.5, 0.5], [0.5, 0.5, 0.9]]},
    ]
    nodes = [{"id": 0, "position": [0.5, 0.5, 0.5], "boundary": False, "n3": 1, "n5": 1,
              "valid": False},
             {"id": 1, "position": [0.2, 0.2, 1.0], "boundary": True, "n3": 1, "n5": 0,
              "valid": True}]
    summary = {"curves": 3, "valence3": 1, "valence5": 1, "curves_3_5": 1, "nodes": 2,
               "invalid_nodes": 1, "meshable": False}
    report = {"version": 1, "input": {"path": part, "kind": "brep"},
              "mesh": {"vertices": 100, "tets": 321, "size": size},
              "features": {"curves": 2, "by_valence": {"1": 1, "3": 1}},
              "feature_curves": [{"edge": 1, "valence": 1, "points": []},
                                 {"edge": 2, "valence": 3,
                                  "points": [[0, 0, 1], [1, 0, 1]]}],
              "singularities": {"curves": curves, "nodes": nodes, "summary": summary},
              "timings_s": {"total": 0.1}, "peak_memory_mb": 1.0}
    os.makedirs(out, exist_ok=True)
    if argv[0] == "correct" or (argv[0] == "blocks" and method != "none"):
        # the 3-5 curve is gone after the correction
        report["correction"] = {"method": method, "chosen": "snap" if method == "auto" else "",
                                "before": dict(summary), "changed_curves": 1,
                                "snapped_paths": [{"source_curve": 2, "points": [
                                    [0.5, 0.0, 0.1], [0.5, 0.0, 0.9]]}]}
        report["singularities"]["curves"] = curves[:2]
        report["singularities"]["summary"] = dict(summary, curves=2, curves_3_5=0,
                                                  invalid_nodes=0, meshable=True)
    if argv[0] == "blocks":
        write_blocks(report, out)
    if hexmesh:
        write_hexmesh(report, out, order=int(argv[argv.index("--order") + 1]) if "--order" in argv else 1)
    with open(os.path.join(out, "report.json"), "w") as f:
        json.dump(report, f)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
