"""Reading the backend's report.json (version 1, its fields in docs/design.md) into checked data.

The report comes from a child process that may have died half-way or printed garbage: every
field the workbench uses is checked here, once, and a bad report becomes a BackendError that
says which field is wrong. Nothing downstream re-checks.
"""
import json
import math

from .errors import BackendError

CURVE_KINDS = ("valence3", "valence5", "3-5")  # others (a newer backend's) are shown as "other"
SUMMARY_KEYS = ("curves", "valence3", "valence5", "curves_3_5", "nodes", "invalid_nodes")


def _fail(what):
    raise BackendError("the backend's report.json is unusable: " + what)


def _points(value, where):
    if not isinstance(value, list):
        _fail("%s.points is not a list" % where)
    points = []
    for p in value:
        if (not isinstance(p, list) or len(p) != 3
                or not all(isinstance(c, (int, float)) and math.isfinite(c) for c in p)):
            _fail("%s.points holds %r, not [x, y, z]" % (where, p))
        points.append((float(p[0]), float(p[1]), float(p[2])))
    return points


def _curve(c, i):
    where = "singularities.curves[%d]" % i
    if not isinstance(c, dict) or not isinstance(c.get("kind"), str):
        _fail("%s.kind is not a string" % where)
    return {"id": int(c.get("id", i)), "kind": c["kind"], "length": float(c.get("length", 0.0)),
            "ends": list(c.get("ends", [])), "points": _points(c.get("points"), where)}


def _node(n, i):
    where = "singularities.nodes[%d]" % i
    if not isinstance(n, dict):
        _fail(where + " is not an object")
    position = _points([n.get("position")], where)[0]
    return {"id": int(n.get("id", i)), "position": position, "boundary": bool(n.get("boundary")),
            "n3": int(n.get("n3", 0)), "n5": int(n.get("n5", 0)), "valid": bool(n.get("valid", True))}


def _feature_curve(f, i):
    where = "feature_curves[%d]" % i
    if not isinstance(f, dict) or not isinstance(f.get("valence"), int):
        _fail(where + ".valence is not an integer")
    return {"edge": int(f.get("edge", 0)), "valence": f["valence"],
            "points": _points(f.get("points", []), where)}


def _summary(value, where):
    if not isinstance(value, dict):
        _fail(where + " is not an object")
    summary = dict(value)
    for key in SUMMARY_KEYS:
        if not isinstance(summary.get(key), int):
            _fail("%s.%s is not an integer" % (where, key))
    summary["meshable"] = bool(summary.get("meshable"))
    return summary


def _tries(tries):
    """Method auto's tries: method, ran, kept, after (a summary), seconds, reason."""
    out = []
    for i, t in enumerate(tries or []):
        if not isinstance(t, dict) or not isinstance(t.get("method"), str):
            _fail("correction.tries[%d].method is not a string" % i)
        out.append({"method": t["method"], "ran": bool(t.get("ran")), "kept": bool(t.get("kept")),
                    "after": _summary(t.get("after"), "correction.tries[%d].after" % i),
                    "seconds": float(t.get("seconds", 0)), "reason": str(t.get("reason", ""))})
    return out


def _mapped(m):
    """The fillet correction's graph on the original part, and its flat-corner re-solve."""
    if m is None:
        return None
    if not isinstance(m, dict):
        _fail("correction.mapped is not an object")
    flat = m.get("flat_corners")
    if isinstance(flat, dict):
        solved = bool(flat.get("solved"))
        flat = {"solved": solved, "turned_vertices": int(flat.get("turned_vertices", 0)),
                "summary": _summary(flat.get("summary"), "correction.mapped.flat_corners.summary")
                if solved else None}
    return {"summary": _summary(m.get("summary"), "correction.mapped.summary"),
            "curves": [_curve(c, i) for i, c in enumerate(m.get("curves") or [])],
            "flat_corners": flat if isinstance(flat, dict) else None}


def check_report(data):
    """The parts of a report dict the workbench uses, checked; raises BackendError."""
    if not isinstance(data, dict):
        _fail("it is not a JSON object")
    if data.get("version") != 1:
        _fail("version is %r, this workbench reads version 1" % data.get("version"))
    sing = data.get("singularities")
    if not isinstance(sing, dict) or not isinstance(sing.get("summary"), dict):
        _fail("singularities.summary is missing")
    summary = _summary(sing["summary"], "singularities.summary")
    curves = [_curve(c, i) for i, c in enumerate(sing.get("curves") or [])]
    nodes = [_node(n, i) for i, n in enumerate(sing.get("nodes") or [])]
    features = [_feature_curve(f, i) for i, f in enumerate(data.get("feature_curves") or [])]
    mesh = data.get("mesh") if isinstance(data.get("mesh"), dict) else {}
    return {"summary": summary, "curves": curves, "nodes": nodes, "feature_curves": features,
            "mesh": mesh, "correction": _correction(data.get("correction")),
            "blocks": _blocks(data.get("blocks")),
            "hexmesh": _hexmesh(data.get("hexmesh")),
            "timings_s": data.get("timings_s") or {}, "raw": data}


def _correction(c):
    """The `correction` section of `framefix correct` (None for an analysis)."""
    if c is None:
        return None
    if not isinstance(c, dict) or not isinstance(c.get("before"), dict) or not isinstance(
            c["before"].get("curves_3_5"), int):
        _fail("correction.before.curves_3_5 is not an integer")
    paths = [{"source_curve": int(p.get("source_curve", -1)) if isinstance(p, dict) else -1,
              "points": _points(p.get("points", []) if isinstance(p, dict) else None,
                                "correction.snapped_paths[%d]" % i)}
             for i, p in enumerate(c.get("snapped_paths") or [])]
    fillets = []
    for i, f in enumerate(c.get("fillets") or []):
        if not isinstance(f, dict) or not isinstance(f.get("edge"), int) or not isinstance(f.get("done"), bool):
            _fail("correction.fillets[%d] has no integer edge or boolean done" % i)
        fillets.append({"edge": f["edge"], "radius": float(f.get("radius", 0)), "done": f["done"],
                        "reason": str(f.get("reason", ""))})
    streamlines = [{"source": str(s.get("source", "")) if isinstance(s, dict) else "",
                    "used": bool(s.get("used")) if isinstance(s, dict) else False,
                    "points": _points(s.get("polyline", []) if isinstance(s, dict) else None,
                                      "correction.streamlines[%d]" % i)}
                   for i, s in enumerate(c.get("streamlines") or [])]
    failures = ["%s: %s" % (f.get("what", ""), f.get("why", "")) if isinstance(f, dict) else str(f)
                for f in c.get("failures") or []]
    return {"method": str(c.get("method", "")), "before": dict(c["before"]),
            "changed_curves": int(c.get("changed_curves", 0)), "snapped_paths": paths,
            "fillets": fillets, "notes": [str(n) for n in c.get("notes") or []],
            "streamlines": streamlines, "failures": failures, "mapped": _mapped(c.get("mapped")),
            "chosen": str(c.get("chosen", "")), "tries": _tries(c.get("tries"))}


BLOCK_COUNTS = ("count", "valid", "conforming_pairs", "pairs", "flat_corners", "flat_edges")


def _blocks(b):
    """The `blocks` section of `framefix blocks` (None for the other commands)."""
    if b is None:
        return None
    if not isinstance(b, dict):
        _fail("blocks is not an object")
    out = {}
    for key in BLOCK_COUNTS:
        if not isinstance(b.get(key), int) or b[key] < 0:
            _fail("blocks.%s is not a count" % key)
        out[key] = b[key]
    flat = b.get("flat_refinement") or {}  # absent in reports from before the blocks' own refinement
    out["refined"] = flat["refined"] if flat.get("kept") and isinstance(flat.get("refined"), int) else 0
    cut = (b.get("before_refinement") or {}).get("count")
    out["cut"] = cut if out["refined"] and isinstance(cut, int) else out["count"]
    items = b.get("blocks") or []
    if not isinstance(items, list) or len(items) != out["count"]:
        _fail("blocks.blocks does not hold blocks.count = %d blocks" % out["count"])
    out["blocks"] = []
    for i, item in enumerate(items):
        if not isinstance(item, dict):
            _fail("blocks.blocks[%d] is not an object" % i)
        neighbours = item.get("neighbours") or []
        if not isinstance(neighbours, list) or not all(
                isinstance(n, int) and 0 <= n < out["count"] for n in neighbours):
            _fail("blocks.blocks[%d].neighbours are not block ids" % i)
        out["blocks"].append({"id": int(item.get("id", i)), "tets": int(item.get("tets", 0)),
                              "valid": bool(item.get("valid")), "neighbours": neighbours,
                              "reason": str(item.get("reason") or "")})
    return out


def _hexmesh(h):
    """The `hexmesh` section of `framefix hexmesh` (None for the other commands)."""
    if h is None:
        return None
    if not isinstance(h, dict) or not isinstance(h.get("done"), bool):
        _fail("hexmesh.done is not a boolean")
    if not h["done"]:
        return {"done": False, "reason": str(h.get("reason") or "no reason given")}
    out = {"done": True, "order": h.get("order", 1)}
    for key in ("hexes", "vertices", "inverted"):
        if not isinstance(h.get(key), int) or h[key] < 0:
            _fail("hexmesh.%s is not a count" % key)
        out[key] = h[key]
    for key in ("min_scaled_jacobian", "mean_scaled_jacobian", "share_sj_ge_0_5"):
        if not isinstance(h.get(key), (int, float)):
            _fail("hexmesh.%s is not a number" % key)
        out[key] = float(h[key])
    if out["order"] not in (1, 2):
        _fail("hexmesh.order is not 1 or 2")
    ref = h.get("refinement") or {}  # absent in reports from before the flat-edge refinement
    out["refined"] = ref["refined"] if ref.get("kept") and isinstance(ref.get("refined"), int) else 0
    out["blocks"] = len(h["blocks"]) if isinstance(h.get("blocks"), list) else 0  # blocks of the meshed complex
    return out


def hexmesh_text(h):
    """'825 hexes, min scaled Jacobian 0.67, 0 inverted (1 block with a flat edge split in three)'
    or 'no hex mesh: <reason>'."""
    if not h["done"]:
        return "no hex mesh: %s" % h["reason"]
    text = "%s%s, min scaled Jacobian %.2f, %d inverted" % (
        plural(h["hexes"], "hex"), " (20-node)" if h["order"] == 2 else "",
        h["min_scaled_jacobian"], h["inverted"])
    if h.get("refined"):
        text += " (%s with a flat edge split in three)" % plural(h["refined"], "block")
    return text


def plural(n, word):
    return "%d %s%s" % (n, word, "" if n == 1 else "es" if word.endswith("x") else "s")


def blocks_text(b):
    """'7 blocks, all valid, 1 flat edge' or '7 blocks, 6 valid, 9/10 pairs conforming,
    1 flat edge': what a CAD engineer asks first about a block decomposition; '9 blocks (7 cut,
    1 with a flat edge cut in three), all valid' where flat corners were refined."""
    parts = [plural(b["count"], "block")]
    if b.get("refined"):
        parts[0] += " (%d cut, %d with a flat edge cut in three)" % (b["cut"], b["refined"])
    parts.append("all valid" if b["valid"] == b["count"] else "%d valid" % b["valid"])
    if b["conforming_pairs"] != b["pairs"]:
        parts.append("%d/%d pairs conforming" % (b["conforming_pairs"], b["pairs"]))
    if b["flat_edges"]:
        parts.append(plural(b["flat_edges"], "flat edge"))
    if b["flat_corners"]:
        parts.append(plural(b["flat_corners"], "flat corner"))
    return ", ".join(parts)


def load_report(path):
    """check_report of the file at `path`; a missing or non-JSON file is a BackendError."""
    try:
        with open(path, encoding="utf-8") as f:
            data = json.load(f)
    except FileNotFoundError:
        raise BackendError("the backend finished but wrote no report.json") from None
    except (ValueError, UnicodeDecodeError) as e:
        raise BackendError("the backend's report.json is not valid JSON (%s)" % e) from None
    return check_report(data)


def curve_breakdown(summary):
    """'1 valence 5, 1 3-5, 3 other': the curves by kind, kinds the summary does not name
    (a backend may add some) counted as other."""
    named = (("valence3", "valence 3"), ("valence5", "valence 5"), ("curves_3_5", "3-5"))
    parts = ["%d %s" % (summary[k], text) for k, text in named if summary[k]]
    other = summary["curves"] - sum(summary[k] for k, _ in named)
    if other > 0:
        parts.append("%d other" % other)
    return ", ".join(parts) or "none"


def summary_text(summary, mesh=None):
    """One line for the console: '1 3-5 curves, 5 singular curves (...): NOT hex-meshable'."""
    verdict = "hex-meshable" if summary["meshable"] else "NOT hex-meshable"
    text = ("%d 3-5 curves, %d singular curves (%s), %d nodes (%d invalid): %s" % (
        summary["curves_3_5"], summary["curves"], curve_breakdown(summary), summary["nodes"],
        summary["invalid_nodes"], verdict))
    if mesh and mesh.get("tets"):
        text += "; mesh %s tets, size %.4g" % (mesh.get("tets"), float(mesh.get("size", 0)))
    return text


def fillet_lines(correction):
    """One line per edge the fillet correction tried, then its notes; [] for other methods."""
    if not correction:
        return []
    lines = ["Edge%d filleted, radius %.4g" % (f["edge"], f["radius"]) if f["done"] else
             "Edge%d not filleted: %s" % (f["edge"], f["reason"]) for f in correction.get("fillets", [])]
    return lines + list(correction.get("notes", [])) + mapped_lines(correction.get("mapped"))


def mapped_lines(mapped):
    """What the map back onto the original part gives: its graph, then the flat-corner re-solve."""
    if not mapped:
        return []
    lines = ["Mapped onto the original part: %s" % summary_text(mapped["summary"])]
    flat = mapped.get("flat_corners") or {}
    if flat.get("solved"):
        lines.append("Original part solved again with flat corners (%d edge vertices turned): %s"
                     % (flat["turned_vertices"], summary_text(flat["summary"])))
    elif flat:
        lines.append("No mapped valence-5 curve lies on a filleted edge: no flat corner to solve")
    return lines


def tries_lines(correction):
    """Method auto: one line per try, side by side with the input, then what was kept."""
    if not correction or not correction.get("tries"):
        return []
    def counts(s):
        return "%d 3-5 curves, %d invalid nodes%s" % (s["curves_3_5"], s["invalid_nodes"],
                                                      ", hex-meshable" if s["meshable"] else "")
    lines = ["input: %s" % counts(correction["before"])] if "invalid_nodes" in correction["before"] else []
    for t in correction["tries"]:
        if not t["ran"]:
            lines.append("%s: not tried (%s)" % (t["method"], t["reason"]))
            continue
        lines.append("%s: %s, %.1f s%s" % (t["method"], counts(t["after"]), t["seconds"],
                                           "" if t["kept"] else " (not kept: %s)" % (t["reason"] or "no change")))
    lines.append("kept: %s" % (correction["chosen"] or "the input (nothing helped)"))
    return lines


def extrusion_lines(correction):
    """The extrusions' streamline count, then one line per failure; [] for other methods."""
    if not correction or not (correction.get("method", "").startswith("extrude") or
                              correction.get("chosen", "").startswith("extrude")):
        return []
    lines = correction.get("streamlines", [])
    used = sum(1 for s in lines if s["used"])
    return ["%d of %d streamlines used" % (used, len(lines))] + list(correction.get("failures", []))


def run_text(report):
    """The console line of a checked report: the blocks first when there are some."""
    text = summary_text(report["summary"], report["mesh"])
    done = [f for f in (report["correction"] or {}).get("fillets", []) if f["done"]]
    if report["correction"] and report["correction"].get("fillets"):
        text += "; %d of %d edges filleted (%s)" % (len(done), len(report["correction"]["fillets"]),
                                                   ", ".join("Edge%d r %.3g" % (f["edge"], f["radius"]) for f in done))
    if report.get("blocks") is not None:
        text = "%s; curves after the correction: %s" % (blocks_text(report["blocks"]), text) \
            if report["correction"] else "%s; %s" % (blocks_text(report["blocks"]), text)
    if report.get("hexmesh") is not None:
        text = "%s; %s" % (hexmesh_text(report["hexmesh"]), text)
    return text
