#include "framefix/pipeline/mesh_attempts.h"

#include <array>
#include <cstdio>
#include <optional>

#include "framefix/core/error.h"
#include "framefix/hxt/hxt_tetrahedralize.h"
#include "framefix/tetgen/tetrahedralize.h"

namespace framefix {
namespace {

// One way to mesh: the surface's edge length as a fraction of h (the tets keep h), and whether
// TetGen must keep the surface triangles as they are (-Y).
struct Plan {
    double surface_factor;
    bool keep_boundary;
    bool for_intersections;  // helps a self-intersecting surface triangulation
    bool for_recovery;       // helps a crash or a failed boundary recovery
};

// Finer surfaces follow thin, curved faces closer and give TetGen shorter segments to recover;
// 0.7 and 0.5 keep the tet count within about 3x of the first try.
constexpr std::array<Plan, 5> kPlans{{
    {1.0, true, true, true},
    {1.0, false, false, true},
    {0.7, true, true, true},
    {0.7, false, false, true},
    {0.5, true, true, false},
}};

std::string describe(const Plan& p) {
    char text[96];
    std::snprintf(text, sizeof text, "surface at %.2g h, %s", p.surface_factor,
                  p.keep_boundary ? "boundary kept" : "boundary Steiner points allowed");
    return text;
}

std::string face_list(const Eigen::VectorXi& faces) {
    std::string text;
    for (Eigen::Index i = 0; i < faces.size(); ++i) text += (i ? ", Face" : "Face") + std::to_string(faces(i));
    return text;
}

// A self-intersecting triangulation of a solid that crosses itself is not ours to fix. Returns
// whether the check ran (it is OCCT modelling code: it may crash or time out on odd parts).
bool refuse_self_intersecting_solid(const BrepModel& model) {
    Eigen::VectorXi faces;
    try {
        faces = self_intersecting_faces(model);
    } catch (const Error&) {
        return false;  // unknown: the finer surfaces are tried all the same
    }
    if (faces.size() > 0)
        throw Error("mesh", "the solid self-intersects: OpenCASCADE's self-intersection check flags " + face_list(faces) +
                                "; repair these faces in the CAD tool");
    return true;
}

// Edges across a face's width (brep face_width) below which a coarse size would leave it
// unresolved: at 1.5 x the default size the groove's floor (2.48 edges across at 1 x) gets 1.65
// and its two 3-5 curves merged into one. 3 instead changed one filleted groove's graph at 1.5 x
// (docs/algorithms.md#narrow-faces).
constexpr double kEdgesAcrossNarrowFace = 2.5;

// Sizes for the faces too narrow for options.size, never finer than the default size; returns
// how many. A face OCCT cannot measure keeps the size.
int keep_narrow_faces(const BrepModel& model, MeshOptions& options) {
    if (!options.keep_narrow_faces) return 0;
    const double h_default = default_size(model, options.target_tets);
    if (options.size <= h_default) return 0;
    int narrow = 0;
    for (int f = 1; f <= model.num_faces; ++f) {
        double width = 0;
        try {
            width = face_width(model, f);
        } catch (const Error&) {
            continue;
        }
        const double hf = std::max(width / kEdgesAcrossNarrowFace, h_default);
        if (hf >= options.size) continue;
        const auto [at, fresh] = options.face_size.emplace(f, hf);
        if (!fresh) at->second = std::min(at->second, hf);
        ++narrow;
    }
    return narrow;
}

bool plan_helps(const Plan& p, TetgenStatus failure) {
    return failure == TetgenStatus::self_intersecting ? p.for_intersections : p.for_recovery;
}

// The surface of the last try, reused by the next one at the same edge length (tries 1 and 2).
struct SurfaceCache {
    double factor = 0;
    SurfaceMesh surface;
};

const SurfaceMesh& surface_for(const BrepModel& model, const FeatureSet& features, const MeshOptions& options,
                               const Plan& p, SurfaceCache& cache) {
    if (cache.factor != p.surface_factor) {
        MeshOptions surface_options = options;
        surface_options.size = options.size * p.surface_factor;
        cache.surface = tessellate(model, features, surface_options);
        cache.factor = p.surface_factor;
    }
    return cache.surface;
}

TetgenRun attempt(const BrepModel& model, const FeatureSet& features, const MeshOptions& options, const Plan& p,
                  SurfaceCache& cache) {
    return try_tetrahedralize(surface_for(model, features, options, p, cache), options, p.keep_boundary);
}

// --mesher hxt: HXT on the surface at h. When it fails, the TetGen plans follow on the same
// surface; the report's attempts say why HXT did not mesh.
std::optional<TetMesh> try_hxt_first(const BrepModel& model, const FeatureSet& features, const MeshOptions& options,
                                     SurfaceCache& cache, std::vector<MeshAttempt>& attempts) {
    const Plan& first = kPlans.front();
    TetgenRun run = try_hxt(surface_for(model, features, options, first, cache), options);
    attempts.push_back({"HXT, " + describe(first), run.message});
    if (run.status == TetgenStatus::meshed) return std::move(run.mesh);
    return std::nullopt;
}

std::string final_message(const std::vector<MeshAttempt>& attempts, bool solid_sound) {
    std::string text = attempts.front().failure;
    if (solid_sound) text += ", although the solid itself does not self-intersect";
    if (attempts.size() > 1) text += "; " + std::to_string(attempts.size()) + " ways tried, none meshed";
    return text + "; try a smaller --size, or report the part";
}

}  // namespace

BrepMeshing mesh_brep(const BrepModel& model, const FeatureSet& features, const MeshOptions& given) {
    FF_ASSERT(given.size > 0);
    BrepMeshing result;
    MeshOptions options = given;
    result.narrow_faces = keep_narrow_faces(model, options);
    TetgenStatus first = TetgenStatus::meshed;
    bool solid_sound = false;
    SurfaceCache cache;
    if (options.mesher == Mesher::hxt) {
        if (std::optional<TetMesh> tets = try_hxt_first(model, features, options, cache, result.attempts)) {
            result.tets = std::move(*tets);
            result.mesher = Mesher::hxt;
            return result;
        }
    }
    for (const Plan& p : kPlans) {
        if (first != TetgenStatus::meshed && !plan_helps(p, first)) continue;
        TetgenRun run;
        try {
            run = attempt(model, features, options, p, cache);
        } catch (const Error& e) {
            if (first == TetgenStatus::meshed) throw;  // bad options or input: no other way helps
            result.attempts.push_back({describe(p), e.message()});  // a finer surface past the memory limit
            break;
        }
        result.attempts.push_back({describe(p), run.message});
        if (run.status == TetgenStatus::meshed) {
            result.tets = std::move(run.mesh);
            return result;
        }
        if (run.status == TetgenStatus::failed) throw Error("mesh", run.message);
        if (first == TetgenStatus::meshed) {
            first = run.status;
            if (first == TetgenStatus::self_intersecting) solid_sound = refuse_self_intersecting_solid(model);
        }
    }
    throw Error("mesh", final_message(result.attempts, solid_sound));
}

}  // namespace framefix
