#include "framefix/pipeline/thin_blocks.h"

#include <algorithm>
#include <cmath>

#include "framefix/corrections/boundary_distance.h"
#include "framefix/mesh/keys.h"
#include "framefix/mesh/size_model.h"
#include "framefix/streamlines/point_grid.h"

namespace framefix {
namespace {

constexpr double kEdgesAcross = 3;     // a thin block gets this many tet edges across
constexpr double kMinSizeH = 1.0 / 3;  // and no edge shorter than h / 3: at most 27 x the tets there
constexpr double kEndSkipH = 1.5;      // arc length from a boundary end where the curve enters the surface
constexpr double kOnBoundaryH = 0.5;   // closer than this the curve or sheet lies on the surface
const double kParallelCos = std::cos(30.0 * M_PI / 180);  // sheet and wall normals this close: a cushion

// Arc length of each polyline point from the curve's start.
std::vector<double> arc_lengths(const Points& p) {
    std::vector<double> s(size_t(p.rows()), 0.0);
    for (Eigen::Index i = 1; i < p.rows(); ++i) s[size_t(i)] = s[size_t(i - 1)] + (p.row(i) - p.row(i - 1)).norm();
    return s;
}

Eigen::Vector3d triangle_normal(const Points& P, int a, int b, int c) {
    return (P.row(b) - P.row(a)).cross(P.row(c) - P.row(a)).transpose();
}

class FaceSizer {
public:
    FaceSizer(const TetMesh& mesh, double h, const std::function<bool(const Eigen::Vector3d&)>& counts)
        : mesh_(mesh), boundary_(mesh), h_(h), counts_(counts) {}

    // A thin place at p, 0.5 h to 3 h from the wall. With a normal (a sheet's), only when the
    // nearest wall triangle is parallel to it, and only that triangle's face; else every face near.
    void add(const Eigen::Vector3d& p, const Eigen::Vector3d* normal = nullptr) {
        if (counts_ && !counts_(p)) return;
        auto near = boundary_.near(p, kResolvedThicknessH * h_);
        if (near.empty()) return;
        const auto nearest = *std::min_element(near.begin(), near.end(), [](const auto& a, const auto& b) { return a.second < b.second; });
        if (nearest.second < kOnBoundaryH * h_) return;
        if (normal) {
            const Eigen::Vector3d wall = triangle_normal(mesh_.points, mesh_.boundary_faces(nearest.first, 0),
                                                         mesh_.boundary_faces(nearest.first, 1), mesh_.boundary_faces(nearest.first, 2));
            if (std::abs(wall.normalized().dot(normal->normalized())) < kParallelCos) return;
            near = {nearest};
        }
        for (const auto& [tri, d] : near) {
            const double size = std::max(d / kEdgesAcross, kMinSizeH * h_);
            auto [it, fresh] = out.face_size.emplace(mesh_.face_tags[tri], size);
            if (!fresh) it->second = std::min(it->second, size);
        }
        out.places += 1;
        out.thinnest = out.thinnest > 0 ? std::min(out.thinnest, nearest.second) : nearest.second;
    }

    ThinFaces out;

private:
    const TetMesh& mesh_;
    const BoundaryDistance boundary_;
    double h_;
    const std::function<bool(const Eigen::Vector3d&)>& counts_;
};

}  // namespace

ThinFaces thin_block_faces(const TetMesh& mesh, const SingularityGraph& graph, const SheetSoup& sheets, double h,
                           const std::function<bool(const Eigen::Vector3d&)>& counts) {
    if (mesh.boundary_faces.rows() == 0 || h <= 0) return {};
    FaceSizer maker(mesh, h, counts);
    for (const SingularCurve& c : graph.curves) {
        const std::vector<double> s = arc_lengths(c.points);
        const double length = s.empty() ? 0.0 : s.back();
        auto boundary_end = [&](int k) { return !c.closed && c.ends[k] >= 0 && graph.nodes[size_t(c.ends[k])].boundary; };
        for (Eigen::Index i = 0; i < c.points.rows(); ++i)
            if (!(boundary_end(0) && s[size_t(i)] < kEndSkipH * h) && !(boundary_end(1) && length - s[size_t(i)] < kEndSkipH * h))
                maker.add(c.points.row(i).transpose());
    }
    for (Eigen::Index t = 0; t < sheets.triangles.rows(); ++t) {
        const int a = sheets.triangles(t, 0), b = sheets.triangles(t, 1), c = sheets.triangles(t, 2);
        const Eigen::Vector3d normal = triangle_normal(sheets.points, a, b, c);
        if (!(normal.norm() > 0)) continue;
        const Eigen::Vector3d centroid = (sheets.points.row(a) + sheets.points.row(b) + sheets.points.row(c)).transpose() / 3;
        maker.add(centroid, &normal);
    }
    return maker.out;
}

namespace {

// Twice the largest distance from a tet centroid of the block to its boundary's nearest vertex,
// model units; 0 when some tet lies deeper than kResolvedThicknessH / 2 h (the block is resolved).
double block_thickness(const TetMesh& mesh, const BlockInfo& info, const std::vector<BoundaryTriangle>& boundary, double h) {
    std::vector<int> verts;
    for (const BoundaryTriangle& t : boundary) verts.insert(verts.end(), t.verts.data(), t.verts.data() + 3);
    std::sort(verts.begin(), verts.end());
    verts.erase(std::unique(verts.begin(), verts.end()), verts.end());
    Points P(verts.size(), 3);
    for (size_t i = 0; i < verts.size(); ++i) P.row(Eigen::Index(i)) = mesh.points.row(verts[i]);
    const double reach = 0.5 * kResolvedThicknessH * h;
    const PointGrid grid(P, reach);
    double deepest = 0;
    for (int t : info.tets) {
        Eigen::Vector3d c = Eigen::Vector3d::Zero();
        for (int k = 0; k < 4; ++k) c += mesh.points.row(mesh.tets(t, k)).transpose() / 4;
        const int near = grid.nearest(c, reach);
        if (near < 0) return 0;
        deepest = std::max(deepest, (P.row(near).transpose() - c).norm());
    }
    return 2 * deepest;
}

}  // namespace

void add_thin_blocks(const TetMesh& mesh, const TetTopology& topo, const BlockDecomposition& blocks, double h,
                     ThinFaces& thin) {
    std::map<TriangleKey, int> tag;  // boundary triangle -> B-rep face
    for (Eigen::Index b = 0; b < mesh.boundary_faces.rows(); ++b)
        tag[triangle_key(mesh.boundary_faces(b, 0), mesh.boundary_faces(b, 1), mesh.boundary_faces(b, 2))] = mesh.face_tags[b];
    for (int k = 0; k < blocks.count; ++k) {
        const BlockInfo& info = blocks.blocks[size_t(k)];
        if (info.valid || info.faces >= 6 || size_t(k) >= blocks.boundary.size()) continue;
        const double t = block_thickness(mesh, info, blocks.boundary[size_t(k)], h);
        if (!(t > 0)) continue;
        const double size = std::max(t / kEdgesAcross, kMinSizeH * h);
        for (int tet : info.tets)
            for (int f = 0; f < 4; ++f) {
                const int face = topo.tet_faces(tet, f);
                if (topo.face_tets(face, 0) >= 0 && topo.face_tets(face, 1) >= 0) continue;
                const auto it = tag.find(triangle_key(topo.faces(face, 0), topo.faces(face, 1), topo.faces(face, 2)));
                if (it == tag.end()) continue;
                auto [at, fresh] = thin.face_size.emplace(it->second, size);
                if (!fresh) at->second = std::min(at->second, size);
            }
        thin.places += 1;
        thin.thinnest = thin.thinnest > 0 ? std::min(thin.thinnest, 0.5 * t) : 0.5 * t;
    }
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
        const double s = it->second;
        tets += 0.5 * (p1 - p0).cross(p2 - p0).norm() * kBandEdges / (kMeanTetVolumePerH3 * s * s);
    }
    return tets;
}

}  // namespace framefix
