#include "framefix/blocks/curtain_corners.h"

#include <algorithm>
#include <string>
#include <unordered_map>

namespace framefix {

namespace {

// The path must run into the curtain: its end tangent within about 60 degrees of the curtain
// direction (the groove's and the dome's paths arrive along it, cos ~ 1).
constexpr double kIntoCurtainCos = 0.5;
// Tangent change over 2 kBendReach seeds below this: the curve is straight there, the curtain
// is flat and has no corner (the path's own sheets, if any, cut the solid).
constexpr double kMinBend = 0.05;
constexpr int kBendReach = 2;
// The first seed sits this far down the line, in h: a seed on the curve lies on the boundary,
// where its streamlines and the cross extension above them would start outside.
constexpr double kFirstSeedDepth = 0.3;

struct Corner {
    Eigen::Vector3d point, along, dir1, dir2;  // path end, curtain direction, the two sheet directions
};

// The corner at a path end: the path's last vertex is `curve`'s seed c, `prev` the vertex before it.
bool corner_at(const TetMesh& mesh, const FeatureSeeds& curve, int c, int prev, Corner& out) {
    const std::vector<FeatureSeed>& S = curve.seeds;
    const int n = int(S.size());
    if (S[c].directions.size() < 2) return false;
    const Eigen::Vector3d u = (S[c].point - mesh.points.row(prev).transpose()).normalized();
    const Eigen::Vector3d& d = S[c].directions[0].dot(u) >= S[c].directions[1].dot(u) ? S[c].directions[0] : S[c].directions[1];
    if (!u.allFinite() || d.dot(u) < kIntoCurtainCos) return false;
    const bool closed = closed_chain(S);
    auto tangent = [&](int i) { return closed ? S[(i + n) % n].tangent : S[std::clamp(i, 0, n - 1)].tangent; };
    Eigen::Vector3d bend = tangent(c + kBendReach) - tangent(c - kBendReach);  // towards the centre of curvature
    bend -= bend.dot(d) * d;
    if (bend.norm() < kMinBend) return false;
    const Eigen::Vector3d away = -bend.normalized(), side = d.cross(away);
    out.point = S[c].point, out.along = d;
    out.dir1 = (away + side).normalized(), out.dir2 = (away - side).normalized();
    return true;
}

// Seeds every h along the corner line (the streamline along the curtain from the path's end).
SheetSource line_source(const Streamline& line, const Corner& k, double h, const std::string& name) {
    SheetSource src;
    src.kind = SheetSource::Concave;
    src.name = name;
    src.boundary_end[0] = src.boundary_end[1] = true;
    const Points& P = line.points;
    double since = h, depth = 0;
    for (int i = 1; i < int(P.rows()); ++i) {
        const double step = (P.row(i) - P.row(i - 1)).norm();
        since += step, depth += step;
        if (depth < kFirstSeedDepth * h || (since < h && i + 1 < int(P.rows()))) continue;
        since = 0;
        SheetSeed seed;
        seed.point = P.row(i).transpose();
        seed.tangent = k.along;
        seed.directions = {k.dir1, k.dir2};
        src.seeds.push_back(std::move(seed));
    }
    return src;
}

}  // namespace

std::vector<SheetSource> curtain_corner_sources(const TetMesh& mesh, const FrameField& field, const TetLocator& locator,
                                                const std::vector<FeatureSeeds>& concave,
                                                const std::vector<SnappedPath>& paths,
                                                const std::vector<char>& convex, double h,
                                                const TraceOptions& trace) {
    std::unordered_map<int, std::pair<int, int>> seed_of;  // mesh vertex -> (curve, seed)
    for (int ci = 0; ci < int(concave.size()); ++ci)
        if (concave[ci].valence == 3)
            for (int k = 0; k < int(concave[ci].seeds.size()); ++k) seed_of[concave[ci].seeds[k].vertex] = {ci, k};
    std::vector<SheetSource> out;
    for (size_t pi = 0; pi < paths.size(); ++pi) {
        const std::vector<int>& V = paths[pi].vertices;
        if (V.size() < 2 || !convex[pi]) continue;
        for (int e = 0; e < 2; ++e) {
            const int end = e == 0 ? V.front() : V.back(), prev = e == 0 ? V[1] : V[V.size() - 2];
            const auto it = seed_of.find(end);
            Corner k;
            if (it == seed_of.end() || !corner_at(mesh, concave[it->second.first], it->second.second, prev, k)) continue;
            const Streamline line = trace_streamline(mesh, field, locator, k.point + 0.02 * h * k.along, k.along, trace);
            if (line.reason == StopReason::StartOutside || line.points.rows() < 2) continue;
            SheetSource src = line_source(line, k, h, "curtain:" + std::to_string(pi) + ":" + std::to_string(e));
            if (src.seeds.size() >= 2) out.push_back(std::move(src));
        }
    }
    return out;
}

void mute_jumps_near_corners(std::vector<SheetSource>& sources, const std::vector<SheetSource>& corners, double reach) {
    for (SheetSource& src : sources) {
        if (src.kind != SheetSource::Concave) continue;
        for (SheetSeed& seed : src.seeds)
            for (const SheetSource& c : corners)
                if ((seed.point - c.seeds.front().point).norm() <= reach) seed.continue_jumps = false;
    }
}

}  // namespace framefix
