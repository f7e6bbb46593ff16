// TetGen on the tagged surface PLC: -p (PLC) -Y (keep the boundary triangulation: the surface is
// already refined to edge length ~h, see brep/surface_refinement.h) -q1.3/15 (radius-edge ratio /
// min dihedral) -a (volume bound from h) -z (0-based) -e (edges, for the feature tags) -Q (quiet).
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <set>
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

// Returns from the worker: TetGen's failures come back as data, so that whatever arrives as an
// Error from run_isolated is a crash.
struct Failure {
    TetgenStatus status;
    std::string message;
};

Failure tetgen_failure(int code) {
    switch (code) {
    case 1: return {TetgenStatus::failed, "TetGen ran out of memory; use a larger size"};
    case 2: return {TetgenStatus::recovery_failed, "TetGen hit an internal error in boundary recovery"};
    case 3: return {TetgenStatus::self_intersecting, "the surface triangulation self-intersects"};
    case 4: return {TetgenStatus::recovery_failed, "the solid has a feature much smaller than the size"};
    case 5: return {TetgenStatus::recovery_failed, "two boundary facets are nearly coincident"};
    case 10: return {TetgenStatus::failed, "TetGen rejected the input surface (not a closed PLC)"};
    default: return {TetgenStatus::failed, "TetGen failed with code " + std::to_string(code)};
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

// "N triangles involved, on Face3 and Face5, near (x, y, z)": where to look in the CAD.
std::string intersection_place(const tetgenio& report) {
    std::set<int> faces;
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (int f = 0; f < report.numberoftrifaces; ++f) {
        if (report.trifacemarkerlist) faces.insert(report.trifacemarkerlist[f]);
        for (int k = 0; k < 3; ++k) {
            const REAL* p = &report.pointlist[3 * report.trifacelist[3 * f + k]];
            sum += Eigen::Vector3d(p[0], p[1], p[2]) / 3.0;
        }
    }
    std::string text = std::to_string(report.numberoftrifaces) + " triangles involved, on";
    for (int face : faces) text += " Face" + std::to_string(face);
    const Eigen::Vector3d c = sum / double(std::max(1, report.numberoftrifaces));
    char where[96];
    std::snprintf(where, sizeof where, ", near (%.4g, %.4g, %.4g)", c.x(), c.y(), c.z());
    return text + where;
}

// TetGen 1.5 can crash (not throw) when the PLC intersects itself, so its -d check runs first.
std::optional<Failure> check_self_intersections(tetgenio& in) {
    tetgenio report;
    char switches[] = "pdzQ";
    try {
        ::tetrahedralize(switches, &in, &report);
    } catch (int code) {
        return tetgen_failure(code);
    }
    if (report.numberoftrifaces == 0) return std::nullopt;
    return Failure{TetgenStatus::self_intersecting, tetgen_failure(3).message + " (" + intersection_place(report) + ")"};
}

// Test hook (FRAMEFIX_FAULT=tetgen-keep-boundary): the worker crashes as TetGen's boundary
// recovery does on some industrial parts, so that the recovery attempts can be tested.
void injected_fault(bool keep_boundary) {
    const char* fault = std::getenv("FRAMEFIX_FAULT");
    if (keep_boundary && fault && std::string(fault) == "tetgen-keep-boundary") std::raise(SIGSEGV);
}

// TetGen's -i list: points it inserts into the mesh (it skips those outside the solid).
void fill_inserted(const Points& inserted, tetgenio& addin) {
    addin.firstnumber = 0;
    addin.numberofpoints = int(inserted.rows());
    addin.pointlist = new REAL[size_t(addin.numberofpoints) * 3];
    for (int i = 0; i < addin.numberofpoints; ++i)
        for (int k = 0; k < 3; ++k) addin.pointlist[3 * i + k] = inserted(i, k);
}

// In the worker: status byte, then the mesh's bytes or the failure's message.
std::string run_tetgen(const SurfaceMesh& surface, double h, bool keep_boundary, const Points& inserted) {
    tetgenio in, out, addin;
    fill_input(surface, in);
    const bool insert = inserted.rows() > 0;
    if (insert) fill_inserted(inserted, addin);
    std::optional<Failure> failure = check_self_intersections(in);
    if (!failure) {
        injected_fault(keep_boundary);
        char switches[128];
        std::snprintf(switches, sizeof switches, "p%s%sq1.3/15a%.17gzeQ", keep_boundary ? "Y" : "", insert ? "i" : "",
                      kVolumeFactor * h * h * h);
        try {
            ::tetrahedralize(switches, &in, &out, insert ? &addin : nullptr);
        } catch (int code) {
            failure = tetgen_failure(code);
        } catch (const std::bad_alloc&) {
            failure = tetgen_failure(1);
        }
    }
    if (!failure && out.numberoftetrahedra == 0)
        failure = Failure{TetgenStatus::failed, "TetGen produced no tets; the surface may not be closed"};
    if (failure) return char(failure->status) + failure->message;
    return char(TetgenStatus::meshed) + tet_mesh_bytes(tet_mesh_from_tetgen(out, surface));
}

}  // namespace

double checked_volume_size(const SurfaceMesh& surface, const MeshOptions& options) {
    if (surface.triangles.rows() < 4) throw Error("mesh", "the surface has " + std::to_string(surface.triangles.rows()) +
                                                              " triangles; a closed surface needs at least 4");
    const double volume = enclosed_volume(surface);
    if (!(volume > 0)) throw Error("mesh", "the surface encloses no positive volume; it must be closed and outward");
    const double h = options.size > 0 ? options.size : size_for_tets(volume, options.target_tets);
    check_memory(volume, h, options);
    return h;
}

TetgenRun try_tetrahedralize(const SurfaceMesh& surface, const MeshOptions& options, bool keep_boundary,
                             const Points& inserted) {
    const double h = checked_volume_size(surface, options);

    // TetGen can crash in boundary recovery instead of throwing: it runs in a worker process.
    // No hint: mesh_brep tries other ways first and ends the message itself.
    const IsolatedTask task{"mesh", "TetGen", ""};
    TetgenRun run;
    std::string bytes;
    try {
        bytes = run_isolated(task, [&] { return run_tetgen(surface, h, keep_boundary, inserted); });
    } catch (const Error& e) {
        run.status = TetgenStatus::crashed;
        run.message = e.message();
        return run;
    }
    run.status = TetgenStatus(bytes.at(0));
    if (run.status != TetgenStatus::meshed) {
        run.message = bytes.substr(1);
        return run;
    }
    run.mesh = tet_mesh_from_bytes(bytes.substr(1));
    run.mesh.size = h;
    return run;
}

TetMesh tetrahedralize(const SurfaceMesh& surface, const MeshOptions& options, const Points& inserted) {
    TetgenRun run = try_tetrahedralize(surface, options, true, inserted);
    if (run.status == TetgenStatus::failed) throw Error("mesh", run.message);
    if (run.status != TetgenStatus::meshed) throw Error("mesh", run.message + "; try a slightly different --size");
    return std::move(run.mesh);
}

}  // namespace framefix
