// TetGen on the tagged surface PLC: -p (PLC) -Y (keep the boundary triangulation: the surface is
// already refined to edge length ~h, see brep/surface_refinement.h) -q1.3/15 (radius-edge ratio /
// min dihedral) -a (volume bound from h) -z (0-based) -e (edges, for the feature tags) -Q (quiet).
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include <tetgen.h>

#include "framefix/core/error.h"
#include "framefix/core/isolation.h"
#include "framefix/tetgen/tet_output.h"
#include "framefix/tetgen/tetrahedralize.h"

namespace framefix {
namespace {

// -a bound = kVolumeFactor * h^3: with -q1.3/15 this puts the median edge length near h
// (a regular tet of edge h has volume 0.118 h^3; TetGen's tets are less regular).
constexpr double kVolumeFactor = 0.2;

std::string tetgen_failure(int code) {
    switch (code) {
    case 1: return "TetGen ran out of memory; use a larger size";
    case 2: return "TetGen hit an internal error; try a slightly different size";
    case 3: return "the surface triangulation self-intersects; check the solid for self-intersections";
    case 4: return "the solid has a feature much smaller than the size; use a smaller size or remove it";
    case 5: return "two boundary facets are nearly coincident; check the solid for overlapping faces";
    case 10: return "TetGen rejected the input surface (not a closed PLC)";
    default: return "TetGen failed with code " + std::to_string(code);
    }
}

double enclosed_volume(const SurfaceMesh& s) {
    double v = 0;
    for (Eigen::Index t = 0; t < s.triangles.rows(); ++t) {
        const Eigen::Vector3d a = s.points.row(s.triangles(t, 0)), b = s.points.row(s.triangles(t, 1)),
                              c = s.points.row(s.triangles(t, 2));
        v += a.dot(b.cross(c)) / 6.0;
    }
    return v;
}

// Fills `in` with the PLC; tetgenio frees the arrays in its destructor.
void fill_input(const SurfaceMesh& s, tetgenio& in) {
    in.firstnumber = 0;
    in.numberofpoints = int(s.points.rows());
    in.pointlist = new REAL[size_t(in.numberofpoints) * 3];
    for (int i = 0; i < in.numberofpoints; ++i)
        for (int k = 0; k < 3; ++k) in.pointlist[3 * i + k] = s.points(i, k);
    in.numberoffacets = int(s.triangles.rows());
    in.facetlist = new tetgenio::facet[size_t(in.numberoffacets)];
    in.facetmarkerlist = new int[size_t(in.numberoffacets)];
    for (int f = 0; f < in.numberoffacets; ++f) {
        tetgenio::facet& facet = in.facetlist[f];
        tetgenio::init(&facet);
        facet.numberofpolygons = 1;
        facet.polygonlist = new tetgenio::polygon[1];
        tetgenio::init(&facet.polygonlist[0]);
        facet.polygonlist[0].numberofvertices = 3;
        facet.polygonlist[0].vertexlist = new int[3];
        for (int k = 0; k < 3; ++k) facet.polygonlist[0].vertexlist[k] = s.triangles(f, k);
        in.facetmarkerlist[f] = s.face_tags(f);
    }
    in.numberofedges = int(s.feature_segments.rows());
    if (in.numberofedges > 0) {
        in.edgelist = new int[size_t(in.numberofedges) * 2];
        in.edgemarkerlist = new int[size_t(in.numberofedges)];
        for (int e = 0; e < in.numberofedges; ++e) {
            in.edgelist[2 * e] = s.feature_segments(e, 0);
            in.edgelist[2 * e + 1] = s.feature_segments(e, 1);
            in.edgemarkerlist[e] = kFeatureMarker + s.segment_tags(e);
        }
    }
}

// TetGen 1.5 can crash (not throw) when the PLC intersects itself, so its -d check runs first.
void check_self_intersections(tetgenio& in) {
    tetgenio report;
    char switches[] = "pdzQ";
    try {
        ::tetrahedralize(switches, &in, &report);
    } catch (int code) {
        throw Error("mesh", tetgen_failure(code));
    }
    if (report.numberoftrifaces > 0)
        throw Error("mesh", tetgen_failure(3) + " (" + std::to_string(report.numberoftrifaces) + " triangles involved)");
}

TetMesh run_tetgen(const SurfaceMesh& surface, double h) {
    tetgenio in, out;
    fill_input(surface, in);
    check_self_intersections(in);
    char switches[128];
    std::snprintf(switches, sizeof switches, "pYq1.3/15a%.17gzeQ", kVolumeFactor * h * h * h);
    try {
        ::tetrahedralize(switches, &in, &out);
    } catch (int code) {
        throw Error("mesh", tetgen_failure(code));
    } catch (const std::bad_alloc&) {
        throw Error("mesh", tetgen_failure(1));
    }
    if (out.numberoftetrahedra == 0) throw Error("mesh", "TetGen produced no tets; the surface may not be closed");
    return tet_mesh_from_tetgen(out, surface);
}

}  // namespace

TetMesh tetrahedralize(const SurfaceMesh& surface, const MeshOptions& options) {
    if (surface.triangles.rows() < 4) throw Error("mesh", "the surface has " + std::to_string(surface.triangles.rows()) +
                                                              " triangles; a closed surface needs at least 4");
    const double volume = enclosed_volume(surface);
    if (!(volume > 0)) throw Error("mesh", "the surface encloses no positive volume; it must be closed and outward");
    const double h = options.size > 0 ? options.size : size_for_tets(volume, options.target_tets);
    check_memory(volume, h, options);

    // TetGen can crash in boundary recovery instead of throwing: it runs in a worker process.
    const IsolatedTask task{"mesh", "TetGen", "try a slightly different --size, or check the solid for tiny faces"};
    TetMesh mesh = tet_mesh_from_bytes(run_isolated(task, [&] { return tet_mesh_bytes(run_tetgen(surface, h)); }));
    mesh.size = h;
    return mesh;
}

}  // namespace framefix
