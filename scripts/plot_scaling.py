#!/usr/bin/python3
"""Plot of bench/scaling.py's rows: seconds per stage against tets (log-log), and peak memory.

    /usr/bin/python3 scripts/plot_scaling.py SCALING.json docs/img/scaling.png

Needs Debian's python3-matplotlib.
"""
import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

STAGES = ["mesh", "field", "singularities", "correct", "blocks", "hexmesh", "total"]


def main(src, png):
    with open(src) as f:
        data = json.load(f)
    rows = data["rows"]
    tets = [r["tets"] for r in rows]
    fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4))
    for s in STAGES:
        left.plot(tets, [max(r.get(s, 0.0), 1e-3) for r in rows], marker="o", label=s,
                  linewidth=2.5 if s == "total" else 1.5)
    left.set_xscale("log")
    left.set_yscale("log")
    left.set_xlabel("tets")
    left.set_ylabel("seconds")
    left.set_title("framefix hexmesh --method %s, %d threads" % (data["method"], data["threads"]))
    left.legend(fontsize=8)
    left.grid(True, which="both", alpha=0.3)
    right.plot(tets, [r["peak_mb"] for r in rows], marker="o", color="black")
    right.axhline(1500, color="red", linestyle="--", label="1.5 GB")
    right.set_xscale("log")
    right.set_xlabel("tets")
    right.set_ylabel("peak memory, MB")
    right.legend(fontsize=8)
    right.grid(True, which="both", alpha=0.3)
    fig.tight_layout()
    fig.savefig(png, dpi=110)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
