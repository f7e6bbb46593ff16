#!/usr/bin/env python3
"""Renders a part's feature curves and singular curves to a PNG from an analyze/correct report.

    /usr/bin/python3 scripts/render_curves.py OUT_DIR/report.json picture.png [title]

Needs Debian's python3-matplotlib (only for this picture; nothing else uses it).
"""
import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

COLOURS = {"valence3": "tab:blue", "valence5": "tab:red", "3-5": "magenta", "other": "grey"}


def main(report_path, png, title=None):
    r = json.load(open(report_path))
    fig = plt.figure(figsize=(6, 6))
    ax = fig.add_subplot(projection="3d")
    for c in r.get("feature_curves", []):
        p = list(zip(*c["points"]))
        ax.plot(*p, color="black", lw=0.8, alpha=0.6)
    for path in r.get("correction", {}).get("snapped_paths", []):
        p = list(zip(*path["points"]))
        ax.plot(*p, color="tab:green", lw=3)
    seen = set()
    for c in r.get("singularities", {}).get("curves", []):
        p = list(zip(*c["points"]))
        label = c["kind"] if c["kind"] not in seen else None
        seen.add(c["kind"])
        ax.plot(*p, color=COLOURS.get(c["kind"], "grey"), lw=3 if c["kind"] == "3-5" else 2, label=label)
    for n in r.get("singularities", {}).get("nodes", []):
        if not n["valid"]:
            ax.scatter(*n["position"], color="orange", s=40)
    ax.set_box_aspect([1, 1, 1])
    ax.view_init(elev=28, azim=-55)
    ax.set_axis_off()
    s = r.get("singularities", {}).get("summary", {})
    ax.set_title(title or f"{s.get('curves', 0)} singular curves, {s.get('curves_3_5', 0)} 3-5")
    if seen:
        ax.legend(loc="lower left")
    fig.savefig(png, dpi=110, bbox_inches="tight")


if __name__ == "__main__":
    main(*sys.argv[1:])
