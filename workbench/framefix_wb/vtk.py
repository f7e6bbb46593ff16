"""Reading the backend's legacy ASCII VTK files: the tets of blocks.vtk, the triangles of
block_surfaces.vtk and the polylines of block_edges.vtk, as checked plain data.

Like report.json, the file comes from a child process that may have died half-way: counts,
cell types, indices and cell data are checked once here; a bad file is a BackendError.
"""
import re

import numpy

from .errors import BackendError

VTK_TETRA = 10
VTK_POLY_LINE, VTK_TRIANGLE = 4, 5
VTK_HEXAHEDRON, VTK_QUADRATIC_HEXAHEDRON = 12, 25
_CELL_SIZES = {VTK_TRIANGLE: 3, VTK_HEXAHEDRON: 8, VTK_QUADRATIC_HEXAHEDRON: 20}  # fixed-size cells


def _fail(path, what):
    raise BackendError("the backend's %s is unusable: %s" % (path.rsplit("/", 1)[-1], what))


def _numbers(text, start, count, dtype):
    """`count` numbers of `text` from offset `start` (numpy parses, Python does not loop)."""
    values = numpy.array(text[start:].split(None, count)[:count], dtype=dtype)
    if len(values) != count:
        raise ValueError("truncated")
    return values


def _header(text, pattern, start=0):
    m = re.compile(pattern, re.M).search(text, start)
    if not m:
        raise ValueError("no %s" % pattern)
    return m


def _read_text(path):
    try:
        with open(path, encoding="ascii") as f:
            return f.read()
    except FileNotFoundError:
        raise BackendError("the backend finished but wrote no %s" % path.rsplit("/", 1)[-1]) from None
    except (OSError, UnicodeDecodeError) as e:
        _fail(path, str(e))



def _cell_arrays(text, start, names, count, floats=()):
    """The CELL_DATA arrays `names` (count integers each) and `floats` (count floats each)
    after offset `start`."""
    data = {}
    for name in tuple(names) + tuple(floats):
        a = _header(text, r"^SCALARS %s \w+ 1\s+LOOKUP_TABLE \w+\s" % re.escape(name), start)
        values = _numbers(text, a.end(), count, float)
        data[name] = values if name in floats else values.astype(numpy.int64)
    return data


def _check_points(path, points, indices, what):
    """Every index in `indices` names one of `points`, and the points are finite."""
    if len(indices) and (min(indices) < 0 or max(indices) >= len(points)):
        _fail(path, "a %s names a point that does not exist" % what)
    if not numpy.isfinite(points).all():
        _fail(path, "a point is not finite")


def _points_and_cells(text):
    """The (n, 3) points, and the match of the CELLS header (count, total) after them."""
    m = _header(text, r"^POINTS (\d+) \w+\s")
    n = int(m.group(1))
    points = _numbers(text, m.end(), 3 * n, float).reshape(n, 3)
    return points, _header(text, r"^CELLS (\d+) (\d+)\s", m.end())


def read_tets(path, arrays=("block",)):
    """{"points": (n, 3) float array, "tets": (m, 4) int array, "<array>": m ints} of a legacy
    ASCII UNSTRUCTURED_GRID of tets with integer CELL_DATA `arrays`."""
    text = _read_text(path)
    try:
        points, m = _points_and_cells(text)
        cells, total = int(m.group(1)), int(m.group(2))
        if total != 5 * cells:
            _fail(path, "cells are not all tets")
        ints = _numbers(text, m.end(), total, numpy.int64).reshape(cells, 5)
        if cells and (ints[:, 0] != 4).any():
            _fail(path, "cells are not all tets")
        m = _header(text, r"^CELL_TYPES (\d+)\s", m.end())
        if cells and (_numbers(text, m.end(), cells, numpy.int64) != VTK_TETRA).any():
            _fail(path, "cell types are not all tets")
        data = _cell_arrays(text, m.end(), arrays, cells)
    except ValueError as e:
        _fail(path, "truncated or not a legacy VTK tet mesh (%s)" % e)
    tets = ints[:, 1:]
    _check_points(path, points, [tets.min(), tets.max()] if cells else [], "tet")
    return dict(data, points=points, tets=tets)


def read_cells(path, cell_type, arrays=(), floats=()):
    """{"points": (n, 3) floats, "cells": list of int arrays, "<array>": one int (one float for
    `floats`) per cell} of a legacy ASCII UNSTRUCTURED_GRID whose cells are all of VTK type
    `cell_type` (triangles of 3 points, hexahedra of 8 or 20, polylines of 2 or more)."""
    text = _read_text(path)
    try:
        points, m = _points_and_cells(text)
        count, total = int(m.group(1)), int(m.group(2))
        ints = _numbers(text, m.end(), total, numpy.int64)
        cells, at = [], 0
        for _ in range(count):
            size = int(ints[at]) if at < total else -1
            if size < 2 or at + 1 + size > total or _CELL_SIZES.get(cell_type, size) != size:
                _fail(path, "a cell has a bad size")
            cells.append(ints[at + 1:at + 1 + size])
            at += 1 + size
        m = _header(text, r"^CELL_TYPES (\d+)\s", m.end())
        if count and (_numbers(text, m.end(), count, numpy.int64) != cell_type).any():
            _fail(path, "cells are not all of type %d" % cell_type)
        data = _cell_arrays(text, m.end(), arrays, count, floats)
    except ValueError as e:
        _fail(path, "truncated or not a legacy VTK grid (%s)" % e)
    _check_points(path, points, [int(i) for c in cells for i in (c.min(), c.max())], "cell")
    return dict(data, points=points, cells=cells)
