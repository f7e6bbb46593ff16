#!/usr/bin/python3
"""Scaling table of the whole pipeline: `framefix hexmesh PART --method M` at sizes giving about
50k, 200k, 1M and 2M tets; per run the tets, the seconds of each stage, the hexes and hexes per
second of the hex mesh stage, the peak memory, and MBO's iterations on the part's first field
(the analysis) and on the corrected one ("(cap)": stopped at the cap, not converged).

    /usr/bin/python3 bench/scaling.py [--part samples/notch.step] [--method snap] [--threads 2]
                                      [--mesher tetgen|hxt] [--json OUT.json]

Prints a Markdown table; --json also writes the rows for scripts/plot_scaling.py. A benchmark:
run it by hand on an otherwise idle machine, never as a test.
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
TARGETS = [50e3, 200e3, 1e6, 2e6]  # tets; the default size gives about the first
STAGES = ["load", "mesh", "field", "singularities", "correct", "blocks", "hexmesh"]


def run(binary, part, method, mesher, factor, threads, out):
    cmd = [binary, "hexmesh", part, "--method", method, "--size-factor", "%.4f" % factor, "--mesher", mesher,
           "--threads", str(threads), "--out", out, "--quiet"]
    done = subprocess.run(cmd, capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit("scaling: %s failed: %s" % (" ".join(cmd), done.stderr.strip()))
    with open(os.path.join(out, "report.json")) as f:
        report = json.load(f)
    row = {"target": factor, "tets": report["mesh"]["tets"], "peak_mb": report["peak_memory_mb"],
           "mbo_iterations": report["field"]["iterations"], "mbo_converged": report["field"]["converged"]}
    analysis = report.get("correction", {}).get("field_before", report["field"])  # the part's first field
    row.update({"analysis_mbo_iterations": analysis["iterations"], "analysis_mbo_converged": analysis["converged"]})
    row.update({s: report["timings_s"].get(s, 0.0) for s in STAGES + ["total"]})
    hexmesh = report.get("hexmesh", {})
    row["hexes"] = hexmesh.get("hexes", 0)
    row["hexes_per_s"] = hexmesh.get("hexes_per_second", 0.0)
    return row


def mbo(row, key):
    return "%d%s" % (row[key + "_iterations"], "" if row[key + "_converged"] else " (cap)")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--part", default=os.path.join(ROOT, "samples", "notch.step"))
    ap.add_argument("--method", default="snap")
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--mesher", default="tetgen", choices=["tetgen", "hxt"])
    ap.add_argument("--binary", default=os.path.join(ROOT, "build", "bin", "framefix"))
    ap.add_argument("--json")
    a = ap.parse_args()
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for i, tets in enumerate(TARGETS):
            factor = (TARGETS[0] / tets) ** (1.0 / 3.0)  # tets scale as size^-3
            rows.append(run(a.binary, a.part, a.method, a.mesher, factor, a.threads, os.path.join(tmp, str(i))))
    print("| tets | " + " | ".join(STAGES) +
          " | total s | peak MB | hexes | hexes/s | MBO iterations, analysis | MBO iterations, corrected |")
    print("|---" * (len(STAGES) + 7) + "|")
    for r in rows:
        print("| {:,} | ".format(r["tets"]) + " | ".join("%.2f" % r[s] for s in STAGES) +
              " | %.1f | %.0f | %d | %.0f | %s | %s |" % (r["total"], r["peak_mb"], r["hexes"], r["hexes_per_s"],
                                                        mbo(r, "analysis_mbo"), mbo(r, "mbo")))
    if a.json:
        with open(a.json, "w") as f:
            json.dump({"part": a.part, "method": a.method, "mesher": a.mesher, "threads": a.threads, "rows": rows}, f, indent=1)


if __name__ == "__main__":
    main()
