#include "framefix/pipeline/thin_blocks.h"

#include <algorithm>

#include "framefix/corrections/boundary_distance.h"
#include "framefix/mesh/size_model.h"

namespace framefix {
namespace {

constexpr double kEdgesAcross = 3;     // a thin block gets this many tet edges across
constexpr double kMinSizeH = 1.0 / 3;  // and no edge shorter than h / 3: at most 27 x the tets there
constexpr double kEndSkipH = 1.5;      // arc length from a boundary end where the curve enters the surface
constexpr double kOnBoundaryH = 0.5;   // closer than this the curve lies on the surface (a snapped path)

// Arc length of each polyline point from the curve's start.
std::vector<double> arc_lengths(const Points& p) {
    std::vector<double> s(size_t(p.rows()), 0.0);
    for (Eigen::Index i = 1; i < p.rows(); ++i) s[size_t(i)] = s[size_t(i - 1)] + (p.row(i) - p.row(i - 1)).norm();
    return s;
}

}  // namespace

ThinFaces thin_block_faces(const TetMesh& mesh, const SingularityGraph& graph, double h,
                           const std::function<bool(int)>& counts) {
    ThinFaces out;
    if (mesh.boundary_faces.rows() == 0 || h <= 0) return out;
    const BoundaryDistance boundary(mesh);
    const double reach = kResolvedThicknessH * h;
    for (const SingularCurve& c : graph.curves) {
        const std::vector<double> s = arc_lengths(c.points);
        const double length = s.empty() ? 0.0 : s.back();
        auto boundary_end = [&](int k) { return !c.closed && c.ends[k] >= 0 && graph.nodes[size_t(c.ends[k])].boundary; };
        const int nf = int(c.faces.size());
        for (Eigen::Index i = 0; i < c.points.rows(); ++i) {
            // points: end node, one centroid per singular triangle, end node
            if (counts && nf > 0 && !counts(c.faces[size_t(std::clamp(int(i) - 1, 0, nf - 1))])) continue;
            if ((boundary_end(0) && s[size_t(i)] < kEndSkipH * h) || (boundary_end(1) && length - s[size_t(i)] < kEndSkipH * h))
                continue;
            const auto near = boundary.near(c.points.row(i).transpose(), reach);
            if (std::any_of(near.begin(), near.end(), [&](const auto& n) { return n.second < kOnBoundaryH * h; })) continue;
            for (const auto& [tri, d] : near) {
                const double size = std::max(d / kEdgesAcross, kMinSizeH * h);
                auto [it, fresh] = out.face_size.emplace(mesh.face_tags[tri], size);
                if (!fresh) it->second = std::min(it->second, size);
                out.thinnest = out.thinnest > 0 ? std::min(out.thinnest, d) : d;
            }
        }
    }
    return out;
}

double estimate_thin_tets(const TetMesh& mesh, const ThinFaces& thin) {
    // Fine tets over a finer face, in its edge lengths: on rounded_box, two_cylinders, HexMe's s10o
    // and n05o this estimated 0.8 to 1.4 x the tets TetGen made.
    constexpr double kBandEdges = 1.4;
    double tets = double(mesh.num_tets());
    for (Eigen::Index b = 0; b < mesh.boundary_faces.rows(); ++b) {
        const auto it = thin.face_size.find(mesh.face_tags[b]);
        if (it == thin.face_size.end()) continue;
        const Eigen::Vector3d p0 = mesh.points.row(mesh.boundary_faces(b, 0)), p1 = mesh.points.row(mesh.boundary_faces(b, 1)),
                              p2 = mesh.points.row(mesh.boundary_faces(b, 2));
        const double area = 0.5 * (p1 - p0).cross(p2 - p0).norm(), s = it->second;
        tets += area * kBandEdges * s / (kMeanTetVolumePerH3 * s * s * s);
    }
    return tets;
}

}  // namespace framefix
