#!/usr/bin/env python3
"""Runs `framefix analyze` (or `correct`, or `hexmesh`) on every CAD model of a folder (such as
the HexMe set) and prints a table of summaries and timings. Not part of ctest.

    /usr/bin/python3 scripts/run_hexme.py --folder DIR [--command correct|hexmesh] [--method M] [--size-factor F] [--threads N]

With `hexmesh` the table has the blocks and the hex mesh: hexes, the smallest scaled Jacobian,
inverted hexes, the volume error against the part, or why there is no hex mesh.
"""
import argparse
import json
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def hexmesh_cells(out, code):
    """The hexmesh table's cells after model and exit code."""
    if code != 0:
        return ["-"] * 10
    rep = json.loads((out / "report.json").read_text())
    b, h = rep["blocks"], rep["hexmesh"]
    cells = [str(rep["mesh"]["tets"]), str(rep["singularities"]["summary"]["meshable"]), str(b["count"]),
             str(b["valid"]), f"{b['conforming_pairs']}/{b['pairs']}"]
    if not h["done"]:
        return cells + [f"none: {h['reason'][:60]}", "-", "-", "-", f"{h['seconds']:.2f}"]
    error = 100 * (h["volume"] - h["part_volume"]) / h["part_volume"]
    return cells + [str(h["hexes"]), f"{h['min_scaled_jacobian']:.2f}", str(h["inverted"]), f"{error:+.2f}",
                    f"{h['seconds']:.2f}"]


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--folder", required=True, help="folder of .step/.stp/.brep/.iges/.igs models")
    p.add_argument("--command", default="analyze", choices=["mesh", "analyze", "correct", "hexmesh"])
    p.add_argument("--method", default=None, help="correction method of correct/hexmesh (default: the backend's)")
    p.add_argument("--size-factor", default="1")
    p.add_argument("--threads", default="0", help="backend threads, 0 = all cores")
    p.add_argument("--out", default="/tmp/framefix-hexme")
    p.add_argument("--timeout", type=float, default=1800)
    args = p.parse_args()
    binary = ROOT / "build" / "bin" / "framefix"
    models = sorted(x for x in Path(args.folder).iterdir() if x.suffix.lower() in (".step", ".stp", ".brep", ".iges", ".igs"))
    hexes = args.command == "hexmesh"
    if hexes:
        print("| model | exit | tets | meshable | blocks | valid | conforming pairs | hexes | min SJ | inverted | volume error % | hex s | seconds |")
        print("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    else:
        print(f"| model | exit | tets | curves | val3 | val5 | 3-5 | invalid nodes | meshable | after 3-5 | after meshable | seconds |")
        print("|---|---|---|---|---|---|---|---|---|---|---|---|")
    for m in models:
        out = Path(args.out) / m.stem
        t0 = time.time()
        try:
            r = subprocess.run([str(binary), args.command, str(m), "--out", str(out), "--quiet",
                                "--size-factor", args.size_factor, "--threads", args.threads]
                               + (["--method", args.method] if args.method else []), capture_output=True, text=True, timeout=args.timeout)
            code, err = r.returncode, r.stderr.strip().splitlines()[-1:] if r.stderr.strip() else []
        except subprocess.TimeoutExpired:
            code, err = "timeout", []
        dt = time.time() - t0
        row = [m.name, str(code)]
        if hexes:
            print("| " + " | ".join(row + hexmesh_cells(out, code) + [f"{dt:.1f}"]) + " |", flush=True)
            continue
        if code == 0:
            rep = json.loads((out / "report.json").read_text())
            s = rep.get("singularities", {}).get("summary", {})
            c = rep.get("correction", {})
            before = c.get("before", s)
            row += [str(rep["mesh"]["tets"]), str(before.get("curves", "-")), str(before.get("valence3", "-")),
                    str(before.get("valence5", "-")), str(before.get("curves_3_5", "-")),
                    str(before.get("invalid_nodes", "-")), str(before.get("meshable", "-")),
                    str(c.get("after", {}).get("curves_3_5", "-")), str(c.get("after", {}).get("meshable", "-"))]
        else:
            row += ["-"] * 9
            if err:
                row[0] += f" ({err[0][:80]})"
        row.append(f"{dt:.1f}")
        print("| " + " | ".join(row) + " |", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
