"""Report data -> Part shapes. Each polyline is a wire of straight edges; the returned
per-edge lists are in the order of the compound's Edges (FreeCAD's Edge1, Edge2, ...)."""
import FreeCAD
import Part


def _dedup(points, tol=1e-12):
    out = []
    for p in points:
        v = FreeCAD.Vector(*p)
        if not out or (v - out[-1]).Length > tol:
            out.append(v)
    return out


def polylines(items, code_of):
    """(compound, edge_codes, edge_items): `items` have "points"; code_of(item) -> int.

    edge_items[e] is the index in `items` of the polyline edge e belongs to. Polylines with
    fewer than two distinct points are skipped.
    """
    wires, codes, owners = [], [], []
    for i, item in enumerate(items):
        pts = _dedup(item["points"])
        if len(pts) < 2:
            continue
        wire = Part.makePolygon(pts)
        wires.append(wire)
        n = len(wire.Edges)
        codes += [code_of(item)] * n
        owners += [i] * n
    compound = compound_of(wires)
    if len(compound.Edges) != len(codes):  # shared edges would break per-edge colours
        raise RuntimeError("polyline compound has %d edges, expected %d"
                           % (len(compound.Edges), len(codes)))
    return compound, codes, owners


def points(positions):
    """Compound of vertices, in order (Vertex1 is positions[0])."""
    return compound_of([Part.Vertex(FreeCAD.Vector(*p)) for p in positions])


def compound_of(shapes):
    """A compound, or the null shape when there is nothing: FreeCAD's viewer reports an empty
    compound as an error ("Bnd_Box is void"), a null shape it just does not draw."""
    return Part.Compound(shapes) if shapes else Part.Shape()
